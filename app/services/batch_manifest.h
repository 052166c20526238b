#pragma once
// The batch manifest (docs/shop-scale.md; a fixed interface): one computation over projects x tools x
// machines x materials x operations, with the single command's flags as "options".
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace mx::app {

struct BatchManifest {
  QString computation;   // "lobes", "rank", "pareto" or "point"
  QString folder;        // the manifest's folder: relative project paths resolve against it
  QStringList projects;  // as written
  std::optional<QStringList> tools;
  std::vector<QJsonObject> machines;  // each replaces the project's section; empty: the project's own
  std::vector<QJsonObject> materials;
  std::vector<QJsonObject> operations;
  QJsonObject options;  // flag name without dashes, "_" for "-": value

  // lobes and point run once per tool, so their cases are also per tool.
  bool perTool() const;
  QString projectPath(qsizetype index) const;
};

// Reads and checks the manifest file; throws InputError (exit 2) naming the field, its value and
// what is allowed.
BatchManifest readBatchManifest(const QString& path);
BatchManifest batchManifestFromJson(const QJsonObject& root, const QString& folder);

}  // namespace mx::app
