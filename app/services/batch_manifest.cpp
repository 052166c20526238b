#include "services/batch_manifest.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include "services/service_errors.h"

namespace mx::app {

namespace {

constexpr qint64 kMaxManifestBytes = 64 << 20;
constexpr qsizetype kMaxListLength = 100000;
const QStringList kComputations{"lobes", "rank", "pareto", "point"};
const QStringList kKeys{"computation", "projects", "tools", "machines", "materials", "operations", "options"};

QString shown(const QJsonValue& value) {
  if (value.isString()) return QString("'%1'").arg(value.toString());
  if (value.isDouble()) return QString::number(value.toDouble(), 'g', 12);
  if (value.isBool()) return value.toBool() ? "true" : "false";
  if (value.isNull() || value.isUndefined()) return "null";
  return value.isArray() ? "an array" : "an object";
}

// A key as a message can show it: control characters (a NUL would end the message) as \uXXXX.
QString printable(const QString& text) {
  QString out;
  for (const QChar c : text)
    out += c.isPrint() || c == ' ' ? QString(c) : QString("\\u%1").arg(c.unicode(), 4, 16, QChar('0'));
  return out;
}

[[noreturn]] void fail(const QString& field, const QJsonValue& value, const QString& allowed) {
  throw InputError(QString("%1 = %2: %3").arg(field, shown(value), allowed));
}

QJsonArray listOf(const QJsonObject& root, const QString& key, const QString& items) {
  const QJsonValue value = root.value(key);
  if (!value.isArray()) fail(key, value, QString("must be an array of %1").arg(items));
  QJsonArray array = value.toArray();
  if (array.isEmpty() || array.size() > kMaxListLength)
    fail(key, value, QString("must hold 1 to %1 %2, holds %3").arg(kMaxListLength).arg(items).arg(array.size()));
  return array;
}

QStringList distinctNames(const QJsonObject& root, const QString& key) {
  QStringList names;
  QSet<QString> seen;
  const QJsonArray array = listOf(root, key, "non-empty strings");
  for (qsizetype i = 0; i < array.size(); ++i) {
    const QString field = QString("%1[%2]").arg(key).arg(i);
    if (!array[i].isString() || array[i].toString().isEmpty()) fail(field, array[i], "must be a non-empty string");
    if (seen.contains(array[i].toString())) fail(field, array[i], QString("appears twice in %1").arg(key));
    seen.insert(array[i].toString());
    names.append(array[i].toString());
  }
  return names;
}

std::vector<QJsonObject> sectionList(const QJsonObject& root, const QString& key) {
  std::vector<QJsonObject> out;
  if (!root.contains(key)) return out;
  const QJsonArray array = listOf(root, key, "objects");
  for (qsizetype i = 0; i < array.size(); ++i) {
    if (!array[i].isObject()) fail(QString("%1[%2]").arg(key).arg(i), array[i], "must be an object");
    out.push_back(array[i].toObject());
  }
  return out;
}

void checkOptionValue(const QString& name, const QJsonValue& value) {
  const QString field = QString("options.%1").arg(name);
  const auto scalar = [](const QJsonValue& v) { return v.isString() || v.isDouble() || v.isBool(); };
  if (scalar(value)) return;
  if (!value.isArray() || value.toArray().isEmpty())
    fail(field, value, "must be a string, a number, true/false, or a non-empty array of strings and numbers");
  for (const auto& item : value.toArray())
    if (!item.isString() && !item.isDouble()) fail(field + "[]", item, "must be a string or a number");
}

QJsonObject optionsOf(const QJsonObject& root) {
  if (!root.contains("options")) return {};
  const QJsonValue value = root.value("options");
  if (!value.isObject()) fail("options", value, "must be an object of flag names and values");
  QJsonObject options = value.toObject();
  for (auto it = options.begin(); it != options.end(); ++it) {
    if (it.key().isEmpty() || it.key().contains('-') || it.key().startsWith('_'))
      fail(QString("options.%1").arg(it.key()), it.value(),
           "a flag name is written without dashes and with '_' for '-' (\"no_simulation\")");
    checkOptionValue(it.key(), it.value());
  }
  return options;
}

}  // namespace

bool BatchManifest::perTool() const {
  return computation == "lobes" || computation == "point";
}

QString BatchManifest::projectPath(qsizetype index) const {
  return QDir::cleanPath(QDir(folder).absoluteFilePath(projects[index]));
}

BatchManifest batchManifestFromJson(const QJsonObject& root, const QString& folder) {
  for (auto it = root.begin(); it != root.end(); ++it)
    if (!kKeys.contains(it.key()))
      fail(printable(it.key()), it.value(), QString("unknown key; allowed: %1").arg(kKeys.join(", ")));
  BatchManifest m;
  m.folder = folder;
  const QJsonValue computation = root.value("computation");
  if (!kComputations.contains(computation.toString()))
    fail("computation", computation, QString("must be one of %1").arg(kComputations.join(", ")));
  m.computation = computation.toString();
  m.projects = distinctNames(root, "projects");
  if (root.contains("tools")) m.tools = distinctNames(root, "tools");
  m.machines = sectionList(root, "machines");
  m.materials = sectionList(root, "materials");
  m.operations = sectionList(root, "operations");
  m.options = optionsOf(root);
  return m;
}

BatchManifest readBatchManifest(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) throw InputError(QString("%1: cannot read the manifest").arg(path));
  if (file.size() > kMaxManifestBytes)
    throw InputError(
        QString("%1: %2 bytes; a manifest has at most %3").arg(path).arg(file.size()).arg(kMaxManifestBytes));
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &error);
  if (error.error != QJsonParseError::NoError)
    throw InputError(QString("%1: not JSON at byte %2: %3").arg(path).arg(error.offset).arg(error.errorString()));
  if (!document.isObject()) throw InputError(QString("%1: the top level must be a JSON object").arg(path));
  try {
    return batchManifestFromJson(document.object(), QFileInfo(path).absolutePath());
  } catch (const InputError& e) {
    throw InputError(QString("%1: %2").arg(path, QString::fromStdString(e.what())));
  }
}

}  // namespace mx::app
