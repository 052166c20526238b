#pragma once
// Internals of the Fusion 360 library reader and writer (fusion_library.h): units, field reading with
// messages that name the Fusion field, tool types, and the mapping of one tool and of its presets.
// Key names follow Fusion's tool JSON (ISO 13399 symbols in "geometry": DC, NOF, LCF, OAL, LB, RE)
// as Autodesk's API documentation and exported libraries show them (docs/tool-libraries.md).
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <optional>
#include <vector>

#include "document/project.h"
#include "document/project_rules.h"

namespace mx::app::fusion {

// A Fusion tool's unit: its lengths (and feeds per tooth) in mm or in, feeds in mm/min or in/min,
// surface speed in m/min or ft/min.
enum class Unit { Millimeters, Inches };

// What a number measures, for its conversion to the project's unit.
enum class Quantity { Length, Feed, SurfaceSpeed, Speed, Angle, Count };

double toProject(double value, Quantity quantity, Unit unit);
double fromProject(double value, Quantity quantity, Unit unit);
QString unitName(Unit unit);  // "millimeters", "inches": the value of a tool's "unit"

// Where a message points: the file and the tool (its id, or "#3" before the id is known).
struct Place {
  QString file;
  QString tool;
};
[[noreturn]] void fail(const Place& place, const QString& field, const QString& what);

// A tool's unit: its "unit", or its expressions.tool_unit ("'inches'"), or else the library's
// (nullopt when the library names none). Throws naming the field when they disagree, when a value is
// not "millimeters" or "inches", or when none is given.
Unit toolUnit(const QJsonObject& tool, const std::optional<QJsonValue>& libraryUnit, const Place& place);

// A numeric field of a Fusion object and its rule in the project's unit.
struct NumberField {
  const char* key;
  Quantity quantity;
  NumberRule rule;
  bool zero_is_unset;  // Fusion writes 0 for a value it does not use (stepdown of a preset without one)
};
// The field's value in the project's unit; nullopt when absent, null, or 0 where 0 means unset.
// Throws naming `path` when it is not a finite number inside the rule.
std::optional<double> readNumber(const QJsonObject& object, const NumberField& field, Unit unit, const Place& place,
                                 const QString& path);
// The value to write for `value` (project unit): the origin's raw value when it reads back as exactly
// `value`, so that an unchanged field keeps its bytes, else `value` converted to the file's unit.
QJsonValue numberToWrite(const QJsonValue& origin, double value, const NumberField& field, Unit unit);

// The reason a Fusion tool type is not imported, or nullopt for a milling cutter.
std::optional<QString> skipReason(const QString& type);

// "T<post-process.number>" when the number is > 0, else the description, else the guid; nullopt when
// none is usable. Throws naming post-process.number when it is not a whole number >= 0.
std::optional<QString> toolId(const QJsonObject& tool, const Place& place);
// A name for messages and the skipped list that never throws: the id, else "#<position>".
QString toolLabel(const QJsonObject& tool, qsizetype position);

// start-values.presets -> cutting data; the presets' other keys stay in each preset's unknown.
std::vector<CuttingPresetSpec> readPresets(const QJsonObject& tool, Unit unit, const Place& place);
// The presets to write, each starting from its unknown keys; `origin` is the origin's presets array.
QJsonArray presetsToWrite(const std::vector<CuttingPresetSpec>& presets, const QJsonArray& origin, Unit unit);

// The geometry, flutes, type and cutting data of one milling cutter (no payload, not yet validated).
ToolSpec readMillingTool(const QJsonObject& tool, const QString& id, Unit unit, const Place& place);
// The Fusion record of `tool`: its origin's, with the mapped fields overwritten where they changed.
QJsonObject toolToWrite(const ToolSpec& tool);

}  // namespace mx::app::fusion
