#include "expert/expert_session.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>

#include "core/invalid_input.h"
#include "core/parallel_for.h"
#include "model/vector_state.h"

namespace mx {

namespace {

RankKey keyOf(const ToolChoice& t, double cost) {
  return {cost, t.q.mrr_m3_per_s, t.q.power_w, t.q.speed_rev_per_s, t.q.depth_m};
}

using Admit = std::function<bool(const ExpertPoint&)>;

// Visits every admissible point of a grid (passing `admit`, when given) with its cost;
// visit(cell, feed_index, cost) returns nothing.
template <class Visit>
void forEachPoint(const AdmissibleGrid& grid, const std::array<double, 3>& c, const CostNormalisation& nf,
                  const Admit& admit, const Visit& visit) {
  const double fs = grid.feedStep();
  const double mrr_weight = c[1] * nf.max_mrr_m3_per_s;
  const double dns_weight = c[2] * nf.max_speed_security;
  const std::vector<GridCell>& cells = grid.cells();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const GridCell& cell = cells[i];
    const double a = powerCostTerm(c[0], cell.power_per_feed, cell.available_power_w);  // cost per unit feed
    const double a0 = powerCostTerm(c[0], cell.power_at_zero_feed_w, cell.available_power_w);
    const double b = mrr_weight / cell.mrr_per_feed;  // cost times feed
    const double k = dns_weight / cell.speed_security;
    for (int f = 1; f <= cell.feed_count; ++f) {
      const double s = fs * f;
      if (admit && !admit(grid.point(i, f))) continue;
      visit(i, f, a * s + a0 + b / s + k);
    }
  }
}

ToolChoice makeChoice(const AdmissibleGrid& grid, std::size_t tool, std::size_t cell, int feed, double cost,
                      const std::array<double, 3>& c, const CostNormalisation& nf) {
  ToolChoice t;
  t.tool = tool;
  t.cell = cell;
  t.feed_index = feed;
  t.q = grid.point(cell, feed);
  t.terms = toolCostTerms(c, nf, t.q.speed_rev_per_s, t.q.power_w, t.q.mrr_m3_per_s, t.q.speed_security);
  t.min_cost = cost;
  return t;
}

// The minimum-cost point of one grid (ties by rankBefore). nullopt for an empty grid.
std::optional<ToolChoice> bestOfGrid(const AdmissibleGrid& grid, std::size_t tool, const std::array<double, 3>& c,
                                     const CostNormalisation& nf, const Admit& admit) {
  bool have = false;
  double best_cost = 0.0;
  std::size_t best_cell = 0;
  int best_feed = 0;
  forEachPoint(grid, c, nf, admit, [&](std::size_t cell, int feed, double cost) {
    if (!have) {
      have = true;
    } else {
      const double tol = kCostTieTolerance * std::max(std::abs(cost), std::abs(best_cost));
      if (cost > best_cost + tol) return;
      if (cost >= best_cost - tol) {  // a tie in cost: the full rule decides
        const ExpertPoint p = grid.point(cell, feed), q = grid.point(best_cell, best_feed);
        if (!rankBefore({cost, p.mrr_m3_per_s, p.power_w, p.speed_rev_per_s, p.depth_m},
                        {best_cost, q.mrr_m3_per_s, q.power_w, q.speed_rev_per_s, q.depth_m}))
          return;
      }
    }
    best_cost = cost;
    best_cell = cell;
    best_feed = feed;
  });
  if (!have) return std::nullopt;
  return makeChoice(grid, tool, best_cell, best_feed, best_cost, c, nf);
}

}  // namespace

