#include "services/pareto_rules.h"

#include <QJsonArray>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "document/shortened_text.h"
#include "model/milling_setup.h"
#include "rules/rule_evaluator.h"
#include "rules/rule_parser.h"

namespace mx::app {

namespace {

const std::array<const char*, 6> kPointVariables{"speed_rpm",          "depth_mm",  "feed_mm_per_tooth",
                                                 "feed_velocity_mm_s", "mrr_cm3_s", "power_W"};
const std::array<const char*, kObjectiveCount> kWeightVariables{"weight.tol", "weight.mrr", "weight.surf",
                                                                "weight.ros"};

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

}  // namespace

bool ParetoRules::restrictsPoint() const {
  return std::any_of(kPointVariables.begin(), kPointVariables.end(),
                     [&](const char* v) { return outcome.boundsOf(v) != nullptr; });
}

bool ParetoRules::restrictsWeights() const {
  return std::any_of(kWeightVariables.begin(), kWeightVariables.end(),
                     [&](const char* v) { return outcome.boundsOf(v) != nullptr; });
}

bool ParetoRules::admits(const ParetoPoint& p, int teeth) const {
  for (const auto& [name, value] : pointVariables(p, teeth))
    if (!outcome.admits(name, value)) return false;
  return true;
}

RuleContext ruleContextFor(const Project& project, const ToolSpec& tool) {
  RuleContext c;
  c.set("tool.id", tool.id.toStdString());
  c.set("tool.teeth", static_cast<double>(tool.teeth));
  c.set("tool.diameter_mm", tool.diameter_mm);
  c.set("tool.helix_deg", tool.helix_deg);
  c.set("tool.modes", static_cast<double>(tool.modes_x.size() + tool.modes_y.size()));
  if (tool.Kt_N_mm2)
    c.set("tool.Kt_N_mm2", *tool.Kt_N_mm2);
  else if (project.material)
    c.set("tool.Kt_N_mm2", project.material->Kt_N_mm2);
  if (tool.Kr)
    c.set("tool.Kr", *tool.Kr);
  else if (project.material)
    c.set("tool.Kr", project.material->Kr);
  if (project.material) {
    c.set("material.name", project.material->name.toStdString());
    c.set("material.Kt_N_mm2", project.material->Kt_N_mm2);
    c.set("material.Kr", project.material->Kr);
  }
  if (project.operation) {
    const OperationSpec& o = *project.operation;
    c.set("operation.milling", o.milling == MillingDirection::Down ? "down" : "up");
    if (o.radial_immersion) c.set("operation.radial_immersion", *o.radial_immersion);
    if (o.radial_depth_mm) c.set("operation.radial_depth_mm", *o.radial_depth_mm);
    c.set("operation.max_feed_per_tooth_mm", o.max_feed_per_tooth_mm);
  }
  if (project.machine) {
    const MachineSpec& m = *project.machine;
    c.set("machine.spindle_power_W", m.spindle_power_W);
    if (m.max_spindle_rpm) c.set("machine.max_spindle_rpm", *m.max_spindle_rpm);
    if (m.max_feed_mm_s) c.set("machine.max_feed_mm_s", *m.max_feed_mm_s);
    if (m.max_torque_Nm) c.set("machine.max_torque_Nm", *m.max_torque_Nm);
    if (m.name) c.set("machine.name", m.name->toStdString());
  }
  return c;
}

ParetoRules evaluateParetoRules(const QStringList& texts, const Project& project, const ToolSpec& tool) {
  std::vector<std::string> lines;
  lines.reserve(static_cast<std::size_t>(texts.size()));
  for (const QString& t : texts) lines.push_back(t.toStdString());
  const RuleParseResult parsed = parseRules(lines);
  if (!parsed.ok()) {
    QStringList messages;
    for (const RuleError& e : parsed.errors)
      messages << QString("operator_rules[%1]: %2").arg(e.line - 1).arg(qs(e.toString()));
    throw ProjectError(messages.join('\n'));
  }
  ParetoRules r;
  r.rules = parsed.rules;
  r.outcome = evaluate(r.rules, ruleContextFor(project, tool));
  if (!r.outcome.consistent()) {
    QStringList messages;
    for (const RuleContradiction& c : r.outcome.contradictions)
      messages << QString(
                      "operator_rules: contradictory rules: operator_rules[%1] (line %2) %3 and "
                      "operator_rules[%4] (line %5) %6: %7")
                      .arg(c.first.line - 1)
                      .arg(c.first.line)
                      .arg(quoted(qs(c.first.text)))
                      .arg(c.second.line - 1)
                      .arg(c.second.line)
                      .arg(quoted(qs(c.second.text)), qs(c.message));
    throw ProjectError(messages.join('\n'));
  }
  return r;
}

std::map<std::string, double> pointVariables(const ParetoPoint& p, int teeth) {
  return {{"speed_rpm", revPerSToRpm(p.speed_rev_per_s)},
          {"depth_mm", p.depth_m * 1e3},
          {"feed_mm_per_tooth", p.feed_per_tooth_m * 1e3},
          {"feed_velocity_mm_s", p.feed_per_tooth_m * teeth * p.speed_rev_per_s * 1e3},
          {"mrr_cm3_s", p.mrr() * 1e6},
          {"power_W", p.power_w}};
}

std::vector<double> applyWeightBounds(const std::vector<const RuleOutcome*>& outcomes,
                                      const std::vector<std::string>& names, const std::vector<double>& w) {
  const std::size_t n = names.size();
  std::vector<double> lo(n, 0.0), hi(n, 1.0);
  double sum_lo = 0.0, sum_hi = 0.0;
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    for (const RuleOutcome* outcome : outcomes)
      if (const VariableBounds* b = outcome->boundsOf(names[i])) {
        any = true;
        lo[i] = std::max(lo[i], b->lower);
        hi[i] = std::min(hi[i], b->upper);
      }
    if (lo[i] > hi[i])
      throw ProjectError(QString("operator_rules: %1 has no admissible value in [0, 1] (bounds [%2, %3])")
                             .arg(qs(names[i]))
                             .arg(lo[i])
                             .arg(hi[i]));
    sum_lo += lo[i];
    sum_hi += hi[i];
  }
  if (!any) return w;
  if (sum_lo > 1.0 + 1e-12 || sum_hi < 1.0 - 1e-12)
    throw ProjectError(QString("operator_rules: the weight bounds leave no weights on the simplex (sum of lower "
                               "bounds %1, sum of upper bounds %2)")
                           .arg(sum_lo)
                           .arg(sum_hi));
  auto total = [&](double lambda) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += std::clamp(w[i] + lambda, lo[i], hi[i]);
    return s;
  };
  double a = -2.0, b = 2.0;  // total(a) = sum lo <= 1 <= sum hi = total(b)
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b);
    (total(m) < 1.0 ? a : b) = m;
  }
  std::vector<double> out(n);
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += out[i] = std::clamp(w[i] + 0.5 * (a + b), lo[i], hi[i]);
  // Remove the bisection residue (~1e-16) on a weight strictly inside its bounds.
  for (std::size_t i = 0; i < n; ++i) {
    const double v = out[i] + (1.0 - s);
    if (v >= lo[i] && v <= hi[i]) {
      out[i] = v;
      break;
    }
  }
  return out;
}

