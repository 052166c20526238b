#pragma once
// The Pareto expert system (Pareto paper, module V with the operator rules of module VII) for one
// project, shared by `millexpert-cli pareto` and the GUI's Pareto docks. Construction does the work
// that does not depend on the weights (the admissible grid of the project's pareto.tool, the
// objective table, the non-dominated set and the operator rules); choose() then runs the weight
// pipeline and the selection in milliseconds:
//   weights (given or pareto.weights) -> weight.* rules (projection onto the simplex within the
//   bounds) -> Rule 11 (requirement) -> Rule 12 (auto weights) -> weight.* rules again -> Rule 10.1
//   coarse selection among the points obeying the point rules (and the requirement, unless no point
//   meets it) -> Rule 10.2 fine search, kept only when it obeys the point rules.
// Errors: ProjectError or InputError (2: bad project, pareto section or operator rules); ComputationError
// (1: empty admissible space).
// The study owns copies of its inputs: build it on any thread, then use it read-only from any thread.
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "document/project.h"
#include "expert/admissible_grid.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_selector.h"
#include "pareto/weight_modulation.h"
#include "services/expert_request.h"
#include "services/learning_record.h"
#include "services/measured_dynamics.h"
#include "services/pareto_request.h"
#include "services/pareto_rules.h"

namespace mx::app {

struct ParetoChoiceOptions {
  std::optional<ParetoWeights> weights;             // default: pareto.weights of the project
  std::optional<ObjectiveRequirement> requirement;  // Rule 11; default: the project's minimum MRR
  bool fine = false;                                // Rule 10.2
  bool auto_weights = false;                        // Rule 12
  bool project_requirement = true;                  // without `requirement`, apply the project's minimum MRR
  std::optional<ParetoObjectiveKind> objective;     // default: pareto.objective
};

// Why the selected point is where it is: the Rule 11 requirement when it moved the selection, the
// operator rules that fired, and the limits of Q that one more step of depth or feed would violate.
struct BindingLimit {
  QString key;        // "requirement", "stability", "spindle_power", "feed_drive", "feed_per_tooth", ...
  QString direction;  // "depth", "feed" or "" (the requirement)
  QString text;       // for the operator, with the limit's value and unit
};

struct ParetoChoice {
  ParetoObjectiveKind objective = ParetoObjectiveKind::Weighted;
  ParetoWeights weights{};  // final weights (after rules, Rule 11 and Rule 12)
  ParetoSelection selection;
  double coarse_j = 0.0;
  std::optional<ObjectiveRequirement> requirement;  // the one applied
  QString requirement_source;                       // "--require" or the project field
  QString requirement_text;
  bool requirement_changed = false;    // Rule 11 moved the weights
  bool requirement_satisfied = false;  // the chosen point meets the requirement
  bool requirement_binding = false;    // without it another point would have been selected
  std::vector<BindingLimit> binding;
  std::optional<PartEconomics> economics;  // when the project has pareto.economics
  std::optional<GradientAscentResult> ascent;
  bool fine_rejected_by_rules = false;
  const ParetoPoint& point() const { return selection.point; }
};

// Module VI (Rules 15-16): after chatter at `chatter_hz` at q, the Smith-Tlusty speed N_s nearest q's
// inside the grid's speed range, then a Rule 10.1 re-selection restricted to the points of Q within
// +-2 % of N_s (the grid speed nearest N_s when none is), the operator rules and the requirement
// (dropped when no such point meets it).
struct ChatterReselection {
  double suggested_rev_per_s = 0.0;
  int k = 0;                                 // lobe number of N_s = f_c / (n_t k)
  bool within_window = false;                // false: the nearest grid speed was used
  std::optional<ParetoSelection> selection;  // nullopt when no admissible point is left
};

class ParetoStudy {
 public:
  // `dynamics`: the tool's lobes on its modes or its tap-test FRF (services/measured_dynamics.h);
  // empty: the tool's default.
  explicit ParetoStudy(Project project, std::optional<DynamicsSource> dynamics = std::nullopt);
  ParetoStudy(const ParetoStudy&) = delete;
  ParetoStudy& operator=(const ParetoStudy&) = delete;

  const Project& project() const { return project_; }
  const ExpertRequest& expert() const { return expert_; }
  const ParetoRequest& request() const { return request_; }
  const ToolSpec& tool() const { return *project_.findTool(request_.tool); }
  const MillingSetup& setup() const { return setup_; }
  const DynamicsChoice& dynamics() const { return dynamics_; }
  const std::optional<ParetoRules>& rules() const { return rules_; }
  const AdmissibleGrid& grid() const { return *grid_; }
  const ObjectiveTable& table() const { return *table_; }
  ParetoSelector selector() const { return ParetoSelector(*table_); }
  const std::vector<std::size_t>& front() const { return front_; }  // indices into table().points()

  bool ruleAdmits(const ParetoPoint& p) const { return !rules_ || rules_->admits(p, setup_.teeth); }
  ParetoChoice choose(const ParetoChoiceOptions& options) const;
  // The Rule 11 requirement MRR >= the project's minimum (MinimumMrr resolved on Q's largest MRR).
  ObjectiveRequirement projectRequirement() const;

  // For each front point (aligned with front()), weights that select it by Rule 10.1 among the front,
  // found on the simplex lattice with `divisions` steps per unit: the mean of the lattice weights
  // whose optimum it is (the set of such weights is convex, so the mean selects it too); nullopt for
  // points no lattice weight selects (unsupported points in a non-convex part of the front).
  std::vector<std::optional<ParetoWeights>> supportingWeights(int divisions = 20) const;

  // nullopt when no Smith-Tlusty speed lies in the grid's speed range.
  std::optional<ChatterReselection> reselectAfterChatter(const ParetoWeights& w,
                                                         const std::optional<ObjectiveRequirement>& requirement,
                                                         double chatter_hz, const ParetoPoint& q) const;

  // The Rule 14 record of a programmed point of this study's tool (objectives, eta, power, feed
  // velocity), time left invalid (the database stamps it).
  LearningRecord learningRecord(const ParetoWeights& w, const ParetoPoint& p, double eta, LearningSource source) const;

 private:
  Project project_;
  ExpertRequest expert_;
  ParetoRequest request_;
  DynamicsChoice dynamics_;
  MillingSetup setup_;
  std::optional<ParetoRules> rules_;
  std::unique_ptr<AdmissibleGrid> grid_;
  std::unique_ptr<ObjectiveTable> table_;
  std::vector<std::size_t> front_;

  ParetoSelection selectWeighted(const ParetoWeights& w, const std::optional<ObjectiveRequirement>& requirement) const;
  ParetoSelection selectEconomic(EconomicObjective objective,
                                 const std::optional<ObjectiveRequirement>& requirement) const;
  std::vector<BindingLimit> bindingLimits(const ParetoChoice& choice) const;
};

}  // namespace mx::app
