#pragma once
// FreeCAD quantities as its tool bits store them (Path/Tool/toolbit/util.py quantity_to_str): a number,
// then a unit, "6.000 mm", "0.2500 in", "0.25\"", "45.00°". Only lengths are read: every geometry value
// MillExpert maps from a bit is one. A bare number is in mm, FreeCAD's internal length unit.
#include <QJsonValue>
#include <QString>
#include <optional>

namespace mx::app {

// The length in mm, or why the value is not one: "unknown unit 'parsec' (a length takes mm, cm, m, µm,
// in, \" or thou)", "45 ° is an angle, not a length", "not a number with a unit". Accepts a JSON number
// or a string; the decimal mark may be a comma (older FreeCAD wrote the user's locale).
struct LengthParse {
  std::optional<double> mm;
  QString problem;
};
LengthParse parseFreeCadLength(const QJsonValue& value);

// "6.35 mm": the shortest text that reads back as the same double.
QString freeCadLengthText(double mm);

}  // namespace mx::app
