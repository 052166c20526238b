#include "services/pareto_request.h"

#include <QStringList>
#include <cmath>

#include "core/invalid_input.h"
#include "document/shortened_text.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

[[noreturn]] void fail(const QString& flag, const QString& value, const QString& range) {
  throw InputError(QString("%1 = %2: must be %3").arg(flag, value, range));
}

PowerLawModel modelFrom(const PowerLawSpec& spec) {
  PowerLawModel m;
  m.k = spec.K;
  m.speed_exponent = spec.speed_exponent;
  m.depth_exponent = spec.depth_exponent;
  m.feed_exponent = spec.feed_exponent;
  return m;
}

// Throws Error (InputError for a flag, ProjectError for the project) unless 4 weights on the simplex.
template <typename Throw>
ParetoWeights checkedWeights(const QString& name, const std::vector<double>& values, Throw raise) {
  if (values.size() != kObjectiveCount)
    raise(QString("%1 has %2 values: expected 4 weights (tol, mrr, surf, ros)").arg(name).arg(values.size()));
  ParetoWeights w{};
  for (std::size_t i = 0; i < kObjectiveCount; ++i) w[i] = values[i];
  try {
    validateParetoWeights(w);
  } catch (const InvalidInput& e) {
    raise(QString("%1: %2").arg(name, QString::fromStdString(e.what())));
  }
  return w;
}

[[noreturn]] void raiseProject(const QString& message) {
  throw ProjectError(message);
}
[[noreturn]] void raiseFlag(const QString& message) {
  throw InputError(message);
}

MachiningEconomics economicsFrom(const ParetoEconomicsSpec& e) {
  MachiningEconomics m;
  m.machine_rate_per_s = e.machine_rate_per_h / 3600.0;
  m.tool_cost = e.tool_cost;
  m.tool_change_s = e.tool_change_min * 60.0;
  m.removal_volume_m3 = e.removal_volume_cm3 * 1e-6;
  return m;
}

MinimumMrr minimumMrrFrom(const ParetoSection& p) {
  MinimumMrr m;
  if (!p.requirements) return m;
  const ParetoRequirementsSpec& q = *p.requirements;
  m.is_default = false;
  if (q.min_mrr_cm3_s) {
    m.basis = MinimumMrr::Basis::Absolute;
    m.value = *q.min_mrr_cm3_s * 1e-6;
    m.field = "pareto.requirements.min_mrr_cm3_s";
  } else if (q.max_time_min) {
    m.basis = MinimumMrr::Basis::TimeForVolume;
    m.value = *q.max_time_min * 60.0;
    m.volume_m3 = q.removal_volume_cm3.value_or(p.economics ? p.economics->removal_volume_cm3 : 0.0) * 1e-6;
    m.field = "pareto.requirements.max_time_min";
  } else if (q.min_mrr_fraction) {
    m.value = *q.min_mrr_fraction;
  } else {
    m.is_default = true;
  }
  return m;
}

}  // namespace

double MinimumMrr::resolve(double max_mrr) const {
  switch (basis) {
    case Basis::Absolute:
      return value;
    case Basis::TimeForVolume:
      return volume_m3 / value;
    case Basis::FractionOfMax:
      break;
  }
  return value * max_mrr;
}

QString MinimumMrr::describe(double max_mrr) const {
  const QString bound = QString("MRR >= %1 cm\u00b3/s").arg(resolve(max_mrr) * 1e6, 0, 'g', 4);
  switch (basis) {
    case Basis::Absolute:
      return QString("%1 (%2)").arg(bound, field);
    case Basis::TimeForVolume:
      return QString("%1 (%2 = %3 min for %4 cm\u00b3)")
          .arg(bound, field)
          .arg(value / 60.0, 0, 'g', 4)
          .arg(volume_m3 * 1e6, 0, 'g', 4);
    case Basis::FractionOfMax:
      break;
  }
  return QString("%1 (%2 = %3 of the largest MRR of Q, %4 cm\u00b3/s%5)")
      .arg(bound, field)
      .arg(value, 0, 'g', 3)
      .arg(max_mrr * 1e6, 0, 'g', 4)
      .arg(is_default ? QString(", the shop default") : QString());
}

ParetoNormalisation paretoNormalisationFromName(const QString& name, const QString& field) {
  if (name == "minmax") return ParetoNormalisation::MinMax;
  if (name == "max") return ParetoNormalisation::Max;
  if (name == "log") return ParetoNormalisation::Log;
  throw InputError(QString("%1 = %2: must be one of minmax, max, log").arg(field, quoted(name)));
}

QString paretoNormalisationName(ParetoNormalisation n) {
  switch (n) {
    case ParetoNormalisation::MinMax:
      return "minmax";
    case ParetoNormalisation::Max:
      return "max";
    case ParetoNormalisation::Log:
      break;
  }
  return "log";
}

