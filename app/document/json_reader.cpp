#include "document/json_reader.h"

#include <climits>

#include "document/project.h"

namespace mx::app {

namespace {
double numberValue(const QJsonValue& v, const QString& path) {
  if (!v.isDouble()) throwWrongType(path, "a number", v);
  return v.toDouble();
}
}  // namespace

double ObjectReader::number(const QString& key, const NumberRule& rule) const {
  if (!has(key)) throwMissing(pathOf(key), rule.requirement());
  return numberValue(value(key), pathOf(key));
}

std::optional<double> ObjectReader::optionalNumber(const QString& key) const {
  if (!has(key)) return std::nullopt;
  return numberValue(value(key), pathOf(key));
}

int ObjectReader::integer(const QString& key, const NumberRule& rule) const {
  const double v = number(key, rule);
  checkNumber(pathOf(key), v, rule);
  if (v < INT_MIN || v > INT_MAX)
    throw ProjectError(QString("%1 = %2: %3 (and fit in 32 bits)").arg(pathOf(key), formatNumber(v), rule.mustBe(v)));
  return static_cast<int>(v);
}

QString ObjectReader::string(const QString& key) const {
  if (!has(key)) throwMissing(pathOf(key), "string");
  const QJsonValue v = value(key);
  if (!v.isString()) throwWrongType(pathOf(key), "a string", v);
  return v.toString();
}

std::optional<QString> ObjectReader::optionalString(const QString& key) const {
  if (!has(key)) return std::nullopt;
  return string(key);
}

std::optional<bool> ObjectReader::optionalBool(const QString& key) const {
  if (!has(key)) return std::nullopt;
  const QJsonValue v = value(key);
  if (!v.isBool()) throwWrongType(pathOf(key), "true or false", v);
  return v.toBool();
}

std::optional<ObjectReader> ObjectReader::optionalObject(const QString& key) const {
  if (!has(key)) return std::nullopt;
  const QJsonValue v = value(key);
  if (!v.isObject()) throwWrongType(pathOf(key), "an object", v);
  return ObjectReader(v.toObject(), pathOf(key));
}

std::optional<QJsonArray> ObjectReader::optionalArray(const QString& key) const {
  if (!has(key)) return std::nullopt;
  const QJsonValue v = value(key);
  if (!v.isArray()) throwWrongType(pathOf(key), "an array", v);
  return v.toArray();
}

QJsonArray ObjectReader::array(const QString& key, const QString& requirement) const {
  if (!has(key)) throwMissing(pathOf(key), requirement);
  return *optionalArray(key);
}

std::optional<std::vector<double>> ObjectReader::optionalNumbers(const QString& key) const {
  const std::optional<QJsonArray> array = optionalArray(key);
  if (!array) return std::nullopt;
  std::vector<double> numbers;
  for (qsizetype i = 0; i < array->size(); ++i) numbers.push_back(numberValue(array->at(i), indexPath(pathOf(key), i)));
  return numbers;
}

ObjectReader elementObject(const QJsonArray& array, qsizetype index, const QString& arrayPath) {
  const QJsonValue v = array.at(index);
  if (!v.isObject()) throwWrongType(indexPath(arrayPath, index), "an object", v);
  return ObjectReader(v.toObject(), indexPath(arrayPath, index));
}

}  // namespace mx::app
