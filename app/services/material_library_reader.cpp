// parseMaterialLibrary: the typed reading of a materials library (format "millexpert-materials",
// version 1), every value checked against the project rule of the material field it fills.
#include <QHash>
#include <QJsonDocument>
#include <QStringList>
#include <algorithm>

#include "document/json_reader.h"
#include "services/material_library.h"
#include "services/material_library_fields.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

const QStringList kIsoGroups{"P", "M", "K", "N", "S", "H"};

QString nonEmptyString(const ObjectReader& r, const QString& key) {
  QString text = r.string(key);
  if (text.trimmed().isEmpty()) throwBadField(r.pathOf(key), formatValue(text), "a non-empty string");
  return text;
}

double requiredNumber(const ObjectReader& r, const QString& key, const NumberRule& rule) {
  const double value = r.number(key, rule);
  checkNumber(r.pathOf(key), value, rule);
  return value;
}

void checkHeader(const ObjectReader& root) {
  const QString format = root.string("format");
  if (format != kMaterialLibraryFormat)
    throwBadField("format", formatValue(format), QString("\"%1\"").arg(kMaterialLibraryFormat));
  const double version = root.number("version", NumberRule{});
  if (version != kMaterialLibraryVersion)
    throwBadField("version", formatNumber(version),
                  QString("%1 (the version this build reads)").arg(kMaterialLibraryVersion));
}

MaterialSource readSource(const ObjectReader& r) {
  return {r.optionalString("cite"), r.optionalString("url"), r.optionalString("conditions"), r.optionalString("note")};
}

QMap<QString, MaterialSource> readSources(const ObjectReader& entry) {
  QMap<QString, MaterialSource> sources;
  const std::optional<ObjectReader> object = entry.optionalObject("sources");
  if (!object) return sources;
  for (const QString& key : object->object().keys()) sources.insert(key, readSource(*object->optionalObject(key)));
  return sources;
}

MaterialEntry readEntry(const ObjectReader& r) {
  MaterialEntry e;
  e.id = nonEmptyString(r, "id");
  e.name = nonEmptyString(r, "name");
  e.iso_group = r.string("iso_group");
  if (!kIsoGroups.contains(e.iso_group))
    throwBadField(r.pathOf("iso_group"), formatValue(e.iso_group), "one of P, M, K, N, S, H (ISO 513)");
  e.Kt_N_mm2 = requiredNumber(r, "Kt_N_mm2", rules::kCuttingPressureNmm2);
  e.Kr = requiredNumber(r, "Kr", rules::kForceRatio);
  for (const MaterialNumberField& f : kOptionalMaterialNumbers) {
    e.*f.member = r.optionalNumber(f.key);
    if (e.*f.member) checkNumber(r.pathOf(f.key), *(e.*f.member), f.rule);
  }
  e.sources = readSources(r);
  return e;
}

// A project names its material's entry by id, so an id may appear once.
void checkUniqueIds(const std::vector<MaterialEntry>& entries) {
  QHash<QString, qsizetype> first;
  for (qsizetype i = 0; i < qsizetype(entries.size()); ++i) {
    const QString& id = entries[std::size_t(i)].id;
    if (first.contains(id))
      throwBadField(indexPath("materials", i) + ".id", formatValue(id),
                    QString("unique (duplicate of %1.id)").arg(indexPath("materials", first.value(id))));
    first.insert(id, i);
  }
}

std::vector<MaterialEntry> readLibrary(const QJsonObject& root) {
  const ObjectReader reader(root, QString());
  checkHeader(reader);
  const QJsonArray array = reader.array("materials", "array of materials");
  std::vector<MaterialEntry> entries;
  for (qsizetype i = 0; i < array.size(); ++i) entries.push_back(readEntry(elementObject(array, i, "materials")));
  checkUniqueIds(entries);
  return entries;
}

}  // namespace

std::vector<MaterialEntry> parseMaterialLibrary(const QByteArray& bytes) {
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
  if (error.error != QJsonParseError::NoError)
    throw InputError(QString("invalid JSON at offset %1: %2").arg(error.offset).arg(error.errorString()));
  if (!document.isObject())
    throw InputError(
        QString("the top level must be a JSON object, got %1").arg(document.isArray() ? "an array" : "nothing"));
  try {
    return readLibrary(document.object());
  } catch (const ProjectError& e) {  // the document's readers name the path; here it is a library's
    throw InputError(QString::fromStdString(e.what()));
  }
}

}  // namespace mx::app
