#include "services/batch_manifest_json.h"

#include <QJsonArray>

namespace mx::app {

namespace {

QJsonArray arrayOf(const std::vector<QJsonObject>& sections) {
  QJsonArray out;
  for (const QJsonObject& s : sections) out.append(s);
  return out;
}

}  // namespace

QJsonObject batchManifestJson(const BatchManifest& manifest) {
  QJsonObject root{{"computation", manifest.computation}, {"projects", QJsonArray::fromStringList(manifest.projects)}};
  if (manifest.tools) root.insert("tools", QJsonArray::fromStringList(*manifest.tools));
  if (!manifest.machines.empty()) root.insert("machines", arrayOf(manifest.machines));
  if (!manifest.materials.empty()) root.insert("materials", arrayOf(manifest.materials));
  if (!manifest.operations.empty()) root.insert("operations", arrayOf(manifest.operations));
  if (!manifest.options.isEmpty()) root.insert("options", manifest.options);
  return root;
}

}  // namespace mx::app