ParetoWeights applyWeightRules(const RuleOutcome& outcome, const ParetoWeights& w) {
  const std::vector<double> out =
      applyWeightBounds({&outcome}, {kWeightVariables.begin(), kWeightVariables.end()}, {w.begin(), w.end()});
  return {out[0], out[1], out[2], out[3]};
}

std::optional<ParetoSelection> selectWhere(const ObjectiveTable& table, const ParetoWeights& w,
                                           const std::function<bool(const ParetoPoint&)>& admit) {
  std::optional<std::size_t> best;
  double best_j = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!admit(table.points()[i])) continue;
    const double j = objectiveJ(w, table.scores()[i]);
    if (j > best_j) {
      best_j = j;
      best = i;
    }
  }
  if (!best) return std::nullopt;
  ParetoSelection s;
  s.table_index = best;
  s.point = table.points()[*best];
  s.scores = table.scores()[*best];
  s.j = best_j;
  s.candidates = table.size();
  return s;
}

QJsonObject rulesJson(const ParetoRules& rules, const ParetoPoint& chosen, int teeth) {
  const std::map<std::string, double> vars = pointVariables(chosen, teeth);
  QJsonArray fired, advice, undetermined;
  for (const RuleRef& ref : rules.outcome.fired) {
    const Rule* rule = rules.rules.findLine(ref.line);
    const bool isAdvice = rule != nullptr && rule->kind == RuleKind::Advice;
    QString reason;
    if (rule != nullptr && !rule->message.empty())
      reason = qs(rule->message);
    else if (rule != nullptr && rule->bound)
      reason = qs(rule->bound->toString());
    if (rule != nullptr && rule->condition) reason += QString(" (since %1)").arg(qs(toString(rule->condition)));
    fired.append(QJsonObject{
        {"line", ref.line}, {"text", qs(ref.text)}, {"kind", isAdvice ? "advice" : "constraint"}, {"reason", reason}});
  }
  for (const RuleAdvice& a : rules.outcome.advice) {
    QJsonValue followed;
    if (a.bound) {
      const auto it = vars.find(a.bound->variable);
      if (it != vars.end()) followed = a.followedBy(it->second);
    }
    advice.append(QJsonObject{
        {"line", a.rule.line}, {"text", qs(a.rule.text)}, {"message", qs(a.message)}, {"followed", followed}});
  }
  for (const UndeterminedRule& u : rules.outcome.undetermined) {
    QJsonArray paths;
    for (const std::string& p : u.paths) paths.append(qs(p));
    undetermined.append(QJsonObject{{"line", u.rule.line}, {"text", qs(u.rule.text)}, {"paths", paths}});
  }
  return {{"fired", fired}, {"advice", advice}, {"undetermined", undetermined}};
}

}  // namespace mx::app
