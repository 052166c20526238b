#include "cli/pareto_request.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_support.h"
#include "model/job_control.h"

namespace mx::app {

namespace {

double numberField(const QJsonObject& o, const QString& path, const QString& key, double lo, double hi,
                   const QString& range, std::optional<double> fallback = {}) {
  return sectionNumber(o, path, key, lo, hi, range, fallback);
}

[[noreturn]] void fail(const QString& field, const QString& value, const QString& range) {
  failField(field, value, range);
}

PowerLawModel readModel(const QJsonObject& pareto, const QString& key) {
  const QString path = "pareto." + key;
  if (!pareto.value(key).isObject()) throw CliError(QString("%1 is missing: the model constants K and exponents").arg(path), kExitBadInput);
  const QJsonObject o = pareto.value(key).toObject();
  PowerLawModel m;
  m.k = numberField(o, path, "K", 1e-300, 1e300, "a finite number > 0");
  if (!(m.k > 0.0)) fail(path + ".K", QString::number(m.k), "a finite number > 0");
  m.speed_exponent = numberField(o, path, "speed_exponent", -10.0, 10.0, "in [-10, 10]");
  m.depth_exponent = numberField(o, path, "depth_exponent", -10.0, 10.0, "in [-10, 10]");
  m.feed_exponent = numberField(o, path, "feed_exponent", -10.0, 10.0, "in [-10, 10]");
  return m;
}

ParetoWeights checkedWeights(const QString& name, const std::vector<double>& values) {
  if (values.size() != kObjectiveCount)
    throw CliError(QString("%1 has %2 values: expected 4 weights (tol, mrr, surf, ros)").arg(name).arg(values.size()),
                   kExitBadInput);
  ParetoWeights w{};
  for (std::size_t i = 0; i < kObjectiveCount; ++i) w[i] = values[i];
  try {
    validateParetoWeights(w);
  } catch (const InvalidInput& e) {
    throw CliError(QString("%1: %2").arg(name, QString::fromStdString(e.what())), kExitBadInput);
  }
  return w;
}

}  // namespace

ParetoRequest paretoRequestFromProject(const Project& project) {
  if (!project.document.value("pareto").isObject())
    throw CliError("section 'pareto' is missing: the Pareto expert system needs the taylor and roughness models",
                   kExitBadInput);
  const QJsonObject p = project.document.value("pareto").toObject();
  ParetoRequest r;
  if (project.tools.empty()) throw CliError("section 'tools' is empty", kExitBadInput);
  r.tool = project.tools.front().id;
  if (p.contains("tool")) {
    r.tool = p.value("tool").toString();
    if (project.findTool(r.tool) == nullptr)
      throw CliError(QString("pareto.tool = '%1': no tool with that id").arg(r.tool), kExitBadInput);
  }
  r.models.tool_life = readModel(p, "taylor");
  r.models.roughness = readModel(p, "roughness");
  if (p.contains("weights")) {
    const QJsonValue wv = p.value("weights");
    if (!wv.isArray()) throw CliError("pareto.weights: must be an array of 4 numbers", kExitBadInput);
    std::vector<double> values;
    for (const QJsonValue& v : wv.toArray()) {
      if (!v.isDouble()) throw CliError("pareto.weights: must be an array of 4 numbers", kExitBadInput);
      values.push_back(v.toDouble());
    }
    r.weights = checkedWeights("pareto.weights", values);
  }
  const QJsonObject fine = p.value("fine").toObject();
  const double div = numberField(fine, "pareto.fine", "divisions", 1.0, 100.0, "an integer in [1, 100]", 5.0);
  if (std::floor(div) != div) fail("pareto.fine.divisions", QString::number(div), "an integer in [1, 100]");
  r.fine.divisions = static_cast<int>(div);
  const QJsonObject aw = p.value("auto_weights").toObject();
  r.ascent.step = numberField(aw, "pareto.auto_weights", "step", 1e-12, 1.0, "in (0, 1]", 0.05);
  r.ascent.tolerance = numberField(aw, "pareto.auto_weights", "tolerance", 1e-15, 0.999999, "in (0, 1)", 1e-4);
  const double iters =
      numberField(aw, "pareto.auto_weights", "max_iterations", 1.0, 100000.0, "an integer in [1, 100000]", 200.0);
  if (std::floor(iters) != iters)
    fail("pareto.auto_weights.max_iterations", QString::number(iters), "an integer in [1, 100000]");
  r.ascent.max_iterations = static_cast<int>(iters);
  r.operator_rules = operatorRulesFromProject(project);
  return r;
}

QStringList operatorRulesFromProject(const Project& project) {
  QStringList out;
  if (!project.document.contains("operator_rules")) return out;
  const QJsonValue rv = project.document.value("operator_rules");
  if (!rv.isArray()) throw CliError("operator_rules: must be an array of strings (one rule each)", kExitBadInput);
  const QJsonArray rules = rv.toArray();
  for (qsizetype i = 0; i < rules.size(); ++i) {
    if (!rules[i].isString() || rules[i].toString().contains('\n'))
      throw CliError(QString("operator_rules[%1]: must be a string holding one rule").arg(i), kExitBadInput);
    out << rules[i].toString();
  }
  return out;
}

ParetoWeights parseParetoWeights(const QString& text) {
  std::vector<double> values;
  for (const QString& item : text.split(',')) {
    bool ok = false;
    const double v = item.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
      throw CliError(QString("--w = '%1': '%2' is not a finite number").arg(text, item), kExitBadInput);
    values.push_back(v);
  }
  return checkedWeights(QString("--w = '%1'").arg(text), values);
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
