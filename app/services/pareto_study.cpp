#include "services/pareto_study.h"

#include <cmath>
#include <limits>

#include "document/shortened_text.h"
#include "expert/limits_at_point.h"
#include "pareto/economic_selection.h"
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
  expert_.settings.limits.max_tool_force_n = project_.toolForceLimitN(tool());  // Module II, Rule 3
  if (!request_.operator_rules.isEmpty()) rules_ = evaluateParetoRules(request_.operator_rules, project_, tool());
  grid_ = std::make_unique<AdmissibleGrid>(setup_, expert_.settings);
  if (grid_->empty())
    throw ComputationError(QString("the admissible space of tool %1 is empty: %2")
                               .arg(quoted(request_.tool), QString::fromStdString(describeConstraint(
                                                               grid_->funnel().emptiedBy(), expert_.settings))));
  table_ = std::make_unique<ObjectiveTable>(*grid_, request_.models, request_.normalisation);
  front_ = nonDominated(table_->scores());
}

ObjectiveRequirement ParetoStudy::projectRequirement() const {
  ObjectiveRequirement r;
  r.objective = Objective::Mrr;
  r.lo = request_.minimum_mrr.resolve(table_->range().max[index(Objective::Mrr)]);
  r.hi = std::numeric_limits<double>::infinity();
  return r;
}

ParetoSelection ParetoStudy::selectWeighted(const ParetoWeights& w,
                                            const std::optional<ObjectiveRequirement>& requirement) const {
  if (!rules_ || !rules_->restrictsPoint()) return ParetoSelector(*table_).coarse(w, requirement);
  auto admits = [&](const ParetoPoint& p) { return ruleAdmits(p); };
  std::optional<ParetoSelection> s = selectWhere(
      *table_, w, [&](const ParetoPoint& p) { return admits(p) && (!requirement || requirement->satisfiedBy(p)); });
  if (!s && requirement) {
    s = selectWhere(*table_, w, admits);
    if (s) s->filtered = false;
  }
  if (!s)
    throw ComputationError(
        QString("the operator rules exclude every point of the admissible space of tool %1 (%2 points)")
            .arg(quoted(request_.tool))
            .arg(table_->size()));
  return *s;
}

ParetoSelection ParetoStudy::selectEconomic(EconomicObjective objective,
                                            const std::optional<ObjectiveRequirement>& requirement) const {
  const MachiningEconomics& e = *request_.economics;
  auto admits = [&](const ParetoPoint& p) { return ruleAdmits(p); };
  bool filtered = true;
  std::optional<std::size_t> i = cheapestPoint(*table_, e, objective, [&](const ParetoPoint& p) {
    return admits(p) && (!requirement || requirement->satisfiedBy(p));
  });
  if (!i && requirement) {
    i = cheapestPoint(*table_, e, objective, admits);
    filtered = false;
  }
  if (!i)
    throw ComputationError(
        QString("the operator rules exclude every point of the admissible space of tool %1 (%2 points)")
            .arg(quoted(request_.tool))
            .arg(table_->size()));
  ParetoSelection s;
  s.point = table_->points()[*i];
  s.scores = table_->scores()[*i];
  s.j = objectiveJ(request_.weights, s.scores);
  s.table_index = i;
  s.filtered = filtered;
  s.candidates = table_->size();
  return s;
}

