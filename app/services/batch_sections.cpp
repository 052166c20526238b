#include "services/batch_sections.h"

#include <QJsonArray>
#include <QJsonDocument>

#include "services/service_errors.h"

namespace mx::app {

namespace {

QString compactText(const QJsonValue& value) {
  const QByteArray array = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
  return QString::fromUtf8(array.mid(1, array.size() - 2));
}

// A project of one section only: what projectFromJson needs to check that section alone.
Project projectWithSection(const QString& section, const QJsonObject& object) {
  return projectFromJson(QJsonObject{{"format", "millexpert-project"},
                                     {"version", 1},
                                     {"name", "batch manifest"},
                                     {"tools", QJsonArray{}},
                                     {section, object}});
}

// The section's keys that the project file does not know (projectFromJson keeps them aside).
QStringList unknownKeysOf(const QString& section, const QJsonObject& object, Project parsed) {
  parsed.document = {};
  const QJsonObject known = projectToJson(parsed).value(section).toObject();
  QStringList unknown;
  for (auto it = object.begin(); it != object.end(); ++it)
    if (!known.contains(it.key())) unknown.append(it.key());
  return unknown;
}

// `list[i]` parsed as the project's `section`; errors name the manifest field.
Project parseSection(const QString& list, qsizetype i, const QString& section, const QJsonObject& object) {
  const QString field = QString("%1[%2]").arg(list).arg(i);
  Project parsed;
  try {
    parsed = projectWithSection(section, object);
  } catch (const ProjectError& e) {
    QString message = QString::fromStdString(e.what());
    if (message.startsWith(section)) message.replace(0, section.size(), field);
    throw InputError(message.startsWith(field) ? message : QString("%1: %2").arg(field, message));
  }
  const QStringList unknown = unknownKeysOf(section, object, parsed);
  if (!unknown.isEmpty())
    throw InputError(QString("%1.%2 = %3: not a key of the project's %4 section (docs/project-file.md)")
                         .arg(field, unknown.front(), compactText(object.value(unknown.front())), section));
  return parsed;
}

}  // namespace

BatchSections readBatchSections(const BatchManifest& manifest) {
  BatchSections s;
  for (std::size_t i = 0; i < manifest.machines.size(); ++i)
    s.machines.push_back(*parseSection("machines", static_cast<qsizetype>(i), "machine", manifest.machines[i]).machine);
  for (std::size_t i = 0; i < manifest.materials.size(); ++i)
    s.materials.push_back(
        *parseSection("materials", static_cast<qsizetype>(i), "material", manifest.materials[i]).material);
  for (std::size_t i = 0; i < manifest.operations.size(); ++i)
    s.operations.push_back(
        *parseSection("operations", static_cast<qsizetype>(i), "operation", manifest.operations[i]).operation);
  return s;
}

}  // namespace mx::app
