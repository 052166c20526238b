#include "expert/rule5_search.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/invalid_input.h"
#include "model/cutting_force.h"

namespace mx {

namespace {

constexpr double kSamePointTolerance = 1e-9;  // relative, per coordinate

bool samePoint(const ExpertPoint& a, const ExpertPoint& b) {
  const auto close = [](double x, double y) {
    return std::abs(x - y) <= kSamePointTolerance * std::max(std::abs(x), std::abs(y));
  };
  return close(a.speed_rev_per_s, b.speed_rev_per_s) && close(a.depth_m, b.depth_m) &&
         close(a.feed_per_tooth_m, b.feed_per_tooth_m);
}

bool contains(const std::vector<ExpertPoint>& points, const ExpertPoint& p) {
  return std::any_of(points.begin(), points.end(), [&](const ExpertPoint& q) { return samePoint(p, q); });
}

// The offsets {-1, 0, 1} of a variable that is still varied, {0} of one whose step is below its resolution.
std::vector<int> offsets(double step, double resolution) {
  if (step >= resolution) return {-1, 0, 1};
  return {0};
}

struct Search {
  const Rule5Problem& problem;
  const Rule5SearchSettings& settings;
  Rule5Result result;
  std::vector<ExpertPoint> simulated;  // result.candidates' points

  bool varies(const Rule5Steps& s) const {
    return s.speed_rev_per_s >= settings.speed_resolution_rev_per_s || s.depth_m >= settings.depth_resolution_m ||
           s.feed_per_tooth_m >= settings.feed_resolution_m;
  }

  // The admissible, not yet simulated points of the stencil around `centre`.
  std::vector<ExpertPoint> stencil(const ExpertPoint& centre, const Rule5Steps& s) const {
    std::vector<ExpertPoint> out;
    for (int i : offsets(s.speed_rev_per_s, settings.speed_resolution_rev_per_s))
      for (int j : offsets(s.depth_m, settings.depth_resolution_m))
        for (int k : offsets(s.feed_per_tooth_m, settings.feed_resolution_m)) {
          const ExpertPoint p =
              expertPointAt(*problem.grid, centre.speed_rev_per_s + i * s.speed_rev_per_s,
                            centre.depth_m + j * s.depth_m, centre.feed_per_tooth_m + k * s.feed_per_tooth_m);
          if (!contains(simulated, p) && !contains(out, p) && rule5Admits(problem, p)) out.push_back(p);
        }
    return out;
  }

  void simulate(const std::vector<ExpertPoint>& points) {
    if (points.empty()) return;
    const std::vector<ResponseMetrics> metrics = problem.simulate(points);
    for (std::size_t i = 0; i < points.size(); ++i) {
      RefinementCandidate c;
      c.q = points[i];
      c.cost = toolCostTerms(problem.weights.c, problem.nf, c.q.speed_rev_per_s, c.q.power_w, c.q.mrr_m3_per_s,
                             c.q.speed_security)
                   .total();
      c.metrics = metrics.at(i);
      result.candidates.push_back(c);
      simulated.push_back(c.q);
    }
  }
};

}  // namespace

Rule5Steps rule5StartSteps(const AdmissibleGrid& grid, const ExpertGrid& spacing, const Rule5SearchSettings& s) {
  // Defaults: the first ring reaches a quarter of the way to the neighbouring grid speeds and half way
  // to the neighbouring depths and feeds. The grid has scored the points beyond by C already, and C
  // carries 0.8 of C_resultant (Rule 7), so q** is expected within the grid cell of q*; the speed ring
  // is tighter because C_t and C_f change fastest along the speed (the tooth-passing frequency moves
  // against the modes). Halving from a quarter step reaches any speed of that cell to the resolution:
  // with the 2006 grid (1000 rpm) the steps are 250, 125, 62.5, ... rpm, so 5800 - 120 rpm (the paper's
  // 5680) is within 8 rpm of a reachable speed.
  Rule5Steps steps;
  steps.speed_rev_per_s = s.speed_step_rev_per_s > 0.0 ? s.speed_step_rev_per_s : spacing.speed_step_rev_per_s / 4.0;
  steps.depth_m = s.depth_step_m > 0.0 ? s.depth_step_m : grid.depthStep() / 2.0;
  steps.feed_per_tooth_m = s.feed_step_m > 0.0 ? s.feed_step_m : grid.feedStep() / 2.0;
  return steps;
}

ExpertPoint expertPointAt(const AdmissibleGrid& grid, double n, double b, double s) {
  const MillingSetup& setup = grid.setup();
  ExpertPoint p;
  p.speed_rev_per_s = n;
  p.depth_m = b;
  p.feed_per_tooth_m = s;
  p.power_w = evaluateCut(setup, {n, b, s}).peak_power_w;
  p.mrr_m3_per_s = setup.radial_depth_m * b * setup.teeth * n * s;
  p.speed_security = grid.boundary().covers(n) && b > 0.0 ? grid.boundary().speedSecurity(n, b) : 0.0;
  return p;
}

bool rule5Admits(const Rule5Problem& problem, const ExpertPoint& p) {
  constexpr double kSlack = 1e-9;
  if (p.speed_rev_per_s < problem.speed_from_rev_per_s * (1.0 - kSlack) ||
      p.speed_rev_per_s > problem.speed_to_rev_per_s * (1.0 + kSlack))
    return false;
  if (!problem.grid->isAdmissible(p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m)) return false;
  return !problem.admit || problem.admit(p);
}

Rule5Result searchRule5(const Rule5Problem& problem, const ExpertPoint& q_star, const std::vector<ExpertPoint>& seeds,
                        const Rule5Steps& start, const Rule5SearchSettings& settings) {
  if (!problem.grid || !problem.simulate) throw InvalidInput("Rule 5 search: needs a grid and a simulation");
  Search search{problem, settings, {}, {}};
  std::vector<ExpertPoint> first;
  for (const ExpertPoint& p : seeds)
    if (!contains(first, p)) first.push_back(p);
  Rule5Steps steps = start;
  ExpertPoint centre = q_star;
  Rule5Result& r = search.result;
  while (r.iterations < settings.max_iterations) {
    if (!search.varies(steps)) break;
    std::vector<ExpertPoint> batch = r.iterations == 0 ? first : std::vector<ExpertPoint>{};
    for (const ExpertPoint& p : search.stencil(centre, steps))
      if (!contains(batch, p)) batch.push_back(p);
    search.simulate(batch);
    ++r.iterations;
    if (r.candidates.empty()) break;
    r.best = selectByResultantCost(r.candidates, problem.weights);
    if (samePoint(r.candidates[r.best].q, centre)) {
      steps.speed_rev_per_s /= 2.0;
      steps.depth_m /= 2.0;
      steps.feed_per_tooth_m /= 2.0;
    } else {
      centre = r.candidates[r.best].q;
    }
  }
  if (r.iterations == 0) search.simulate(first);  // no iteration ran: the seeds alone
  if (r.candidates.empty()) throw InvalidInput("Rule 5: the tool has no admissible point to simulate");
  r.best = selectByResultantCost(r.candidates, problem.weights);
  r.converged = !search.varies(steps);
  r.final_steps = steps;
  return r;
}

}  // namespace mx
