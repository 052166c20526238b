#pragma once
// The cutter geometry of a tool (helix_deg, pitch_deg, runout_um): the rules its per-tooth lists obey,
// worded once for the project file, the tool-library CSV and the tool editor, and its SI form.
#include <QString>
#include <vector>

#include "document/project.h"
#include "document/project_rules.h"

namespace mx::app {

inline constexpr double kPitchSumToleranceDeg = 1e-6;  // the pitch angles sum to 360 within this

namespace rules {
inline constexpr NumberRule kPitchDeg{B::Open, 0.0, B::Open, 360.0, false};
// A runout offset of a tool of diameter D [mm], in um: |value| < D / 4.
inline constexpr NumberRule runoutUm(double diameter_mm) {
  return {B::Open, -250.0 * diameter_mm, B::Open, 250.0 * diameter_mm, false};
}
}  // namespace rules

// The rule a per-tooth list breaks: `index` >= 0 for one value, -1 for the list as a whole (its length
// or its sum); an empty `rule` when the list is valid.
struct ToothListIssue {
  int index = -1;
  QString rule;  // "must be in (0, 360)", "must have one value per tooth (teeth = 4), got 3"
  bool ok() const { return rule.isEmpty(); }
};

ToothListIssue pitchIssue(const std::vector<double>& pitch_deg, int teeth);
ToothListIssue runoutIssue(const std::vector<double>& runout_um, int teeth, double diameter_mm);

// "[70, 110, 70]": a list as the messages quote it.
QString formatNumberList(const std::vector<double>& values);

// Throws ProjectError naming the field path, the value and the rule, e.g.
// "tools[1].pitch_deg[2] = 0: must be in (0, 360)" or "tools[1].pitch_deg = [90, 90]: must have ...".
void validateToolGeometry(const QString& toolPath, const ToolSpec& tool);

// The tool's teeth, diameter and cutter geometry in SI (the other fields of the setup are left default).
MillingSetup cutterGeometryOf(const ToolSpec& tool);

}  // namespace mx::app