ExpertSession::ExpertSession(std::vector<MillingSetup> tools, const ExpertSettings& settings,
                             const std::vector<double>& tool_force_limits_n, const JobControl& job)
    : settings_(settings), tools_(std::move(tools)), cache_(settings.refinement) {
  clearUpperVectorState();
  if (tools_.empty()) throw InvalidInput("the expert system needs at least one candidate tool");
  if (!tool_force_limits_n.empty() && tool_force_limits_n.size() != tools_.size())
    throw InvalidInput("the expert system needs one tool force limit per tool (" + std::to_string(tools_.size()) +
                       "), got " + std::to_string(tool_force_limits_n.size()));
  std::vector<std::optional<AdmissibleGrid>> built(tools_.size());
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;  // progress callbacks one at a time, in order
  parallelFor(tools_.size(), settings_.refinement.threads, [&](std::size_t i) {
    ExpertSettings own = settings_;
    if (!tool_force_limits_n.empty()) own.limits.max_tool_force_n = tool_force_limits_n[i];
    built[i].emplace(tools_[i], own, JobControl{job.cancel, {}});
    const std::lock_guard<std::mutex> lock(progress_mutex);
    job.report(static_cast<double>(++done) / static_cast<double>(tools_.size()));
  });
  grids_.reserve(built.size());
  for (auto& g : built) grids_.push_back(std::move(*g));
  nf_.available_power = settings_.limits.spindlePower();
  for (const AdmissibleGrid& g : grids_) {
    nf_.max_mrr_m3_per_s = std::max(nf_.max_mrr_m3_per_s, g.maxMrr());
    nf_.max_speed_security = std::max(nf_.max_speed_security, g.maxSpeedSecurity());
  }
}

std::function<bool(const ExpertPoint&)> ExpertSession::admitFor(std::size_t tool) const {
  if (!filter_) return {};
  return [this, tool](const ExpertPoint& p) { return filter_(tool, p); };
}

bool ExpertSession::filteredOut(std::size_t tool) const {
  const AdmissibleGrid& grid = grids_.at(tool);
  if (grid.empty() || !filter_) return false;
  bool any = false;
  forEachPoint(grid, {1.0, 0.0, 0.0}, nf_, admitFor(tool), [&](std::size_t, int, double) { any = true; });
  return !any;
}

bool ExpertSession::empty() const {
  return std::all_of(grids_.begin(), grids_.end(), [](const AdmissibleGrid& g) { return g.empty(); });
}

std::string ExpertSession::emptyReason() const {
  if (!empty()) return {};
  // The constraint that removed the last point of the longest-lived tool, with that tool's limits.
  const AdmissibleGrid* latest = &grids_.front();
  for (const AdmissibleGrid& g : grids_)
    if (g.funnel().emptiedBy() > latest->funnel().emptiedBy()) latest = &g;
  std::ostringstream out;
  out << "the admissible cutting-parameter space is empty for every tool: "
      << describeConstraint(latest->funnel().emptiedBy(), latest->settings()) << " leaves no grid point";
  return out.str();
}

Ranking ExpertSession::rank(const std::array<double, 3>& c) const {
  validateSimplexWeights("c", {c.begin(), c.end()}, 3);
  Ranking r;
  r.c = c;
  for (std::size_t t = 0; t < grids_.size(); ++t) {
    if (auto best = bestOfGrid(grids_[t], t, c, nf_, admitFor(t)))
      r.tools.push_back(*best);
    else
      r.excluded.push_back(t);
  }
  std::stable_sort(r.tools.begin(), r.tools.end(), [](const ToolChoice& a, const ToolChoice& b) {
    return rankBefore(keyOf(a, a.min_cost), keyOf(b, b.min_cost));
  });
  return r;
}

