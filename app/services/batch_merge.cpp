#include "services/batch_merge.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <map>

#include "services/service_errors.h"

namespace mx::app {

namespace {

struct Placed {
  QJsonObject line;
  QString where;  // "FILE:LINE"
};

QString compact(const QJsonValue& value) {
  if (value.isObject()) return QString::fromUtf8(QJsonDocument(value.toObject()).toJson(QJsonDocument::Compact));
  if (value.isArray()) return QString::fromUtf8(QJsonDocument(value.toArray()).toJson(QJsonDocument::Compact));
  return value.isString() ? value.toString() : QString();
}

QString computationOf(const QJsonObject& result) {
  if (result.contains("selected")) return "rank";
  if (result.contains("pareto_set")) return "pareto";
  if (result.contains("verdict")) return "point";
  if (result.contains("minima")) return "lobes";
  return {};
}

// The highest b_lim of the envelope; null b_lim (no chatter below the depth cap) is the highest of all.
QJsonObject bestPocket(const QJsonObject& lobes) {
  const QJsonArray speeds = lobes.value("speed_rpm").toArray(), blim = lobes.value("blim_mm").toArray();
  qsizetype best = -1;
  for (qsizetype i = 0; i < blim.size() && i < speeds.size(); ++i) {
    if (best >= 0 && blim[best].isNull()) break;
    if (best < 0 || blim[i].isNull() || blim[i].toDouble() > blim[best].toDouble()) best = i;
  }
  if (best < 0) return {{"speed_rpm", QJsonValue()}, {"blim_mm", QJsonValue()}};
  return {{"speed_rpm", speeds[best]}, {"blim_mm", blim[best]}};
}

// What a row shows of one case.
QJsonObject entryOf(const QJsonObject& line) {
  const QJsonObject result = line.value("result").toObject();
  QJsonObject entry{{"case", line.value("case")}};
  if (line.contains("error")) entry.insert("error", line.value("error"));
  if (line.value("result").isNull()) return entry;
  const QString kind = computationOf(result);
  if (kind == "rank") {
    entry.insert("tool", result.value("selected"));
    entry.insert("q", result.value("q_star"));
  } else if (kind == "pareto") {
    entry.insert("tool", result.value("tool"));
    entry.insert("q", result.value("q"));
  } else if (kind == "lobes") {
    entry.insert("tool", result.value("tool"));
    entry.insert("pocket", bestPocket(result));
  } else if (kind == "point") {
    entry.insert("tool", result.value("tool"));
    entry.insert("q", QJsonObject{{"speed_rpm", result.value("speed_rpm")},
                                  {"depth_mm", result.value("depth_mm")},
                                  {"feed_mm_per_tooth", result.value("feed_per_tooth_mm")}});
    entry.insert("verdict", result.value("verdict"));
    entry.insert("stable", result.value("stable"));
  }
  return entry;
}

std::map<QString, Placed> uniqueCases(const std::vector<BatchResultsInput>& inputs, qint64& duplicates) {
  std::map<QString, Placed> unique;
  for (const BatchResultsInput& input : inputs)
    for (std::size_t i = 0; i < input.read.lines.size(); ++i) {
      const QJsonObject& line = input.read.lines[i];
      const QString where = QString("%1:%2").arg(input.path).arg(i + 1);
      const auto [it, inserted] = unique.emplace(line.value("hash").toString(), Placed{line, where});
      if (inserted) continue;
      ++duplicates;
      if (it->second.line.value("result") != line.value("result") ||
          it->second.line.value("error") != line.value("error"))
        throw ComputationError(
            QString("hash %1: different results in %2 and %3").arg(it->first, it->second.where, where));
    }
  return unique;
}

QString rowKey(const QJsonObject& line) {
  return compact(line.value("project")) + '\x1f' + compact(line.value("machine")) + '\x1f' +
         compact(line.value("material")) + '\x1f' + compact(line.value("operation"));
}

QJsonObject newRow(const QJsonObject& line) {
  const QJsonObject machine = line.value("machine").toObject(), material = line.value("material").toObject();
  return {{"project", line.value("project")},
          {"machine", machine.value("name").isString() ? machine.value("name") : QJsonValue()},
          {"material", material.value("name").isString() ? material.value("name") : QJsonValue()},
          {"operation", line.value("operation")},
          {"first_case", line.value("case")},
          {"entries", QJsonArray{}}};
}

}  // namespace

QJsonObject mergeBatchResults(const std::vector<BatchResultsInput>& inputs) {
  qint64 duplicates = 0, failed = 0, torn = 0;
  const std::map<QString, Placed> unique = uniqueCases(inputs, duplicates);
  std::map<qint64, QJsonObject> by_case;  // the table in case order
  for (const auto& [hash, placed] : unique) by_case.emplace(placed.line.value("case").toInteger(), placed.line);
  QString computation;
  std::map<QString, QJsonObject> rows;
  std::map<qint64, QString> row_order;
  for (const auto& [index, line] : by_case) {
    if (line.contains("error")) ++failed;
    if (computation.isEmpty()) computation = computationOf(line.value("result").toObject());
    const QString key = rowKey(line);
    auto [it, inserted] = rows.emplace(key, newRow(line));
    if (inserted) row_order.emplace(index, key);
    QJsonArray entries = it->second.value("entries").toArray();
    entries.append(entryOf(line));
    it->second.insert("entries", entries);
  }
  QJsonArray table, files;
  for (const auto& [index, key] : row_order) table.append(rows.at(key));
  for (const BatchResultsInput& input : inputs) {
    files.append(input.path);
    if (input.read.torn_last_line) ++torn;
  }
  return {{"computation", computation.isEmpty() ? QJsonValue() : QJsonValue(computation)},
          {"files", files},
          {"cases", static_cast<qint64>(unique.size())},
          {"duplicates", duplicates},
          {"failed", failed},
          {"torn_lines", torn},
          {"rows", table}};
}

QStringList batchTableHeader() {
  return {"project",   "machine",  "material",          "operation", "case",    "tool",
          "speed_rpm", "depth_mm", "feed_mm_per_tooth", "blim_mm",   "verdict", "error"};
}

std::vector<QStringList> batchTableLines(const QJsonObject& summary) {
  const auto number = [](const QJsonValue& v) {
    return v.isDouble() ? QString::number(v.toDouble(), 'g', 12) : QString();
  };
  std::vector<QStringList> lines;
  for (const QJsonValue& r : summary.value("rows").toArray()) {
    const QJsonObject row = r.toObject();
    for (const QJsonValue& e : row.value("entries").toArray()) {
      const QJsonObject entry = e.toObject(), q = entry.value("q").toObject(),
                        pocket = entry.value("pocket").toObject();
      const QJsonValue speed = entry.contains("pocket") ? pocket.value("speed_rpm") : q.value("speed_rpm");
      lines.push_back({compact(row.value("project")), compact(row.value("machine")), compact(row.value("material")),
                       compact(row.value("operation")), number(entry.value("case")), compact(entry.value("tool")),
                       number(speed), number(q.value("depth_mm")), number(q.value("feed_mm_per_tooth")),
                       number(pocket.value("blim_mm")), compact(entry.value("verdict")),
                       entry.value("error").toObject().value("message").toString()});
    }
  }
  return lines;
}

}  // namespace mx::app
