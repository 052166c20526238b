#pragma once
// Test helper: batch manifests over copies of the Rubio 2006 project (tools R1, R2) in a scratch folder.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <QTemporaryDir>
#include <algorithm>

#include "support/project_files.h"

namespace mx::test {

inline QJsonArray batchMachines() {
  return {QJsonObject{{"name", "DMU-50"}, {"spindle_power_W", 15000}, {"max_spindle_rpm", 18000}},
          QJsonObject{{"name", "Mini"}, {"spindle_power_W", 745.3}}};
}
inline QJsonArray batchMaterials() {
  return {QJsonObject{{"name", "7075"}, {"Kt_N_mm2", 700}, {"Kr", 0.3}},
          QJsonObject{{"name", "6061"}, {"Kt_N_mm2", 600}, {"Kr", 0.3}}};
}
inline QJsonArray batchOperations() {
  return {QJsonObject{{"milling", "down"}, {"radial_immersion", 0.5}, {"max_feed_per_tooth_mm", 0.15}}};
}

// The Rubio project copied into `dir` as `name` (relative paths in manifests resolve against `dir`).
inline QString copyRubio(const QTemporaryDir& dir, const QString& name = "rubio.mxproj") {
  return writeText(dir, name, readBytes(projectsPath("rubio2006-tool-selection.mxproj")));
}

// lobes over Rubio: 2 tools x 2 machines x 2 materials x 1 operation = 8 cases, a coarse speed grid.
inline QJsonObject lobesManifest() {
  return {{"computation", "lobes"},          {"projects", QJsonArray{"rubio.mxproj"}},
          {"machines", batchMachines()},     {"materials", batchMaterials()},
          {"operations", batchOperations()}, {"options", QJsonObject{{"from", 4000}, {"to", 18000}, {"step", 200}}}};
}

inline QString writeManifest(const QTemporaryDir& dir, const QJsonObject& manifest,
                             const QString& name = "manifest.json") {
  return writeText(dir, name, QJsonDocument(manifest).toJson());
}

// The non-empty lines of a results file, sorted (a set of lines, whatever order the jobs wrote them).
inline QStringList sortedLines(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
  std::sort(lines.begin(), lines.end());
  return lines;
}

inline std::vector<QJsonObject> jsonLines(const QString& path) {
  std::vector<QJsonObject> out;
  for (const QString& line : sortedLines(path)) out.push_back(QJsonDocument::fromJson(line.toUtf8()).object());
  std::sort(out.begin(), out.end(),
            [](const QJsonObject& a, const QJsonObject& b) { return a["case"].toInteger() < b["case"].toInteger(); });
  return out;
}

}  // namespace mx::test
