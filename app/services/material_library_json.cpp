#include "services/material_library_json.h"

#include <QJsonDocument>

#include "services/material_library_fields.h"

namespace mx::app {

namespace {

void putText(QJsonObject& o, const char* key, const std::optional<QString>& text) {
  if (text) o.insert(key, *text);
}

QJsonObject sourceJson(const MaterialSource& s) {
  QJsonObject o;
  putText(o, "cite", s.cite);
  putText(o, "url", s.url);
  putText(o, "conditions", s.conditions);
  putText(o, "note", s.note);
  return o;
}

}  // namespace

QJsonObject materialEntryJson(const MaterialEntry& entry) {
  QJsonObject o{{"id", entry.id},
                {"name", entry.name},
                {"iso_group", entry.iso_group},
                {"Kt_N_mm2", entry.Kt_N_mm2},
                {"Kr", entry.Kr}};
  for (const MaterialNumberField& f : kOptionalMaterialNumbers)
    if (const std::optional<double>& v = entry.*f.member) o.insert(f.key, *v);
  QJsonObject sources;
  for (auto it = entry.sources.begin(); it != entry.sources.end(); ++it) sources.insert(it.key(), sourceJson(*it));
  o.insert("sources", sources);
  return o;
}

QJsonArray materialEntriesJson(const std::vector<MaterialEntry>& entries) {
  QJsonArray array;
  for (const MaterialEntry& e : entries) array.append(materialEntryJson(e));
  return array;
}

QByteArray materialLibraryJson(const std::vector<MaterialEntry>& entries) {
  const QJsonObject root{{"format", kMaterialLibraryFormat},
                         {"version", kMaterialLibraryVersion},
                         {"materials", materialEntriesJson(entries)}};
  return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

}  // namespace mx::app
