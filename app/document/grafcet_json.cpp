#include "document/grafcet_json.h"
#include "document/project.h"

#include <QJsonArray>
#include <QMap>
#include <cmath>

#include "document/project_rules.h"

namespace mx::app {

namespace {

constexpr double kMaxInteger = 1e9;
const QString kIntegerRange = "an integer in [0, 1000000000]";

[[noreturn]] void fail(const QString& field, const QString& message) {
  throw ProjectError(field + ": " + message);
}

QString shown(const QJsonValue& v) {
  switch (v.type()) {
    case QJsonValue::String: return "\"" + v.toString() + "\"";
    case QJsonValue::Double: return QString::number(v.toDouble(), 'g', 10);
    case QJsonValue::Bool: return v.toBool() ? "true" : "false";
    case QJsonValue::Array: return "(an array)";
    case QJsonValue::Object: return "(an object)";
    case QJsonValue::Null: return "null";
    default: return "(missing)";
  }
}

int integer(const QJsonValue& v, const QString& field) {
  const double x = v.toDouble(-1.0);
  if (!v.isDouble() || !(x >= 0.0 && x <= kMaxInteger) || std::floor(x) != x) throwBadField(field, shown(v), kIntegerRange);
  return static_cast<int>(x);
}

QJsonObject object(const QJsonValue& v, const QString& field) {
  if (!v.isObject()) throwBadField(field, shown(v), "an object");
  return v.toObject();
}

QJsonArray array(const QJsonObject& o, const QString& key, const QString& field, bool required) {
  if (!o.contains(key)) {
    if (required) fail(field, "missing");
    return {};
  }
  const QJsonValue v = o.value(key);
  if (!v.isArray()) throwBadField(field, shown(v), "an array");
  return v.toArray();
}

QString string(const QJsonObject& o, const QString& key, const QString& field, bool required) {
  if (!o.contains(key)) {
    if (required) fail(field, "missing");
    return {};
  }
  const QJsonValue v = o.value(key);
  if (!v.isString()) throwBadField(field, shown(v), "a string");
  return v.toString();
}

std::vector<int> ids(const QJsonObject& o, const QString& key, const QString& field) {
  std::vector<int> out;
  const QJsonArray a = array(o, key, field, true);
  for (qsizetype i = 0; i < a.size(); ++i) out.push_back(integer(a.at(i), QString("%1[%2]").arg(field).arg(i)));
  return out;
}

QJsonArray idsJson(const std::vector<int>& ids) {
  QJsonArray a;
  for (int id : ids) a.append(id);
  return a;
}

QString elementPath(const QString& path, const char* list, int index) {
  return QString("%1.%2[%3]").arg(path, list).arg(index);
}

}  // namespace

GrafcetChart grafcetChartFromJson(const QJsonValue& value, const QString& path) {
  const QJsonObject o = object(value, path);
  GrafcetChart c;
  c.name = string(o, "name", path + ".name", false).toStdString();
  const QJsonArray steps = array(o, "steps", path + ".steps", true);
  for (qsizetype i = 0; i < steps.size(); ++i) {
    const QString at = elementPath(path, "steps", static_cast<int>(i));
    const QJsonObject s = object(steps.at(i), at);
    GrafcetStep step;
    if (!s.contains("id")) fail(at + ".id", "missing");
    step.id = integer(s.value("id"), at + ".id");
    step.name = string(s, "name", at + ".name", true).toStdString();
    if (s.contains("initial")) {
      if (!s.value("initial").isBool()) throwBadField(at + ".initial", shown(s.value("initial")), "true or false");
      step.initial = s.value("initial").toBool();
    }
    const QJsonArray actions = array(s, "actions", at + ".actions", false);
    for (qsizetype k = 0; k < actions.size(); ++k) {
      const QString field = QString("%1.actions[%2]").arg(at).arg(k);
      if (!actions.at(k).isString()) throwBadField(field, shown(actions.at(k)), "a string (\"A\", or \"L*\" for an impulse)");
      step.actions.push_back(actions.at(k).toString().toStdString());
    }
    c.steps.push_back(std::move(step));
  }
  const QJsonArray transitions = array(o, "transitions", path + ".transitions", false);
  for (qsizetype i = 0; i < transitions.size(); ++i) {
    const QString at = elementPath(path, "transitions", static_cast<int>(i));
    const QJsonObject t = object(transitions.at(i), at);
    GrafcetTransition tr;
    if (!t.contains("id")) fail(at + ".id", "missing");
    tr.id = integer(t.value("id"), at + ".id");
    tr.from = ids(t, "from", at + ".from");
    tr.to = ids(t, "to", at + ".to");
    tr.receptivity = string(t, "receptivity", at + ".receptivity", true).toStdString();
    if (t.contains("priority")) tr.priority = integer(t.value("priority"), at + ".priority");
    c.transitions.push_back(std::move(tr));
  }
  return c;
}

QString grafcetIssuePath(const GrafcetIssue& issue, const QString& path) {
  QString at;
  switch (issue.element) {
    case GrafcetElement::Chart: return path + ".steps";
    case GrafcetElement::Step: at = elementPath(path, "steps", issue.index); break;
    case GrafcetElement::Transition: at = elementPath(path, "transitions", issue.index); break;
  }
  return issue.field.empty() ? at : at + "." + QString::fromStdString(issue.field);
}

QStringList grafcetChartErrors(const GrafcetChart& chart, const QString& path,
                               const std::optional<std::set<std::string>>& knownSignals) {
  const std::vector<GrafcetIssue> issues =
      knownSignals ? validateGrafcetChart(chart, *knownSignals) : validateGrafcetChart(chart);
  QStringList out;
  for (const GrafcetIssue& i : issues)
    out << grafcetIssuePath(i, path) + ": " + QString::fromStdString(i.message);
  return out;
}

GrafcetChart loadGrafcetChart(const QJsonValue& value, const QString& path,
                              const std::optional<std::set<std::string>>& knownSignals) {
  GrafcetChart chart = grafcetChartFromJson(value, path);
  const QStringList errors = grafcetChartErrors(chart, path, knownSignals);
  if (!errors.isEmpty()) throw ProjectError(errors.front());
  return chart;
}

QJsonObject grafcetChartToJson(const GrafcetChart& chart, const QJsonObject& previous) {
  // Previous element objects by id, to keep their unknown keys.
  auto byId = [&](const char* list) {
    QMap<int, QJsonObject> m;
    for (const QJsonValue& v : previous.value(list).toArray())
      if (v.isObject() && v.toObject().value("id").isDouble()) m.insert(v.toObject().value("id").toInt(), v.toObject());
    return m;
  };
  const QMap<int, QJsonObject> oldSteps = byId("steps"), oldTransitions = byId("transitions");
  QJsonObject o = previous;
  o["name"] = QString::fromStdString(chart.name);
  QJsonArray steps;
  for (const GrafcetStep& s : chart.steps) {
    QJsonObject j = oldSteps.value(s.id);
    j["id"] = s.id;
    j["name"] = QString::fromStdString(s.name);
    if (s.initial)
      j["initial"] = true;
    else
      j.remove("initial");
    QJsonArray actions;
    for (const std::string& a : s.actions) actions.append(QString::fromStdString(a));
    j["actions"] = actions;
    steps.append(j);
  }
  o["steps"] = steps;
  QJsonArray transitions;
  for (const GrafcetTransition& t : chart.transitions) {
    QJsonObject j = oldTransitions.value(t.id);
    j["id"] = t.id;
    j["from"] = idsJson(t.from);
    j["to"] = idsJson(t.to);
    j["receptivity"] = QString::fromStdString(t.receptivity);
    j["priority"] = t.priority;
    transitions.append(j);
  }
  o["transitions"] = transitions;
  return o;
}

}  // namespace mx::app
