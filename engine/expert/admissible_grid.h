#pragma once
// The admissible cutting-parameter space Q of one tool on the expert grid (2006, Rules 1-2; Pareto
// paper, Rules 5-7): every (N, b, s_t) of the grid with
//   b < alpha * b_lim,delta(N) and Delta N_s(N, b) > 0   (Rule 1; a zero Delta N_s is on the boundary),
//   N <= spindle maximum, s_t <= feed per tooth maximum, s_t n_t N <= feed-drive maximum,
//   peak cutting power P(N, b, s_t) <= available spindle power P_av(N) (Pareto eq. 8; torque-limited
//   below the spindle's base speed, MachineLimits::spindlePower()),
//   peak resultant force |F|(b, s_t) <= the tool's allowable force F_allow (Pareto Rules 3 and 7.1).
// At a given (N, b) the power and the MRR are proportional to s_t, and the admissible feeds are
// feed_step * (1 .. feed_count). So Q is stored as cells (N, b) with their power and MRR per unit feed,
// Delta N_s and feed count: a weight change only needs a pass over these arrays (ExpertSession).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/cancellation.h"
#include "expert/expert_settings.h"
#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"
#include "stability/stability_boundary.h"

namespace mx {

struct GridCell {
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  double power_per_feed = 0.0;        // peak power [W] per metre of feed per tooth ...
  double power_at_zero_feed_w = 0.0;  // ... plus this (edge forces, runout): P = p0 + p1 s_t
  double available_power_w = std::numeric_limits<double>::infinity();  // P_av at this speed
  double mrr_per_feed = 0.0;    // MRR [m^3/s] per metre of feed per tooth: a b n_t N
  double speed_security = 0.0;  // Delta N_s [rev/s], > 0
  int feed_count = 0;           // admissible feeds: i * feed_step, i = 1 .. feed_count
};

// A point of Q with its cost-function inputs. SI.
struct ExpertPoint {
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  double feed_per_tooth_m = 0.0;
  double power_w = 0.0;
  double mrr_m3_per_s = 0.0;
  double speed_security = 0.0;  // Delta N_s [rev/s]
};

// The constraints in the order they are applied; the first one after which no grid point is left is
// the one that emptied Q.
enum class QConstraint {
  None,
  SpindleSpeed,
  Stability,
  FeedPerTooth,
  FeedDrive,
  SpindlePower,
  ToolForce,
  SpeedSecurity,
  OutsideGrid  // outside the lobes' speed range or a non-positive depth or feed (violation() only)
};

struct ConstraintFunnel {
  std::int64_t speeds = 0;           // grid speeds
  std::int64_t below_max_speed = 0;  // speeds <= spindle maximum
  std::int64_t stable_cells = 0;     // (N, b) under the margined lobes
  std::int64_t feeds = 0;            // grid feeds <= feed per tooth maximum (-1: unbounded)
  std::int64_t feed_drive_points = 0;
  std::int64_t power_points = 0;
  std::int64_t force_points = 0;
  std::int64_t admissible_points = 0;  // also Delta N_s > 0

  QConstraint emptiedBy() const;
};

// Human-readable name of a constraint with its limit, e.g. "the spindle power limit (745.3 W)".
std::string describeConstraint(QConstraint constraint, const ExpertSettings& settings);

class AdmissibleGrid {
 public:
  // Computes the lobes (ZOA or SDM per settings.stability) over the extended speed range. Polls
  // job.cancelled() in the lobes and once per grid speed (throws Cancelled).
  AdmissibleGrid(const MillingSetup& setup, const ExpertSettings& settings, const JobControl& job = {});
  // With lobes already computed (their speed range must cover the grid's).
  AdmissibleGrid(const MillingSetup& setup, const ExpertSettings& settings, const LobeDiagram& lobes,
                 const JobControl& job = {});

  const MillingSetup& setup() const { return setup_; }
  const ExpertSettings& settings() const { return settings_; }
  const LobeDiagram& lobes() const { return lobes_; }
  const StabilityBoundary& boundary() const { return boundary_; }
  const std::vector<double>& speeds() const { return speeds_; }
  const std::vector<GridCell>& cells() const { return cells_; }
  const ConstraintFunnel& funnel() const { return funnel_; }
  bool empty() const { return cells_.empty(); }

  double minimumBorderDepth() const { return b_min_; }  // b_min over [from, to] (alpha applied)
  double depthStep() const { return depth_step_; }      // b_min / depth_divisions
  double feedStep() const { return feed_step_; }
  std::int64_t pointCount() const { return funnel_.admissible_points; }
  double maxMrr() const { return max_mrr_; }            // over Q
  double maxSpeedSecurity() const { return max_dns_; }  // over Q

  ExpertPoint point(std::size_t cell, int feed_index) const;  // feed_index in 1 .. feed_count

  // Independent re-check of every constraint of Q at an arbitrary point (tests, reports).
  bool isAdmissible(double speed_rev_per_s, double depth_m, double feed_per_tooth_m) const;
  // The first constraint (funnel order, Delta N_s last) that excludes the point; None when admissible.
  QConstraint violation(double speed_rev_per_s, double depth_m, double feed_per_tooth_m) const;

  // Lobe speeds used for a settings/grid pair: [low_factor * from, high_factor * to] by the lobe step.
  static std::vector<double> lobeSpeeds(const ExpertSettings& settings);
  static LobeDiagram computeLobes(const MillingSetup& setup, const ExpertSettings& settings,
                                  const JobControl& job = {});

 private:
  void build(const JobControl& job);

  MillingSetup setup_;
  ExpertSettings settings_;
  LobeDiagram lobes_;
  StabilityBoundary boundary_;
  std::vector<double> speeds_;
  std::vector<GridCell> cells_;
  ConstraintFunnel funnel_;
  double b_min_ = 0.0;
  double depth_step_ = 0.0;
  double feed_step_ = 0.0;
  double max_mrr_ = 0.0;
  double max_dns_ = 0.0;
};

}  // namespace mx