ParetoObjectiveKind paretoObjectiveFromName(const QString& name, const QString& field) {
  if (name == "weighted") return ParetoObjectiveKind::Weighted;
  if (name == "min_cost") return ParetoObjectiveKind::MinCost;
  if (name == "max_rate") return ParetoObjectiveKind::MaxRate;
  throw InputError(QString("%1 = %2: must be one of weighted, min_cost, max_rate").arg(field, quoted(name)));
}

QString paretoObjectiveName(ParetoObjectiveKind k) {
  switch (k) {
    case ParetoObjectiveKind::MinCost:
      return "min_cost";
    case ParetoObjectiveKind::MaxRate:
      return "max_rate";
    case ParetoObjectiveKind::Weighted:
      break;
  }
  return "weighted";
}

ParetoRequest paretoRequestFrom(const ParetoSection& p, const Project& project) {
  ParetoRequest r;
  if (project.tools.empty()) throw ProjectError("section 'tools' is empty");
  r.tool = p.tool.value_or(project.tools.front().id);
  if (project.findTool(r.tool) == nullptr)
    throw ProjectError(QString("pareto.tool = %1: no tool with that id").arg(quoted(r.tool)));
  if (!p.taylor) throw ProjectError("pareto.taylor is missing: the model constants K and exponents");
  if (!p.roughness) throw ProjectError("pareto.roughness is missing: the model constants K and exponents");
  r.models.tool_life = modelFrom(*p.taylor);
  r.models.roughness = modelFrom(*p.roughness);
  if (p.weights) r.weights = checkedWeights("pareto.weights", *p.weights, raiseProject);
  const ParetoFineSpec fine = p.fine.value_or(ParetoFineSpec{});
  r.fine.divisions = static_cast<int>(fine.divisions.value_or(5.0));
  const ParetoAutoWeightsSpec aw = p.auto_weights.value_or(ParetoAutoWeightsSpec{});
  r.ascent.step = aw.step.value_or(0.05);
  r.ascent.tolerance = aw.tolerance.value_or(1e-4);
  r.ascent.max_iterations = static_cast<int>(aw.max_iterations.value_or(200.0));
  r.operator_rules = operatorRulesFromProject(project);
  try {
    if (p.normalisation) r.normalisation = paretoNormalisationFromName(*p.normalisation, "pareto.normalisation");
    if (p.objective) r.objective = paretoObjectiveFromName(*p.objective, "pareto.objective");
  } catch (const InputError& e) {
    throw ProjectError(QString::fromStdString(e.what()));
  }
  if (p.economics) r.economics = economicsFrom(*p.economics);
  if (r.objective != ParetoObjectiveKind::Weighted && !r.economics)
    throw ProjectError(QString("pareto.objective = '%1' needs pareto.economics").arg(paretoObjectiveName(r.objective)));
  r.minimum_mrr = minimumMrrFrom(p);
  return r;
}

ParetoRequest paretoRequestFromProject(const Project& project) {
  if (!project.pareto)
    throw ProjectError("section 'pareto' is missing: the Pareto expert system needs the taylor and roughness models");
  return paretoRequestFrom(*project.pareto, project);
}

QStringList operatorRulesFromProject(const Project& project) {
  return project.operator_rules.value_or(QStringList{});
}

ParetoWeights parseParetoWeights(const QString& text) {
  std::vector<double> values;
  for (const QString& item : text.split(',')) {
    bool ok = false;
    const double v = item.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
      throw InputError(QString("--w = %1: %2 is not a finite number").arg(quoted(text), quoted(item)));
    values.push_back(v);
  }
  return checkedWeights(QString("--w = %1").arg(quoted(text)), values, raiseFlag);
}

ObjectiveRequirement parseRequirement(const QString& text) {
  const QString form = "KEY=LO:HI with KEY mrr_cm3_s, tol, surf or ros and finite LO <= HI";
  const qsizetype eq = text.indexOf('=');
  if (eq < 0) fail("--require", "'" + text + "'", form);
  const QString key = text.left(eq).trimmed();
  const QStringList bounds = text.mid(eq + 1).split(':');
  if (bounds.size() != 2) fail("--require", "'" + text + "'", form);
  bool ok_lo = false, ok_hi = false;
  const double lo = bounds[0].trimmed().toDouble(&ok_lo), hi = bounds[1].trimmed().toDouble(&ok_hi);
  if (!ok_lo || !ok_hi || !std::isfinite(lo) || !std::isfinite(hi) || lo > hi || lo < 0.0)
    fail("--require", "'" + text + "'", form + " (LO >= 0)");
  ObjectiveRequirement r;
  double scale = 1.0;
  if (key == "mrr_cm3_s") {
    r.objective = Objective::Mrr;
    scale = 1e-6;
  } else if (key == "tol") {
    r.objective = Objective::ToolLife;
  } else if (key == "surf") {
    r.objective = Objective::Roughness;
  } else if (key == "ros") {
    r.objective = Objective::Robustness;
  } else {
    fail("--require key", "'" + key + "'", "one of mrr_cm3_s, tol, surf, ros");
  }
  r.lo = lo * scale;
  r.hi = hi * scale;
  return r;
}

}  // namespace mx::app
