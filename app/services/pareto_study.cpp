#include "services/pareto_study.h"

#include <cmath>
#include <limits>

#include "pareto/pareto_front.h"
#include "services/json_output.h"
#include "services/service_errors.h"
#include "simulation/smith_tlusty.h"

namespace mx::app {

ParetoStudy::ParetoStudy(Project project, std::optional<DynamicsSource> dynamics)
    : project_(std::move(project)),
      expert_(expertRequestFromProject(project_)),
      request_(paretoRequestFromProject(project_)),
      dynamics_(
          chooseDynamics(tool(), dynamics, expert_.settings.stability.delta_per_s, expert_.settings.stability.method)),
      setup_(dynamicsSetupFor(project_, request_.tool, dynamics_.used)) {
  expert_.settings.stability.dynamics = dynamics_.used;
  if (!request_.operator_rules.isEmpty()) rules_ = evaluateParetoRules(request_.operator_rules, project_, tool());
  grid_ = std::make_unique<AdmissibleGrid>(setup_, expert_.settings);
  if (grid_->empty())
    throw ComputationError(QString("the admissible space of tool '%1' is empty: %2")
                               .arg(request_.tool, QString::fromStdString(describeConstraint(
                                                       grid_->funnel().emptiedBy(), expert_.settings))));
  table_ = std::make_unique<ObjectiveTable>(*grid_, request_.models);
  front_ = nonDominated(table_->scores());
}

ParetoChoice ParetoStudy::choose(const ParetoChoiceOptions& options) const {
  ParetoChoice out;
  ParetoWeights w = options.weights.value_or(request_.weights);
  if (rules_) w = applyWeightRules(rules_->outcome, w);
  const ParetoSelector sel(*table_);
  const std::optional<ObjectiveRequirement>& requirement = options.requirement;
  if (requirement) {
    const RequirementResult r = applyRequirement(sel, w, *requirement);
    w = r.weights;
    out.requirement_changed = r.changed;
  }
  if (options.auto_weights) {
    out.ascent = ascendWeights(sel, w, request_.ascent, requirement);
    w = out.ascent->weights;
  }
  if (rules_) w = applyWeightRules(rules_->outcome, w);
  out.weights = w;

  auto admits = [&](const ParetoPoint& p) { return ruleAdmits(p); };
  if (!rules_ || !rules_->restrictsPoint()) {
    out.selection = sel.coarse(w, requirement);
  } else {
    std::optional<ParetoSelection> s = selectWhere(
        *table_, w, [&](const ParetoPoint& p) { return admits(p) && (!requirement || requirement->satisfiedBy(p)); });
    if (!s && requirement) {
      s = selectWhere(*table_, w, admits);
      if (s) s->filtered = false;
    }
    if (!s)
      throw ComputationError(
          QString("the operator rules exclude every point of the admissible space of tool '%1' (%2 points)")
              .arg(request_.tool)
              .arg(table_->size()));
    out.selection = *s;
  }
  out.coarse_j = out.selection.j;
  if (options.fine) {
    const ParetoSelection f = sel.fine(out.selection, w, request_.fine, requirement);
    if (admits(f.point))
      out.selection = f;
    else
      out.fine_rejected_by_rules = true;
  }
  out.requirement_satisfied = requirement && requirement->satisfiedBy(out.selection.point);
  return out;
}

std::vector<std::optional<ParetoWeights>> ParetoStudy::supportingWeights(int divisions) const {
  const std::size_t m = front_.size();
  std::vector<ParetoWeights> sums(m, ParetoWeights{});
  std::vector<int> counts(m, 0);
  const double step = 1.0 / divisions;
  for (int a = 0; a <= divisions; ++a)
    for (int b = 0; a + b <= divisions; ++b)
      for (int c = 0; a + b + c <= divisions; ++c) {
        const ParetoWeights w{a * step, b * step, c * step, (divisions - a - b - c) * step};
        double best = -std::numeric_limits<double>::infinity();
        std::size_t arg = 0;
        for (std::size_t k = 0; k < m; ++k) {
          const double j = objectiveJ(w, table_->scores()[front_[k]]);
          if (j > best) {
            best = j;
            arg = k;
          }
        }
        for (std::size_t i = 0; i < kObjectiveCount; ++i) sums[arg][i] += w[i];
        ++counts[arg];
      }
  std::vector<std::optional<ParetoWeights>> out(m);
  for (std::size_t k = 0; k < m; ++k)
    if (counts[k] > 0) {
      ParetoWeights w{};
      for (std::size_t i = 0; i < kObjectiveCount; ++i) w[i] = sums[k][i] / counts[k];
      out[k] = renormaliseBySum(w);
    }
  return out;
}

std::optional<ChatterReselection> ParetoStudy::reselectAfterChatter(
    const ParetoWeights& w, const std::optional<ObjectiveRequirement>& requirement, double chatter_hz,
    const ParetoPoint& q) const {
  const std::vector<double>& speeds = grid_->speeds();
  const auto st = smithTlustyChoice(chatter_hz, setup_.teeth, q.speed_rev_per_s, speeds.front(), speeds.back());
  if (!st) return std::nullopt;
  ChatterReselection out;
  const double ns = out.suggested_rev_per_s = st->rev_per_s;
  out.k = st->k;
  auto near = [&](const ParetoPoint& p) { return std::abs(p.speed_rev_per_s - ns) <= 0.02 * ns; };
  double nearest = table_->points().front().speed_rev_per_s;
  for (const ParetoPoint& p : table_->points()) {
    out.within_window = out.within_window || near(p);
    if (std::abs(p.speed_rev_per_s - ns) < std::abs(nearest - ns)) nearest = p.speed_rev_per_s;
  }
  auto speedOk = [&](const ParetoPoint& p) {
    return out.within_window ? near(p) : std::abs(p.speed_rev_per_s - nearest) <= 1e-9 * nearest;
  };
  out.selection = selectWhere(*table_, w, [&](const ParetoPoint& p) {
    return speedOk(p) && ruleAdmits(p) && (!requirement || requirement->satisfiedBy(p));
  });
  if (!out.selection && requirement)
    out.selection = selectWhere(*table_, w, [&](const ParetoPoint& p) { return speedOk(p) && ruleAdmits(p); });
  return out;
}

LearningRecord ParetoStudy::learningRecord(const ParetoWeights& w, const ParetoPoint& p, double eta,
                                           LearningSource source) const {
  const ToolSpec& t = tool();
  LearningRecord r;
  r.weights.assign(w.begin(), w.end());
  r.tool = {t.id, t.diameter_mm, t.teeth};
  r.material = project_.material ? project_.material->name : QString("unknown");
  const MachineSpec& machine = project_.requireMachine();
  r.machine = {machine.spindle_power_W, machine.max_spindle_rpm};
  r.q = {revPerSToRpm(p.speed_rev_per_s), p.depth_m * 1e3, p.feed_per_tooth_m * 1e3};
  r.objectives = QJsonObject{{"tol", p.tol()},
                             {"mrr_cm3_s", p.mrr() * 1e6},
                             {"surf", p.surf()},
                             {"ros", jsonNumberOrNull(p.ros())},
                             {"eta", eta},
                             {"power_W", p.power_w},
                             {"feed_velocity_mm_s", p.feed_per_tooth_m * setup_.teeth * p.speed_rev_per_s * 1e3}};
  r.source = source;
  return r;
}

}  // namespace mx::app
