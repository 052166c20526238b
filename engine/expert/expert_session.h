#pragma once
// The expert system of Rubio, De la Sen & Ibeas (2006), section 3, over a library of candidate tools.
//
// Construction does everything that does not depend on the weights, once: per tool the lobes and the
// admissible grid Q (AdmissibleGrid: power and MRR per unit feed, Delta N_s and feed count of every
// (N, b) cell), and the normalisation factors NF1..NF3 over all tools. Afterwards
//   rank(c)      Rule 4: one pass over the cached cells (no lobes, no simulation),
//   refine(...)  Rule 5: a pattern search around q*, seeded with the best K points by C, simulated
//                through the SimulationCache,
//   run(...)     Rules 4, 5 and 6 (the malfunction loop, on simulated or reported chatter).
// A weight change re-uses every cached grid and simulation. Thread-safety: const members may run
// concurrently; refine/run mutate the simulation cache (internally locked).
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "expert/admissible_grid.h"
#include "expert/cost_weights.h"
#include "expert/expert_settings.h"
#include "expert/reported_chatter.h"
#include "expert/resultant_cost.h"
#include "expert/rule5_search.h"
#include "expert/simulation_cache.h"
#include "expert/tool_cost.h"
#include "model/milling_setup.h"

namespace mx {

struct ToolChoice {
  std::size_t tool = 0;   // index into the session's tools
  double min_cost = 0.0;  // min over Q of C (eq. 13)
  CostTerms terms;        // at q*
  ExpertPoint q;          // q*: the cost-minimising point of this tool
  std::size_t cell = 0;
  int feed_index = 0;
};

struct Ranking {
  std::array<double, 3> c{};
  std::vector<ToolChoice> tools;      // tools with a non-empty Q, best first (rankBefore on min cost)
  std::vector<std::size_t> excluded;  // tools whose Q is empty, by index
  const ToolChoice& selected() const { return tools.front(); }  // Rule 4 (requires !tools.empty())
};

struct Refinement {
  std::size_t tool = 0;
  // Every point simulated for Rule 5: the best K points by C (best first), then the pattern search's
  // points in the order scored (rule5_search.h). C_t and C_f are normalised over all of them.
  std::vector<RefinementCandidate> candidates;
  std::size_t best = 0;        // q** = candidates[best].q
  std::size_t seed_count = 0;  // the leading candidates that are the best K by C
  int search_iterations = 0;
  bool search_converged = false;    // the steps reached the resolutions (not the iteration limit)
  std::size_t simulations_run = 0;  // simulated by this call; the other candidates came from the cache
  const RefinementCandidate& chosen() const { return candidates[best]; }
};

struct ExpertResult {
  CostWeights weights;  // after Rule 6
  Ranking ranking;
  std::optional<Refinement> refinement;  // absent without simulation
  int malfunction_iterations = 0;
  int reported_chatter_iterations = 0;     // the steps a reported chatter region triggered
  bool malfunction_limit_reached = false;  // Rule 6 stopped at the iteration limit
  // At the limit: the report whose region still holds the chosen point (nullopt: the simulated
  // malfunction persists).
  std::optional<std::size_t> unresolved_report;

  // q** with simulation, else q*: the point Rule 6 judges.
  const ExpertPoint& chosenPoint() const { return refinement ? refinement->chosen().q : ranking.selected().q; }
  std::size_t chosenTool() const { return refinement ? refinement->tool : ranking.selected().tool; }
};

class ExpertSession {
 public:
  // Builds every tool's grid (in parallel). `tool_force_limits_n`, when not empty, holds each tool's
  // allowable force F_allow (Rule 3; +inf: none), aligned with `tools`, and replaces
  // settings.limits.max_tool_force_n for that tool. Throws InvalidInput for an empty library, a
  // misaligned limit list or bad settings; Cancelled when job.cancelled() (polled per grid speed),
  // and reports the fraction of tools built.
  ExpertSession(std::vector<MillingSetup> tools, const ExpertSettings& settings,
                const std::vector<double>& tool_force_limits_n = {}, const JobControl& job = {});

  std::size_t toolCount() const { return grids_.size(); }
  const AdmissibleGrid& grid(std::size_t tool) const { return grids_.at(tool); }
  const ExpertSettings& settings() const { return settings_; }
  const CostNormalisation& normalisation() const { return nf_; }

  // True when no tool has an admissible point; emptyReason() then names the constraint (the first one,
  // in the order of ConstraintFunnel, that left no point for any tool).
  bool empty() const;
  std::string emptyReason() const;

  // Module VII (Pareto paper, Rule 18) operator constraints: when set, rank, minimumCosts, bestPoints
  // and refine consider only the points of each tool that pass `filter(tool, point)`; a tool left with
  // no point is excluded from the ranking (filteredOut() tells it apart from an empty Q).
  using PointFilter = std::function<bool(std::size_t tool, const ExpertPoint& point)>;
  void setPointFilter(PointFilter filter) { filter_ = std::move(filter); }
  bool filteredOut(std::size_t tool) const;  // Q non-empty, but no point passes the filter
  // Rule 4. c must lie on the simplex (InvalidInput otherwise).
  Ranking rank(const std::array<double, 3>& c) const;
  // Minimum cost of every tool (NaN for an empty Q), in tool order: the figure 4/5 sweeps.
  std::vector<double> minimumCosts(const std::array<double, 3>& c) const;
  // The best `count` points of one tool by C, best first.
  std::vector<ToolChoice> bestPoints(std::size_t tool, const std::array<double, 3>& c, std::size_t count) const;

  // Rule 5 for one tool: the pattern search around its q* (rule5_search.h), seeded with its best K points
  // by C, every point simulated through the cache; q** minimises C_resultant over all of them.
  Refinement refine(std::size_t tool, const CostWeights& weights);
  // Rules 4-6. Rule 6 steps the weights (malfunctionStep) while the chosen point (q**, or q* without
  // simulation) lies in a reported chatter region of its tool or, with simulation, while its simulated
  // A_chatter exceeds A_toothpass; at most refinement.max_malfunction_iterations steps. Throws
  // InvalidInput for a bad report (validateChatterReport).
  ExpertResult run(const CostWeights& weights, bool simulate, const std::vector<ChatterReport>& reported = {});

  const SimulationCache& simulations() const { return cache_; }

 private:
  std::function<bool(const ExpertPoint&)> admitFor(std::size_t tool) const;

  ExpertSettings settings_;
  std::vector<MillingSetup> tools_;
  std::vector<AdmissibleGrid> grids_;
  CostNormalisation nf_;
  SimulationCache cache_;
  PointFilter filter_;
};

}  // namespace mx
