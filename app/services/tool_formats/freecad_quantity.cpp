#include "services/tool_formats/freecad_quantity.h"

#include <QRegularExpression>
#include <cmath>

#include "document/project_rules.h"
#include "document/shortened_text.h"

namespace mx::app {

namespace {

// No quantity is longer: a longer text is refused before any pattern runs over it.
constexpr qsizetype kMaxQuantityChars = 100;

struct LengthUnit {
  const char16_t* name;
  double mm;
};

// FreeCAD's length units (Base/Unit, Quantity parser) that tool dimensions use, and the spellings of its
// imperial schemas: "in" and '"' for inch, "thou" and "mil" for 0.001 in, "ft" and "'" for foot.
constexpr LengthUnit kLengthUnits[] = {
    {u"mm", 1.0},       {u"cm", 10.0},      {u"dm", 100.0},   {u"m", 1000.0},  {u"um", 1e-3},
    {u"\u00b5m", 1e-3}, {u"\u03bcm", 1e-3}, {u"in", 25.4},    {u"inch", 25.4}, {u"inches", 25.4},
    {u"\"", 25.4},      {u"thou", 0.0254},  {u"mil", 0.0254}, {u"ft", 304.8},  {u"'", 304.8},
};
constexpr const char16_t* kAngleUnits[] = {u"\u00b0", u"deg", u"rad", u"gon"};

std::optional<double> unitFactor(const QString& unit) {
  const QString key = unit.toLower();
  for (const LengthUnit& u : kLengthUnits)
    if (key == QString::fromUtf16(u.name)) return u.mm;
  return std::nullopt;
}

bool isAngleUnit(const QString& unit) {
  const QString key = unit.toLower();
  for (const char16_t* name : kAngleUnits)
    if (key == QString::fromUtf16(name)) return true;
  return false;
}

// "6.35", "6,35", ".5", "1e-3" or "1/4"; nullopt otherwise.
std::optional<double> parseMagnitude(QString number) {
  const qsizetype slash = number.indexOf('/');
  if (slash >= 0) {
    bool ok_n = false;
    bool ok_d = false;
    const double n = number.left(slash).trimmed().toDouble(&ok_n);
    const double d = number.mid(slash + 1).trimmed().toDouble(&ok_d);
    if (!ok_n || !ok_d || d == 0.0) return std::nullopt;
    return n / d;
  }
  number.replace(',', '.');
  bool ok = false;
  const double value = number.toDouble(&ok);
  return ok ? std::optional<double>(value) : std::nullopt;
}

LengthParse problem(const QString& text) {
  return {std::nullopt, text};
}

LengthParse parseLengthText(const QString& raw) {
  const QString text = raw.trimmed();
  if (text.size() > kMaxQuantityChars) return problem(QString("%1: not a number with a unit").arg(quoted(text)));
  static const QRegularExpression pattern(
      R"(^([+-]?(?:[0-9]+\s*/\s*[0-9]+|(?:[0-9]+(?:[.,][0-9]*)?|[.,][0-9]+)(?:[eE][+-]?[0-9]+)?))\s*(\S*)$)");
  const QRegularExpressionMatch match = pattern.match(text);
  if (!match.hasMatch()) return problem(QString("%1: not a number with a unit").arg(quoted(text)));
  const std::optional<double> magnitude = parseMagnitude(match.captured(1));
  if (!magnitude || !std::isfinite(*magnitude)) return problem(QString("%1: not a finite number").arg(quoted(text)));
  const QString unit = match.captured(2);
  if (unit.isEmpty()) return {*magnitude, {}};
  if (isAngleUnit(unit)) return problem(QString("%1 is an angle, not a length").arg(quoted(text)));
  const std::optional<double> factor = unitFactor(unit);
  if (!factor)
    return problem(QString("%1: unknown unit %2 (a length takes mm, cm, m, \u00b5m, in, \", thou or ft)")
                       .arg(quoted(text), quoted(unit)));
  return {*magnitude * *factor, {}};
}

}  // namespace

LengthParse parseFreeCadLength(const QJsonValue& value) {
  if (value.isDouble()) return {value.toDouble(), {}};
  if (value.isString()) return parseLengthText(value.toString());
  return problem(QString("%1: must be a length such as \"6.00 mm\"").arg(formatValue(value)));
}

QString freeCadLengthText(double mm) {
  return formatNumber(mm) + " mm";
}

}  // namespace mx::app
