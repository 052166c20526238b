#pragma once
// Typed, path-aware access to one JSON object of the project document. It reports missing fields
// and wrong types ("tools[0].diameter_mm: expected a number, got string"); numeric ranges are
// checked afterwards on the parsed structs (project_validation.h), except for integers, which must
// be integral before they can be stored.
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <utility>
#include <vector>

#include "document/project_rules.h"

namespace mx::app {

class ObjectReader {
 public:
  ObjectReader(QJsonObject object, QString path) : object_(std::move(object)), path_(std::move(path)) {}

  const QString& path() const { return path_; }
  const QJsonObject& object() const { return object_; }
  QString pathOf(const QString& key) const { return childPath(path_, key); }
  bool has(const QString& key) const { return object_.contains(key); }
  QJsonValue value(const QString& key) const { return object_.value(key); }

  // Required number; `rule` only words the "missing (required ...)" message.
  double number(const QString& key, const NumberRule& rule) const;
  std::optional<double> optionalNumber(const QString& key) const;
  // Required integer, checked against `rule` right away (it must be integral to be stored).
  int integer(const QString& key, const NumberRule& rule) const;
  QString string(const QString& key) const;
  std::optional<QString> optionalString(const QString& key) const;
  std::optional<bool> optionalBool(const QString& key) const;
  std::optional<ObjectReader> optionalObject(const QString& key) const;
  std::optional<QJsonArray> optionalArray(const QString& key) const;
  QJsonArray array(const QString& key, const QString& requirement) const;
  // Optional array of numbers of any length (lengths and ranges are validated later).
  std::optional<std::vector<double>> optionalNumbers(const QString& key) const;

 private:
  QJsonObject object_;
  QString path_;
};

// Element `index` of the array at `arrayPath`, which must be an object.
ObjectReader elementObject(const QJsonArray& array, qsizetype index, const QString& arrayPath);

}  // namespace mx::app