std::vector<double> ExpertSession::minimumCosts(const std::array<double, 3>& c) const {
  validateSimplexWeights("c", {c.begin(), c.end()}, 3);
  std::vector<double> out;
  for (std::size_t t = 0; t < grids_.size(); ++t) {
    const auto best = bestOfGrid(grids_[t], t, c, nf_, admitFor(t));
    out.push_back(best ? best->min_cost : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

std::vector<ToolChoice> ExpertSession::bestPoints(std::size_t tool, const std::array<double, 3>& c,
                                                  std::size_t count) const {
  const AdmissibleGrid& grid = grids_.at(tool);
  std::vector<ToolChoice> best;
  if (count == 0) return best;
  forEachPoint(grid, c, nf_, admitFor(tool), [&](std::size_t cell, int feed, double cost) {
    if (best.size() == count) {
      const ExpertPoint p = grid.point(cell, feed);
      if (!rankBefore({cost, p.mrr_m3_per_s, p.power_w, p.speed_rev_per_s, p.depth_m},
                      keyOf(best.back(), best.back().min_cost)))
        return;
      best.pop_back();
    }
    ToolChoice choice = makeChoice(grid, tool, cell, feed, cost, c, nf_);
    auto at = std::find_if(best.begin(), best.end(),
                           [&](const ToolChoice& b) { return rankBefore(keyOf(choice, cost), keyOf(b, b.min_cost)); });
    best.insert(at, choice);
  });
  return best;
}

Refinement ExpertSession::refine(std::size_t tool, const CostWeights& weights) {
  weights.validate();
  const int k = std::max(1, settings_.refinement.simulated_points);
  const std::vector<ToolChoice> best_by_cost = bestPoints(tool, weights.c, static_cast<std::size_t>(k));
  if (best_by_cost.empty()) throw InvalidInput("Rule 5: the tool has no admissible point");
  std::vector<ExpertPoint> seeds;
  seeds.reserve(best_by_cost.size());
  for (const ToolChoice& p : best_by_cost) seeds.push_back(p.q);
  const AdmissibleGrid& grid = grids_.at(tool);
  Rule5Problem problem;
  problem.grid = &grid;
  problem.speed_from_rev_per_s = settings_.grid.speed_from_rev_per_s;
  problem.speed_to_rev_per_s = settings_.grid.speed_to_rev_per_s;
  problem.nf = nf_;
  problem.weights = weights;
  problem.admit = admitFor(tool);
  problem.simulate = [&](const std::vector<ExpertPoint>& points) {
    std::vector<SimulationCache::Request> requests;
    requests.reserve(points.size());
    for (const ExpertPoint& q : points)
      requests.push_back({tool, &tools_[tool], {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}});
    return cache_.evaluate(requests);
  };
  const Rule5SearchSettings& search = settings_.refinement.search;
  const std::size_t runs_before = cache_.simulationsRun();
  Rule5Result found = searchRule5(problem, seeds.front(), seeds, rule5StartSteps(grid, settings_.grid, search), search);
  Refinement r;
  r.tool = tool;
  r.candidates = std::move(found.candidates);
  r.best = found.best;
  r.seed_count = seeds.size();
  r.search_iterations = found.iterations;
  r.search_converged = found.converged;
  r.simulations_run = cache_.simulationsRun() - runs_before;
  return r;
}

ExpertResult ExpertSession::run(const CostWeights& weights, bool simulate, const std::vector<ChatterReport>& reported) {
  weights.validate();
  for (std::size_t i = 0; i < reported.size(); ++i)
    validateChatterReport(reported[i], toolCount(), "reported chatter #" + std::to_string(i + 1));
  ExpertResult result;
  result.weights = weights;
  for (;;) {
    result.ranking = rank(result.weights.c);
    if (result.ranking.tools.empty()) return result;
    if (simulate) result.refinement = refine(result.ranking.selected().tool, result.weights);
    const std::optional<std::size_t> holding = reportHolding(reported, result.chosenTool(), result.chosenPoint());
    const bool simulated =
        simulate && result.refinement->chosen().metrics.malfunction(settings_.refinement.malfunction_ratio);
    if (!holding && !simulated) break;
    if (result.malfunction_iterations >= settings_.refinement.max_malfunction_iterations) {
      result.malfunction_limit_reached = true;
      result.unresolved_report = holding;
      break;
    }
    result.weights.c = malfunctionStep(result.weights.c);
    ++result.malfunction_iterations;
    if (holding) ++result.reported_chatter_iterations;
  }
  return result;
}

}  // namespace mx
