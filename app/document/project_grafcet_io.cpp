#include "document/project_grafcet_io.h"

#include <QJsonArray>
#include <cmath>
#include <initializer_list>

#include "document/project.h"
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
    case QJsonValue::String:
      return "\"" + v.toString() + "\"";
    case QJsonValue::Double:
      return QString::number(v.toDouble(), 'g', 10);
    case QJsonValue::Bool:
      return v.toBool() ? "true" : "false";
    case QJsonValue::Array:
      return "(an array)";
    case QJsonValue::Object:
      return "(an object)";
    case QJsonValue::Null:
      return "null";
    default:
      return "(missing)";
  }
}

int integer(const QJsonValue& v, const QString& field) {
  const double x = v.toDouble(-1.0);
  if (!v.isDouble() || !(x >= 0.0 && x <= kMaxInteger) || std::floor(x) != x)
    throwBadField(field, shown(v), kIntegerRange);
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

// The keys of `o` beyond `known`, and which of `optionalDefaults` (key, default) the file wrote at
// that default.
GrafcetJsonKeys keysOf(const QJsonObject& o, std::initializer_list<const char*> known,
                       std::initializer_list<std::pair<const char*, QJsonValue>> optionalDefaults) {
  GrafcetJsonKeys keys;
  keys.unknown = o;
  for (const char* k : known) keys.unknown.remove(k);
  for (const auto& [key, value] : optionalDefaults)
    if (o.contains(key) && o.value(key) == value) keys.defaults_written << key;
  return keys;
}

// Writes an optional key unless it is at its default and the file did not write it there.
void putUnlessDefault(QJsonObject& o, const GrafcetJsonKeys& keys, const QString& key, const QJsonValue& value,
                      const QJsonValue& defaultValue) {
  if (value != defaultValue || keys.defaults_written.contains(key)) {
    o.insert(key, value);
  } else {
    o.remove(key);
  }
}

const GrafcetJsonKeys& keysAt(const std::vector<GrafcetJsonKeys>& keys, std::size_t index) {
  static const GrafcetJsonKeys kNone;
  return index < keys.size() ? keys[index] : kNone;
}

QJsonArray actionsJson(const std::vector<std::string>& actions) {
  QJsonArray a;
  for (const std::string& action : actions) a.append(QString::fromStdString(action));
  return a;
}

// The keys of the first element of `old` with `id`, or none.
template <typename T>
GrafcetJsonKeys keysById(const std::vector<T>& old, const std::vector<GrafcetJsonKeys>& keys, int id) {
  for (std::size_t i = 0; i < old.size(); ++i)
    if (old[i].id == id) return keysAt(keys, i);
  return {};
}

}  // namespace

GrafcetChartSpec grafcetChartFromJson(const QJsonValue& value, const QString& path) {
  const QJsonObject o = object(value, path);
  GrafcetChartSpec spec;
  GrafcetChart& c = spec.chart;
  c.name = string(o, "name", path + ".name", false).toStdString();
  spec.keys = keysOf(o, {"name", "steps", "transitions"}, {{"name", QString()}, {"transitions", QJsonArray()}});
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
      if (!actions.at(k).isString())
        throwBadField(field, shown(actions.at(k)), "a string (\"A\", or \"L*\" for an impulse)");
      step.actions.push_back(actions.at(k).toString().toStdString());
    }
    c.steps.push_back(std::move(step));
    spec.steps.push_back(
        keysOf(s, {"id", "name", "initial", "actions"}, {{"initial", false}, {"actions", QJsonArray()}}));
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
    spec.transitions.push_back(keysOf(t, {"id", "from", "to", "receptivity", "priority"}, {{"priority", 1}}));
  }
  return spec;
}

QJsonObject grafcetChartToJson(const GrafcetChartSpec& spec) {
  const GrafcetChart& chart = spec.chart;
  QJsonObject o = spec.keys.unknown;
  putUnlessDefault(o, spec.keys, "name", QString::fromStdString(chart.name), QString());
  QJsonArray steps;
  for (std::size_t i = 0; i < chart.steps.size(); ++i) {
    const GrafcetStep& s = chart.steps[i];
    const GrafcetJsonKeys& keys = keysAt(spec.steps, i);
    QJsonObject j = keys.unknown;
    j["id"] = s.id;
    j["name"] = QString::fromStdString(s.name);
    putUnlessDefault(j, keys, "initial", s.initial, false);
    putUnlessDefault(j, keys, "actions", actionsJson(s.actions), QJsonArray());
    steps.append(j);
  }
  o["steps"] = steps;
  QJsonArray transitions;
  for (std::size_t i = 0; i < chart.transitions.size(); ++i) {
    const GrafcetTransition& t = chart.transitions[i];
    const GrafcetJsonKeys& keys = keysAt(spec.transitions, i);
    QJsonObject j = keys.unknown;
    j["id"] = t.id;
    j["from"] = idsJson(t.from);
    j["to"] = idsJson(t.to);
    j["receptivity"] = QString::fromStdString(t.receptivity);
    putUnlessDefault(j, keys, "priority", t.priority, 1);
    transitions.append(j);
  }
  putUnlessDefault(o, spec.keys, "transitions", transitions, QJsonArray());
  return o;
}

GrafcetChartSpec grafcetChartSpecWith(const GrafcetChartSpec& previous, GrafcetChart chart) {
  GrafcetChartSpec spec;
  spec.keys = previous.keys;
  for (const GrafcetStep& s : chart.steps) spec.steps.push_back(keysById(previous.chart.steps, previous.steps, s.id));
  for (const GrafcetTransition& t : chart.transitions)
    spec.transitions.push_back(keysById(previous.chart.transitions, previous.transitions, t.id));
  spec.chart = std::move(chart);
  return spec;
}

QString grafcetIssuePath(const GrafcetIssue& issue, const QString& path) {
  QString at;
  switch (issue.element) {
    case GrafcetElement::Chart:
      return path + ".steps";
    case GrafcetElement::Step:
      at = elementPath(path, "steps", issue.index);
      break;
    case GrafcetElement::Transition:
      at = elementPath(path, "transitions", issue.index);
      break;
  }
  return issue.field.empty() ? at : at + "." + QString::fromStdString(issue.field);
}

QStringList grafcetChartErrors(const GrafcetChart& chart, const QString& path,
                               const std::optional<std::set<std::string>>& knownSignals) {
  const std::vector<GrafcetIssue> issues =
      knownSignals ? validateGrafcetChart(chart, *knownSignals) : validateGrafcetChart(chart);
  QStringList out;
  for (const GrafcetIssue& i : issues) out << grafcetIssuePath(i, path) + ": " + QString::fromStdString(i.message);
  return out;
}

void checkGrafcetChart(const GrafcetChart& chart, const QString& path,
                       const std::optional<std::set<std::string>>& knownSignals) {
  const QStringList errors = grafcetChartErrors(chart, path, knownSignals);
  if (!errors.isEmpty()) throw ProjectError(errors.front());
}

}  // namespace mx::app
