#pragma once
// Stability pockets of a lobe envelope: the local peaks of b_lim(N) between neighbouring lobes, where
// a cut can go deepest at a given spindle speed (Altintas, Manufacturing Automation, sec. 3.5). The
// envelope is sampled on increasing speeds; NaN marks speeds without a finite limit.
#include <QVector>

namespace mx::widgets {

struct StabilityPocket {
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
};

// The interior local maxima of `depth_mm` over `speed_rpm`, deepest first. A peak counts when it rises
// at least `min_prominence` (a fraction of its depth) above the lower of the lowest points between it
// and the next higher envelope on either side; a plateau counts once, at its middle. The range ends are
// not pockets: the envelope may go on rising beyond them.
QVector<StabilityPocket> findStabilityPockets(const QVector<double>& speed_rpm, const QVector<double>& depth_mm,
                                              double min_prominence = 0.02);

// The envelope at `speed_rpm`, linear between samples; NaN outside the sampled range or next to a NaN.
double envelopeAt(const QVector<double>& speed_rpm, const QVector<double>& depth_mm, double speed);

}  // namespace mx::widgets
