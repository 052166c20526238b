#pragma once
// The numeric rules of the project document and the wording of its messages. Every message names
// the field path, the offending value and the allowed range, e.g.
//   "tools[0].teeth = 0: must be an integer in [1, 100]", "material.Kt_N_mm2: missing (required number > 0)".
#include <QJsonValue>
#include <QString>
#include <optional>

namespace mx::app {

struct NumberRule {
  enum class Bound { None, Open, Closed };
  Bound lower = Bound::None;
  double lo = 0.0;
  Bound upper = Bound::None;
  double hi = 0.0;
  bool integer = false;

  bool accepts(double value) const;    // finite, inside the bounds, integral when required
  QString range() const;               // "> 0", ">= 0", "in (0, 100)", "in (0, 1]", "" (any)
  QString mustBe(double value) const;  // "must be > 0", "must be an integer >= 1", ...
  QString requirement() const;         // "number > 0", "integer >= 1" (for missing fields)
};

namespace rules {
using B = NumberRule::Bound;
inline constexpr NumberRule kPositive{B::Open, 0.0, B::None, 0.0, false};
inline constexpr NumberRule kNonNegative{B::Closed, 0.0, B::None, 0.0, false};
inline constexpr NumberRule kPercent{B::Open, 0.0, B::Open, 100.0, false};   // damping_pct
inline constexpr NumberRule kFraction{B::Open, 0.0, B::Closed, 1.0, false};  // alpha, a/D
inline constexpr NumberRule kHelixDeg{B::Open, -90.0, B::Open, 90.0, false};
inline constexpr NumberRule kTorqueNm{B::Open, 0.0, B::Closed, 1e5, false};        // machine.max_torque_Nm
inline constexpr NumberRule kToolForceN{B::Open, 0.0, B::Closed, 1e7, false};      // tools[].max_force_N
inline constexpr NumberRule kCountAtLeastOne{B::Closed, 1.0, B::None, 0.0, true};  // divisions
// Teeth per cutter: every model's cost grows with the teeth, and no milling cutter has more than 100.
inline constexpr NumberRule kTeeth{B::Closed, 1.0, B::Closed, 100.0, true};
inline constexpr NumberRule kCountAtLeastZero{B::Closed, 0.0, B::None, 0.0, true};  // indices
// Physical ranges: wide enough for any machine tool, cutter and work material, narrow enough that no
// model overflows or runs without bound.
inline constexpr NumberRule kSpindlePowerW{B::Open, 0.0, B::Closed, 1e6, false};
inline constexpr NumberRule kSpindleRpm{B::Open, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kCurveSpeedRpm{B::Closed, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kCurvePowerW{B::Closed, 0.0, B::Closed, 1e6, false};
inline constexpr NumberRule kFeedMmS{B::Open, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kCuttingPressureNmm2{B::Open, 0.0, B::Closed, 1e5, false};  // Kt
inline constexpr NumberRule kForceRatio{B::Closed, 0.0, B::Closed, 10.0, false};        // Kr
inline constexpr NumberRule kAxialPressureNmm2{B::Closed, 0.0, B::Closed, 1e5, false};  // Ka
inline constexpr NumberRule kEdgeForceNmm{B::Closed, 0.0, B::Closed, 1e4, false};       // Kte, Kre, Kae
// Process damping C_i: measured values are 1e4 .. 1e7 N/m; above 1e9 the damping is unphysical.
inline constexpr NumberRule kProcessDampingNm{B::Closed, 0.0, B::Closed, 1e9, false};
inline constexpr NumberRule kFeedPerToothMm{B::Open, 0.0, B::Closed, 10.0, false};
inline constexpr NumberRule kDiameterMm{B::Open, 0.0, B::Closed, 1000.0, false};
// A mode's frequency, damping and stiffness: above 20 kHz no lobe of a milling speed range is
// resolved, and under 0.001 % damping the stability limit overflows.
inline constexpr NumberRule kModeFrequencyHz{B::Open, 0.0, B::Closed, 2e4, false};
inline constexpr NumberRule kDampingPct{B::Closed, 1e-3, B::Open, 100.0, false};
inline constexpr NumberRule kStiffnessNPerUm{B::Closed, 1e-3, B::Closed, 1e6, false};
inline constexpr NumberRule kGridSpeedRpm{B::Open, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kGridDivisions{B::Closed, 1.0, B::Closed, 1000.0, true};
inline constexpr NumberRule kGridFeedStepMm{B::Closed, 1e-4, B::Closed, 10.0, false};
inline constexpr NumberRule kDeltaPerS{B::Closed, 0.0, B::Closed, 1e4, false};  // expert.delta_per_s
// CAM geometry and cutting presets (tools[].flute_length_mm ..., tools[].cutting_data[]).
inline constexpr NumberRule kToolLengthMm{B::Open, 0.0, B::Closed, 1e4, false};
inline constexpr NumberRule kPresetSpeedRpm{B::Open, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kSurfaceSpeedMMin{B::Open, 0.0, B::Closed, 1e5, false};
inline constexpr NumberRule kPresetFeedMmMin{B::Open, 0.0, B::Closed, 1e6, false};
inline constexpr NumberRule kPresetDepthMm{B::Open, 0.0, B::Closed, 1000.0, false};
// The project's operating point (operating_point): the spindle's speed range, the presets' depths and
// the feed per tooth of the operation.
inline constexpr NumberRule kPointSpeedRpm = kSpindleRpm;
inline constexpr NumberRule kPointDepthMm = kPresetDepthMm;
inline constexpr NumberRule kPointFeedMmPerTooth = kFeedPerToothMm;
inline constexpr qsizetype kMaxCuttingPresets = 100;  // tools[].cutting_data
inline constexpr qsizetype kMaxToolTypeChars = 100;   // tools[].type
// Counts that scale every computation linearly.
inline constexpr qsizetype kMaxTools = 100;        // tools in one project
inline constexpr qsizetype kMaxModesPerAxis = 50;  // modes_x, modes_y
inline constexpr double kMaxGridCells = 1e6;       // expert grid speeds x depth divisions
inline constexpr double kMaxGridPoints = 5e6;      // ... x feeds: the Pareto study's table
// Corner radius of a tool of diameter D: [0, D/2].
inline constexpr NumberRule cornerRadius(double diameter_mm) {
  return {B::Closed, 0.0, B::Closed, diameter_mm / 2.0, false};
}
// Radial depth of a tool of diameter D: (0, D].
inline constexpr NumberRule radialDepth(double diameter_mm) {
  return {B::Open, 0.0, B::Closed, diameter_mm, false};
}
}  // namespace rules

// Shortest text that reads back as the same double ("0.1", "150", "inf", "nan").
QString formatNumber(double value);
// Compact JSON text of any value ("\"up\"", "[1, 2]", "150"), shortened (shortened_text.h).
QString formatValue(const QJsonValue& value);
// "null", "boolean", "number", "string", "array", "object".
QString jsonTypeName(const QJsonValue& value);

// "machine" + "spindle_power_W" -> "machine.spindle_power_W"; "" + "name" -> "name".
QString childPath(const QString& parent, const QString& key);
// "tools" + 1 -> "tools[1]".
QString indexPath(const QString& parent, qsizetype index);

// Throws ProjectError("PATH = VALUE: must be RANGE[ (context)]") unless rule.accepts(value).
void checkNumber(const QString& path, double value, const NumberRule& rule, const QString& context = {});

// The ranges of the process sections, worded as in their messages: "control.beta = 2: must be in [-1, 1]".
struct FieldRange {
  double lo = 0.0;
  double hi = 0.0;
  const char* text = "";  // "in (0, 1e5]": the wording of the message
  bool integer = false;
};
// The ranges of a chatter report, in the project (expert.reported_chatter[]) and on the command line
// (rank --chatter-at).
namespace chatter_report {
inline constexpr FieldRange kSpeedRpm{1e-3, 1e6, "in [0.001, 1e6]"};
inline constexpr FieldRange kDepthMm{1e-6, 1e3, "in [1e-6, 1000]"};
inline constexpr FieldRange kFrequencyHz{1e-3, 1e6, "in [0.001, 1e6]"};
}  // namespace chatter_report

// Throws ProjectError("PATH = VALUE: must be RANGE") unless value is finite, in [lo, hi] (and integral).
void checkField(const QString& path, double value, const FieldRange& range);
void checkField(const QString& path, const std::optional<double>& value, const FieldRange& range);
// "PATH is missing: must be RANGE".
[[noreturn]] void throwMissingField(const QString& path, const QString& range);
// "PATH = VALUE: must be RANGE".
[[noreturn]] void throwBadField(const QString& path, const QString& value, const QString& range);

[[noreturn]] void throwMissing(const QString& path, const QString& requirement);
[[noreturn]] void throwWrongType(const QString& path, const QString& expected, const QJsonValue& got);

}  // namespace mx::app
