#pragma once
// The end view of the selected cutter: a circle of its diameter, one mark per tooth at its angle
// (clockwise from the top, the direction of rotation), the pitch angles in degrees, the helix, and
// runout drawn as exaggerated radial offsets of the edges.
#include <QPointF>
#include <QWidget>
#include <optional>
#include <vector>

#include "display_units.h"
#include "document/project.h"

namespace mx::widgets {

struct ToothMark {
  double angle_rad = 0.0;  // toothAngleRad(j), clockwise from the top
  QPointF edge;            // the cutting edge: on the circle, moved outwards by the drawn runout
  double pitch_deg = 0.0;  // from this tooth to the next
  QPointF pitch_label;     // where that angle is written: halfway to the next tooth, inside the circle
};

// The teeth of `cutter` on a circle of `radius_px` about `centre` (screen coordinates, y down); a runout
// of r metres moves an edge r * runout_px_per_m outwards.
std::vector<ToothMark> toothMarks(const MillingSetup& cutter, QPointF centre, double radius_px, double runout_px_per_m);
// The scale that draws the largest |runout| as `max_px`; 0 without runout.
double runoutScalePxPerM(const MillingSetup& cutter, double max_px);

// The text beside the end view: the tool, D (in `units`, mm when null), its pitch, helix and runout,
// each with its unit. runout_gain: how many times larger the drawn runout is than the true one.
QStringList toolCaption(const MillingSetup& cutter, double runout_gain, const DisplayUnits* units);

class ToolPictureWidget : public QWidget {
  Q_OBJECT
 public:
  explicit ToolPictureWidget(QWidget* parent = nullptr);

  void setTool(const app::ToolSpec& tool);
  void clear();                              // no tool selected
  void setUnits(const DisplayUnits* units);  // the diameter in mm or inch; nullptr = mm
  const std::optional<MillingSetup>& cutter() const { return cutter_; }
  QSize sizeHint() const override { return {360, 180}; }
  QSize minimumSizeHint() const override { return {260, 130}; }  // the tools dock is short beside tall plots

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::optional<MillingSetup> cutter_;
  const DisplayUnits* units_ = nullptr;
};

}  // namespace mx::widgets
