#pragma once
// Readouts for an operating point, from the immutable lobe snapshot computed on the engine thread:
// geometry queries on the margined boundary (b_lim, Delta N_s, ROS) and the static cut (power, MRR).
// The static cut grows with the teeth, the helix slices and, for unequal teeth, a whole revolution, so
// evaluate() and powerLimitMm() run on the readout thread (PointRunner), never on the GUI thread.
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "lobe_job.h"
#include "model/spindle_power.h"
#include "point_readout.h"
#include "stability/stability_boundary.h"
#include "stability/stable_point_suggestion.h"

namespace mx::gui {

class PointEvaluator {
 public:
  PointEvaluator() = default;
  // spindle_power: P_av(N) of the machine; the default (no limit) for a project without one.
  PointEvaluator(std::shared_ptr<const LobeSnapshot> snapshot, SpindlePowerCurve spindle_power);

  bool ready() const { return snapshot_ != nullptr && !boundaries_.empty(); }
  int toolCount() const { return static_cast<int>(boundaries_.size()); }
  int toolIndex(const QString& id) const;
  widgets::PointReadout evaluate(int tool, double speed_rpm, double depth_mm, double feed_mm_per_tooth) const;
  // alpha * b_lim [mm] at the speed (a lookup on the boundary: cheap); NaN outside the lobes or without them.
  double depthLimitMm(int tool, double speed_rpm) const;
  // [lowest, highest] computed speed [rpm] of the tool's lobes ({0, 0} without them).
  std::pair<double, double> speedRangeRpm(int tool) const;
  // A chatter-free point near (speed, depth), checked on the tool's lobes (stable_point_suggestion.h);
  // nullopt without lobes for the tool or computed speeds in [0, max_speed_rpm].
  std::optional<StablePointSuggestion> suggestStablePoint(int tool, double speed_rpm, double depth_mm,
                                                          std::optional<double> chatter_hz, double max_speed_rpm) const;

  // Depth [mm] at which the peak power reaches the available power P_av(N), per speed of the snapshot:
  // the peak power is N b s_t k(b, s_t) (peakPerDepthFeed), so b k(b, s_t) = P_av(N) / (N s_t). k is one
  // number for straight teeth without runout; else b k(b) is tabulated over the chart's depths and
  // interpolated (it grows with b). Empty without a power limit.
  QVector<double> powerLimitMm(int tool, double feed_mm_per_tooth) const;

  // Each snapshot tool's allowable force F_allow [N] (Rule 3), aligned with the snapshot's tools;
  // +inf or an absent entry: no limit. Set apart from the snapshot: the limit may change without new lobes.
  void setForceLimits(std::vector<double> force_limits_n) { force_limits_n_ = std::move(force_limits_n); }

 private:
  std::shared_ptr<const LobeSnapshot> snapshot_;
  std::vector<StabilityBoundary> boundaries_;
  SpindlePowerCurve spindle_power_;
  std::vector<double> force_limits_n_;
};

}  // namespace mx::gui
