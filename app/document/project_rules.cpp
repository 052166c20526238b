#include "document/project_rules.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <cmath>

#include "document/project.h"
#include "document/shortened_text.h"

namespace mx::app {

bool NumberRule::accepts(double value) const {
  if (!std::isfinite(value)) return false;
  if (integer && value != std::floor(value)) return false;
  if (lower == Bound::Open && !(value > lo)) return false;
  if (lower == Bound::Closed && !(value >= lo)) return false;
  if (upper == Bound::Open && !(value < hi)) return false;
  if (upper == Bound::Closed && !(value <= hi)) return false;
  return true;
}

QString NumberRule::range() const {
  if (lower != Bound::None && upper != Bound::None) {
    return QString("in %1%2, %3%4")
        .arg(lower == Bound::Open ? "(" : "[", formatNumber(lo), formatNumber(hi), upper == Bound::Open ? ")" : "]");
  }
  if (lower != Bound::None) return QString(lower == Bound::Open ? "> %1" : ">= %1").arg(formatNumber(lo));
  if (upper != Bound::None) return QString(upper == Bound::Open ? "< %1" : "<= %1").arg(formatNumber(hi));
  return {};
}

QString NumberRule::mustBe(double value) const {
  const QString r = range();
  if (integer) return r.isEmpty() ? QString("must be an integer") : "must be an integer " + r;
  if (!std::isfinite(value)) return r.isEmpty() ? QString("must be a finite number") : "must be a finite number " + r;
  return r.isEmpty() ? QString("must be a finite number") : "must be " + r;
}

QString NumberRule::requirement() const {
  const QString kind = integer ? "integer" : "number";
  const QString r = range();
  return r.isEmpty() ? kind : kind + " " + r;
}

QString formatNumber(double value) {
  return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

namespace {
QString compactJson(const QJsonValue& value) {
  const QByteArray wrapped = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
  return QString::fromUtf8(wrapped.mid(1, wrapped.size() - 2));  // strip the [ ]
}
}  // namespace

QString formatValue(const QJsonValue& value) {
  if (value.isDouble()) return formatNumber(value.toDouble());
  if (value.isUndefined()) return "undefined";
  const QString text = value.toString();
  if (value.isString() && text.size() > kMaxEchoedCharacters) {  // "aaaa…" (N characters), still escaped
    QString head = compactJson(text.left(kMaxEchoedCharacters));
    head.insert(head.size() - 1, QChar(0x2026));
    return head + QString(" (%1 characters)").arg(text.size());
  }
  return shortened(compactJson(value));
}

QString jsonTypeName(const QJsonValue& value) {
  switch (value.type()) {
    case QJsonValue::Null:
      return "null";
    case QJsonValue::Bool:
      return "boolean";
    case QJsonValue::Double:
      return "number";
    case QJsonValue::String:
      return "string";
    case QJsonValue::Array:
      return "array";
    case QJsonValue::Object:
      return "object";
    case QJsonValue::Undefined:
      break;
  }
  return "nothing";
}

QString childPath(const QString& parent, const QString& key) {
  return parent.isEmpty() ? key : parent + "." + key;
}

QString indexPath(const QString& parent, qsizetype index) {
  return QString("%1[%2]").arg(parent).arg(index);
}

void checkNumber(const QString& path, double value, const NumberRule& rule, const QString& context) {
  if (rule.accepts(value)) return;
  QString message = QString("%1 = %2: %3").arg(path, formatNumber(value), rule.mustBe(value));
  if (!context.isEmpty()) message += " (" + context + ")";
  throw ProjectError(message);
}

void checkField(const QString& path, double value, const FieldRange& range) {
  const bool ok =
      std::isfinite(value) && value >= range.lo && value <= range.hi && (!range.integer || std::floor(value) == value);
  if (!ok) throwBadField(path, QString::number(value, 'g', 10), range.text);
}

void checkField(const QString& path, const std::optional<double>& value, const FieldRange& range) {
  if (value) checkField(path, *value, range);
}

void throwMissingField(const QString& path, const QString& range) {
  throw ProjectError(QString("%1 is missing: must be %2").arg(path, range));
}

void throwBadField(const QString& path, const QString& value, const QString& range) {
  throw ProjectError(QString("%1 = %2: must be %3").arg(path, value, range));
}

void throwMissing(const QString& path, const QString& requirement) {
  throw ProjectError(QString("%1: missing (required %2)").arg(path, requirement));
}

void throwWrongType(const QString& path, const QString& expected, const QJsonValue& got) {
  throw ProjectError(QString("%1: expected %2, got %3").arg(path, expected, jsonTypeName(got)));
}

}  // namespace mx::app
