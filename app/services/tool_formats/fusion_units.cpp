// Units of a Fusion tool and its numeric fields. Inch tools hold lengths in inches, feeds in in/min and
// surface speed in ft/min (Fusion's inch units); the project holds mm, mm/min and m/min.
#include <cmath>

#include "document/shortened_text.h"
#include "services/tool_formats/fusion_format.h"
#include "services/tool_formats/tool_library_io.h"

namespace mx::app::fusion {

namespace {

// 1 in = 25.4 mm and 1 ft = 0.3048 m exactly. Multiplying by the integer first keeps the usual inch
// fractions exact (0.375 * 254 = 95.25), so one division rounds once: 0.5 in -> 12.7 mm exactly.
constexpr double kTenthMmPerInch = 254.0;
constexpr double kTenthMmPerMm = 10.0;
constexpr double kMmPerFootPerTenth = 3048.0;  // m/min per ft/min, times 10 000
constexpr double kTenThousand = 10000.0;

const QString kUnitKey = QStringLiteral("unit");

QString fileUnitSymbol(Quantity quantity, Unit unit) {
  const bool inch = unit == Unit::Inches;
  switch (quantity) {
    case Quantity::Length:
      return inch ? "in" : "mm";
    case Quantity::Feed:
      return inch ? "in/min" : "mm/min";
    case Quantity::SurfaceSpeed:
      return inch ? "ft/min" : "m/min";
    case Quantity::Speed:
      return "rpm";
    case Quantity::Angle:
      return "deg";
    case Quantity::Count:
      return "";
  }
  return "";
}

QString withSymbol(const QString& text, const QString& symbol) {
  return symbol.isEmpty() ? text : text + ' ' + symbol;
}

// "'-3' must be in (0, 1000] mm"; for an inch tool "'-0.5' in (-12.7 mm) must be in (0, 1000] mm".
QString rangeMessage(const QJsonValue& raw, double converted, const NumberField& field, Unit unit) {
  const QString project_symbol = fileUnitSymbol(field.quantity, Unit::Millimeters);
  const QString file_symbol = fileUnitSymbol(field.quantity, unit);
  QString value = quoted(formatValue(raw));
  if (file_symbol != project_symbol)
    value = QString("%1 %2 (%3)").arg(value, file_symbol, withSymbol(formatNumber(converted), project_symbol));
  return value + ' ' + withSymbol(field.rule.mustBe(converted), project_symbol);
}

std::optional<Unit> parseUnit(const QString& text) {
  QString name = text.trimmed();
  if (name.size() >= 2 && (name.front() == '\'' || name.front() == '"') && name.back() == name.front())
    name = name.mid(1, name.size() - 2).trimmed();  // expressions quote their strings: "'inches'"
  if (name.compare("millimeters", Qt::CaseInsensitive) == 0) return Unit::Millimeters;
  if (name.compare("inches", Qt::CaseInsensitive) == 0) return Unit::Inches;
  return std::nullopt;
}

std::optional<Unit> unitAt(const QJsonValue& value, const Place& place, const QString& field) {
  if (value.isUndefined() || value.isNull()) return std::nullopt;
  const std::optional<Unit> unit = value.isString() ? parseUnit(value.toString()) : std::nullopt;
  if (!unit) fail(place, field, quoted(formatValue(value)) + " must be \"millimeters\" or \"inches\"");
  return unit;
}

}  // namespace

double toProject(double value, Quantity quantity, Unit unit) {
  if (unit == Unit::Millimeters) return value;
  switch (quantity) {
    case Quantity::Length:
    case Quantity::Feed:
      return value * kTenthMmPerInch / kTenthMmPerMm;
    case Quantity::SurfaceSpeed:
      return value * kMmPerFootPerTenth / kTenThousand;
    case Quantity::Speed:
    case Quantity::Angle:
    case Quantity::Count:
      return value;
  }
  return value;
}

double fromProject(double value, Quantity quantity, Unit unit) {
  if (unit == Unit::Millimeters) return value;
  switch (quantity) {
    case Quantity::Length:
    case Quantity::Feed:
      return value * kTenthMmPerMm / kTenthMmPerInch;
    case Quantity::SurfaceSpeed:
      return value * kTenThousand / kMmPerFootPerTenth;
    case Quantity::Speed:
    case Quantity::Angle:
    case Quantity::Count:
      return value;
  }
  return value;
}

QString unitName(Unit unit) {
  return unit == Unit::Inches ? "inches" : "millimeters";
}

void fail(const Place& place, const QString& field, const QString& what) {
  throw ToolLibraryError(toolLibraryError(place.file, place.tool, field, what));
}

Unit toolUnit(const QJsonObject& tool, const std::optional<QJsonValue>& libraryUnit, const Place& place) {
  const std::optional<Unit> own = unitAt(tool.value(kUnitKey), place, kUnitKey);
  const std::optional<Unit> expressed =
      unitAt(tool.value("expressions").toObject().value("tool_unit"), place, "expressions.tool_unit");
  if (own && expressed && *own != *expressed)
    fail(place, kUnitKey,
         QString("\"%1\" disagrees with expressions.tool_unit \"%2\"").arg(unitName(*own), unitName(*expressed)));
  if (own) return *own;
  if (expressed) return *expressed;
  if (libraryUnit) {
    if (const std::optional<Unit> shared = unitAt(*libraryUnit, {place.file, {}}, kUnitKey)) return *shared;
  }
  fail(place, kUnitKey,
       "missing (\"millimeters\" or \"inches\", in the tool, its expressions.tool_unit or the library)");
}

std::optional<double> readNumber(const QJsonObject& object, const NumberField& field, Unit unit, const Place& place,
                                 const QString& path) {
  const QJsonValue raw = object.value(field.key);
  if (raw.isUndefined() || raw.isNull()) return std::nullopt;
  if (!raw.isDouble()) fail(place, path, quoted(formatValue(raw)) + " must be a number");
  const double value = raw.toDouble();
  if (value == 0.0 && field.zero_is_unset) return std::nullopt;
  const double converted = toProject(value, field.quantity, unit);
  if (!std::isfinite(value) || !field.rule.accepts(converted))
    fail(place, path, rangeMessage(raw, converted, field, unit));
  return converted;
}

QJsonValue numberToWrite(const QJsonValue& origin, double value, const NumberField& field, Unit unit) {
  if (origin.isDouble() && toProject(origin.toDouble(), field.quantity, unit) == value) return origin;
  if (field.quantity == Quantity::Count) return QJsonValue(static_cast<qint64>(std::llround(value)));
  return QJsonValue(fromProject(value, field.quantity, unit));
}

}  // namespace mx::app::fusion
