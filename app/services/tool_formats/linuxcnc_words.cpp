#include "services/tool_formats/linuxcnc_words.h"

#include <QRegularExpression>
#include <cmath>

namespace mx::app {

double millimetresPer(TableUnits units) {
  return units == TableUnits::Inch ? 25.4 : 1.0;
}

QString unitsName(TableUnits units) {
  return units == TableUnits::Inch ? QStringLiteral("inch") : QStringLiteral("mm");
}

std::optional<TableUnits> unitsNamed(const QString& name) {
  static const QStringList metric{"mm", "millimeter", "millimeters", "millimetre", "millimetres", "metric"};
  static const QStringList imperial{"in", "inch", "inches", "imperial"};
  const QString key = name.toLower();
  if (metric.contains(key)) return TableUnits::Millimetre;
  if (imperial.contains(key)) return TableUnits::Inch;
  return std::nullopt;
}

std::optional<QString> declaredUnits(const QString& remark) {
  static const QRegularExpression pattern(QStringLiteral(R"(\bunits?\s*[:=]\s*([^\s,;.)]*))"),
                                          QRegularExpression::CaseInsensitiveOption);
  const QRegularExpressionMatch match = pattern.match(remark);
  if (!match.hasMatch()) return std::nullopt;
  return match.captured(1);
}

bool isTableLetter(QChar letter) {
  return QStringLiteral("TPXYZABCUVWDIJQ").contains(letter.toUpper());
}

bool isIntegerLetter(QChar letter) {
  return QStringLiteral("TPQ").contains(letter.toUpper());
}

bool isLengthLetter(QChar letter) {
  return QStringLiteral("XYZUVWD").contains(letter.toUpper());
}

std::optional<double> wordValue(const QString& word) {
  static const QRegularExpression real(
      QStringLiteral(R"(^[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?$)"));
  static const QRegularExpression integer(QStringLiteral(R"(^[+-]?[0-9]+$)"));
  if (word.size() < 2) return std::nullopt;
  const QString number = word.mid(1);
  const QRegularExpression& pattern = isIntegerLetter(word.at(0)) ? integer : real;
  if (!pattern.match(number).hasMatch()) return std::nullopt;
  bool ok = false;
  const double value = number.toDouble(&ok);
  if (!ok || !std::isfinite(value)) return std::nullopt;
  return value;
}

const QStringList& linuxCncCarriedKeys() {
  static const QStringList keys{
      "teeth", "type", "flute_length_mm", "overall_length_mm", "stickout_mm", "corner_radius_mm", "cutting_data"};
  return keys;
}

QStringList lineWords(const QString& words_part) {
  static const QRegularExpression separators(QStringLiteral("[ \\t]+"));
  return words_part.split(separators, Qt::SkipEmptyParts);
}

}  // namespace mx::app
