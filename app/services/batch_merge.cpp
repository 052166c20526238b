#include "services/batch_merge.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <map>

#include "services/batch_results.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

// What the table keeps of one case.
struct CaseRecord {
  qint64 index = 0;
  QString where;      // "FILE:LINE", for messages
  QByteArray digest;  // SHA-256 of the result and the error: two files agree when their digests do
  QString row_key;
  QJsonObject row;  // the row's head, should this case open it
  QJsonObject entry;
  QString computation;
  bool failed = false;
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

QByteArray digestOf(const QJsonObject& line) {
  const QJsonObject outcome{{"result", line.value("result")}, {"error", line.value("error")}};
  return QCryptographicHash::hash(QJsonDocument(outcome).toJson(QJsonDocument::Compact), QCryptographicHash::Sha256);
}

CaseRecord recordOf(const QJsonObject& line, const QString& where) {
  return {line.value("case").toInteger(),
          where,
          digestOf(line),
          rowKey(line),
          newRow(line),
          entryOf(line),
          computationOf(line.value("result").toObject()),
          line.contains("error")};
}

struct MergedCases {
  std::map<QString, CaseRecord> by_hash;
  qint64 duplicates = 0;
  qint64 torn_lines = 0;
};

void addLine(MergedCases& merged, const QJsonObject& line, const QString& where) {
  const QString hash = line.value("hash").toString();
  const auto found = merged.by_hash.find(hash);
  if (found == merged.by_hash.end()) {
    merged.by_hash.emplace(hash, recordOf(line, where));
    return;
  }
  ++merged.duplicates;
  if (found->second.digest != digestOf(line))
    throw ComputationError(QString("hash %1: different results in %2 and %3").arg(hash, found->second.where, where));
}

MergedCases readCases(const QStringList& paths) {
  MergedCases merged;
  for (const QString& path : paths) {
    qint64 number = 0;
    const BatchResultsScan scan = scanBatchResults(
        path, [&](const QJsonObject& line) { addLine(merged, line, QString("%1:%2").arg(path).arg(++number)); });
    if (scan.torn_last_line) ++merged.torn_lines;
  }
  return merged;
}

}  // namespace

QJsonObject mergeBatchResults(const QStringList& paths) {
  const MergedCases merged = readCases(paths);
  std::map<qint64, const CaseRecord*> by_case;  // the table in case order
  for (const auto& [hash, record] : merged.by_hash) by_case.emplace(record.index, &record);
  QString computation;
  qint64 failed = 0;
  std::map<QString, QJsonObject> rows;
  std::vector<QString> row_order;
  for (const auto& [index, record] : by_case) {
    if (record->failed) ++failed;
    if (computation.isEmpty()) computation = record->computation;
    auto [it, inserted] = rows.emplace(record->row_key, record->row);
    if (inserted) row_order.push_back(record->row_key);
    QJsonArray entries = it->second.value("entries").toArray();
    entries.append(record->entry);
    it->second.insert("entries", entries);
  }
  QJsonArray table;
  for (const QString& key : row_order) table.append(rows.at(key));
  return {{"computation", computation.isEmpty() ? QJsonValue() : QJsonValue(computation)},
          {"files", QJsonArray::fromStringList(paths)},
          {"cases", static_cast<qint64>(merged.by_hash.size())},
          {"duplicates", merged.duplicates},
          {"failed", failed},
          {"torn_lines", merged.torn_lines},
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
  for (const auto& r : summary.value("rows").toArray()) {
    const QJsonObject row = r.toObject();
    for (const auto& e : row.value("entries").toArray()) {
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