ParetoChoice ParetoStudy::choose(const ParetoChoiceOptions& options) const {
  ParetoChoice out;
  out.objective = options.objective.value_or(request_.objective);
  std::optional<ObjectiveRequirement> requirement = options.requirement;
  if (requirement) {
    out.requirement_source = "--require";
  } else if (options.project_requirement) {
    requirement = projectRequirement();
    out.requirement_source = request_.minimum_mrr.field;
    out.requirement_text = request_.minimum_mrr.describe(table_->range().max[index(Objective::Mrr)]);
  }
  out.requirement = requirement;
  if (out.objective != ParetoObjectiveKind::Weighted && !request_.economics)
    throw ProjectError(
        QString("pareto.objective = '%1' needs pareto.economics").arg(paretoObjectiveName(out.objective)));

  ParetoWeights w = options.weights.value_or(request_.weights);
  const ParetoSelector sel(*table_);
  std::optional<ParetoSelection> unrestricted;
  if (out.objective == ParetoObjectiveKind::Weighted) {
    if (rules_) w = applyWeightRules(rules_->outcome, w);
    if (requirement) unrestricted = selectWeighted(w, std::nullopt);
    // The flag's requirement is the paper's Rule 11 (move the weights, filter where they cannot
    // reach it). The project's minimum MRR is a constraint only (the epsilon-constraint method): the
    // weights stay the operator's, and the point is the best J among those meeting it; moving the
    // weights would jump across the front's non-convex gap to the largest MRR on the lobes' border.
    if (options.requirement) {
      const RequirementResult r = applyRequirement(sel, w, *requirement);
      w = r.weights;
      out.requirement_changed = r.changed;
    }
    if (options.auto_weights) {
      out.ascent = ascendWeights(sel, w, request_.ascent, requirement);
      w = out.ascent->weights;
    }
    if (rules_) w = applyWeightRules(rules_->outcome, w);
    out.selection = selectWeighted(w, requirement);
  } else {
    const EconomicObjective eo =
        out.objective == ParetoObjectiveKind::MinCost ? EconomicObjective::MinCost : EconomicObjective::MaxRate;
    if (requirement) unrestricted = selectEconomic(eo, std::nullopt);
    out.selection = selectEconomic(eo, requirement);
  }
  out.weights = w;
  out.coarse_j = out.selection.j;
  if (options.fine && out.objective == ParetoObjectiveKind::Weighted) {
    const ParetoSelection f = sel.fine(out.selection, w, request_.fine, requirement);
    if (ruleAdmits(f.point))
      out.selection = f;
    else
      out.fine_rejected_by_rules = true;
  }
  out.requirement_satisfied = requirement && requirement->satisfiedBy(out.selection.point);
  out.requirement_binding = requirement && unrestricted && !requirement->satisfiedBy(unrestricted->point);
  if (request_.economics) out.economics = pointEconomics(*request_.economics, out.selection.point);
  out.binding = bindingLimits(out);
  return out;
}

std::vector<BindingLimit> ParetoStudy::bindingLimits(const ParetoChoice& choice) const {
  std::vector<BindingLimit> out;
  const ParetoPoint& q = choice.point();
  if (choice.requirement_binding) {
    const QString text = choice.requirement_text.isEmpty() ? QString("the --require bound") : choice.requirement_text;
    out.push_back({"requirement", "", QString("Rule 11 requirement: %1").arg(text)});
  }
  if (rules_) {
    // A fired bound on a point variable is binding when q sits on it (within 2 %, about a grid step).
    const std::map<std::string, double> vars = pointVariables(q, setup_.teeth);
    auto near = [](double v, double bound) { return std::abs(v - bound) <= 0.02 * std::max(std::abs(bound), 1e-12); };
    for (const auto& [name, bounds] : rules_->outcome.bounds) {
      const auto it = vars.find(name);
      if (it == vars.end()) continue;
      const std::pair<const std::optional<RuleRef>*, double> sides[] = {{&bounds.upperRule, bounds.upper},
                                                                        {&bounds.lowerRule, bounds.lower}};
      for (const auto& [rule, bound] : sides)
        if (*rule && std::isfinite(bound) && near(it->second, bound))
          out.push_back(
              {"operator_rule", "",
               QString("operator rule %1: %2").arg((*rule)->line).arg(QString::fromStdString((*rule)->text))});
    }
  }
  const LimitsAtPoint limits = limitsAtPoint(*grid_, q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m);
  auto add = [&](QConstraint c, const QString& direction, double next, const QString& unit) {
    if (c == QConstraint::None) return;
    out.push_back({constraintKey(c), direction,
                   QString("%1 %2 %3 would break %4")
                       .arg(direction == "depth" ? "depth" : "feed per tooth")
                       .arg(next, 0, 'g', 4)
                       .arg(unit, QString::fromStdString(describeConstraint(c, expert_.settings)))});
  };
  add(limits.depth, "depth", limits.next_depth_m * 1e3, "mm");
  add(limits.feed, "feed", limits.next_feed_per_tooth_m * 1e3, "mm");
  const std::vector<double>& speeds = grid_->speeds();
  const double rpm = revPerSToRpm(q.speed_rev_per_s);
  if (std::abs(q.speed_rev_per_s - speeds.front()) <= 1e-9 * speeds.front())
    out.push_back(
        {"grid", "speed", QString("speed %1 rpm is the lowest of the grid (expert.grid.speed_from_rpm)").arg(rpm)});
  else if (std::abs(q.speed_rev_per_s - speeds.back()) <= 1e-9 * speeds.back())
    out.push_back({"grid", "speed", QString("speed %1 rpm is the highest of the grid").arg(rpm)});
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
  r.machine = {machine.name, machine.spindle_power_W, machine.max_spindle_rpm};
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
