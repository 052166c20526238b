#include "expert/admissible_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/invalid_input.h"
#include "expert/candidate_speeds.h"
#include "model/cutting_force.h"

namespace mx {

namespace {
constexpr double kEps = 1e-9;  // relative slack of the grid comparisons
constexpr std::int64_t kUnbounded = std::int64_t{1} << 40;
constexpr std::int64_t kMaxFeedsPerCell = 1000000;

// floor(x) with a relative slack, so that a grid value equal to a limit counts as inside it.
std::int64_t countUpTo(double limit, double step) {
  if (!std::isfinite(limit)) return kUnbounded;
  if (limit <= 0.0) return 0;
  return static_cast<std::int64_t>(std::floor(limit / step * (1.0 + kEps)));
}

// The peak power per (N b) [W / (rev/s m)] and the peak force per b [N/m] at depth b as lines in s_t:
// through the origin at the reference feed, or (affine) the chord between it and half of it.
struct PeakLines {
  double power_slope = 0.0, power_intercept = 0.0;
  double force_slope = 0.0, force_intercept = 0.0;
};
PeakLines peakLines(const MillingSetup& setup, double depth_m, double reference_feed_m, bool affine) {
  const PeakPerDepthFeed at = peakPerDepthFeed(setup, depth_m, reference_feed_m);
  if (!affine) return {at.power_w_per_rev_per_s, 0.0, at.force_n, 0.0};
  const double half_feed = 0.5 * reference_feed_m;
  const PeakPerDepthFeed half = peakPerDepthFeed(setup, depth_m, half_feed);
  auto chord = [&](double per_area_full, double per_area_half, double& slope, double& intercept) {
    const double full = per_area_full * reference_feed_m, at_half = per_area_half * half_feed;
    slope = (full - at_half) / half_feed;
    intercept = full - slope * reference_feed_m;
  };
  PeakLines lines;
  chord(at.power_w_per_rev_per_s, half.power_w_per_rev_per_s, lines.power_slope, lines.power_intercept);
  chord(at.force_n, half.force_n, lines.force_slope, lines.force_intercept);
  return lines;
}
}  // namespace

QConstraint ConstraintFunnel::emptiedBy() const {
  if (admissible_points > 0) return QConstraint::None;
  if (below_max_speed == 0) return QConstraint::SpindleSpeed;
  if (stable_cells == 0) return QConstraint::Stability;
  if (feeds == 0) return QConstraint::FeedPerTooth;
  if (feed_drive_points == 0) return QConstraint::FeedDrive;
  if (power_points == 0) return QConstraint::SpindlePower;
  if (force_points == 0) return QConstraint::ToolForce;
  return QConstraint::SpeedSecurity;
}

std::string describeConstraint(QConstraint c, const ExpertSettings& s) {
  std::ostringstream out;
  switch (c) {
    case QConstraint::None:
      out << "no constraint";
      break;
    case QConstraint::OutsideGrid:
      out << "the ends of the grid (speed range, first depth and feed step)";
      break;
    case QConstraint::SpindleSpeed:
      out << "the spindle speed maximum (" << s.limits.max_spindle_rev_per_s * 60.0 << " rpm, grid from "
          << s.grid.speed_from_rev_per_s * 60.0 << " rpm)";
      break;
    case QConstraint::Stability:
      out << "the margined stability lobes (Rule 1)";
      break;
    case QConstraint::FeedPerTooth:
      out << "the feed per tooth maximum (" << s.limits.max_feed_per_tooth_m * 1e3 << " mm, feed step "
          << s.grid.feed_step_m * 1e3 << " mm)";
      break;
    case QConstraint::FeedDrive:
      out << "the feed-drive maximum (" << s.limits.max_feed_velocity_m_per_s * 1e3 << " mm/s)";
      break;
    case QConstraint::SpindlePower:
      out << "the spindle power limit (" << s.limits.spindle_power_w << " W";
      if (std::isfinite(s.limits.max_spindle_torque_nm)) out << ", " << s.limits.max_spindle_torque_nm << " N m torque";
      if (!s.limits.spindle_curve.empty()) out << ", power curve of " << s.limits.spindle_curve.size() << " rows";
      out << ")";
      break;
    case QConstraint::ToolForce:
      out << "the tool force limit F_allow (" << s.limits.max_tool_force_n << " N peak resultant, Rule 3)";
      break;
    case QConstraint::SpeedSecurity:
      out << "Delta N_s > 0 (every remaining point lies on the lobe boundary)";
      break;
  }
  return out.str();
}

std::vector<double> AdmissibleGrid::lobeSpeeds(const ExpertSettings& s) {
  const StabilitySettings& st = s.stability;
  const double step = st.method == StabilityMethod::ZeroOrder ? st.lobe_step_rev_per_s : st.sdm_lobe_step_rev_per_s;
  const double from = st.lobe_range_low_factor * s.grid.speed_from_rev_per_s;
  const double to = st.lobe_range_high_factor * s.grid.speed_to_rev_per_s;
  if (!(step > 0.0 && from > 0.0 && to > from) || (to - from) / step > 2e5)
    throw InvalidInput("expert lobe grid: needs a positive step, 0 < from < to and at most 2e5 speeds");
  std::vector<double> speeds = SpeedGrid{from, to, step}.values();
  if (speeds.back() < to * (1.0 - kEps)) speeds.push_back(to);
  return speeds;
}

LobeDiagram AdmissibleGrid::computeLobes(const MillingSetup& setup, const ExpertSettings& s, const JobControl& job) {
  return mx::computeLobes(setup, lobeSpeeds(s),
                          {s.stability.method, s.stability.delta_per_s, s.stability.max_depth_m,
                           s.stability.sdm_steps_per_period, s.stability.dynamics},
                          JobControl{job.cancel, {}});
}

AdmissibleGrid::AdmissibleGrid(const MillingSetup& setup, const ExpertSettings& settings, const JobControl& job)
    : AdmissibleGrid(setup, settings, computeLobes(setup, settings, job), job) {}

AdmissibleGrid::AdmissibleGrid(const MillingSetup& setup, const ExpertSettings& settings, const LobeDiagram& lobes,
                               const JobControl& job)
    : setup_(setup), settings_(settings), lobes_(lobes), boundary_(lobes_, settings.stability.alpha) {
  build(job);
}

void AdmissibleGrid::build(const JobControl& job) {
  const ExpertGrid& g = settings_.grid;
  const MachineLimits& lim = settings_.limits;
  if (!(g.feed_step_m > 0.0) || g.depth_divisions < 1)
    throw InvalidInput("expert grid: feed step must be > 0 and depth divisions >= 1");
  const SpindlePowerCurve spindle = lim.spindlePower();
  spindle.validate();
  speeds_ = rankingSpeeds(setup_, g);
  if (!boundary_.covers(speeds_.front()) || !boundary_.covers(speeds_.back()))
    throw InvalidInput("expert grid: the lobes do not cover the speed range of the grid");
  feed_step_ = g.feed_step_m;
  const double cap = settings_.stability.max_depth_m;

  // b_min: the minimum of the margined border line over [from, to] (lobe samples and grid speeds).
  b_min_ = std::numeric_limits<double>::infinity();
  for (const double n : lobes_.speed_rev_per_s)
    if (n >= g.speed_from_rev_per_s && n <= g.speed_to_rev_per_s) b_min_ = std::min(b_min_, boundary_.depthLimit(n));
  for (double n : speeds_) b_min_ = std::min(b_min_, boundary_.depthLimit(n));
  if (!std::isfinite(b_min_)) b_min_ = cap;
  depth_step_ = b_min_ / g.depth_divisions;

  const double radial = setup_.radial_depth_m;
  const std::int64_t grid_feeds = countUpTo(lim.max_feed_per_tooth_m, feed_step_);
  funnel_ = {};
  funnel_.speeds = static_cast<std::int64_t>(speeds_.size());
  funnel_.feeds = grid_feeds >= kUnbounded ? -1 : grid_feeds;
  // The peak power per b is proportional to N (v = pi D N; the force pattern over a period does not
  // depend on N) and the peak force independent of it, so one evaluation per depth serves every speed.
  // With straight teeth one serves every depth too. Without runout and edge forces both are
  // proportional to s_t; runout and edge forces make them affine in s_t only approximately, so their line
  // is the chord between the largest feed and half of it, and each cell's largest feed is then checked
  // exactly.
  const bool straight = setup_.helix_rad == 0.0;
  const bool affine = setup_.hasRunout() || setup_.hasEdgeForces();
  const double reference_feed =
      std::isfinite(lim.max_feed_per_tooth_m) && lim.max_feed_per_tooth_m > 0.0 ? lim.max_feed_per_tooth_m : feed_step_;
  std::vector<PeakLines> peaks;  // by depth index j - 1
  auto feedsUnder = [&](double headroom, double per_feed) { return countUpTo(headroom / per_feed, feed_step_); };
  auto peakAt = [&](std::int64_t j) -> const PeakLines& {
    const auto index = static_cast<std::size_t>(straight ? 0 : j - 1);
    while (peaks.size() <= index)
      peaks.push_back(peakLines(setup_, static_cast<double>(peaks.size() + 1) * depth_step_, reference_feed, affine));
    return peaks[index];
  };
  // The lines can miss either way: the count is moved to the largest count <= most whose exact peak stays
  // within `limit` (the peak grows with s_t).
  auto exactFeeds = [&](std::int64_t estimate, std::int64_t most, double n, double b, bool power, double limit) {
    if (!affine || !std::isfinite(limit)) return estimate;
    auto fits = [&](std::int64_t count) {
      const CutPerformance perf = evaluateCut(setup_, {n, b, static_cast<double>(count) * feed_step_});
      return (power ? perf.peak_power_w : perf.peak_force_n) <= limit * (1.0 + 1e-6);
    };
    std::int64_t count = std::min(estimate, most);
    while (count > 0 && !fits(count)) --count;
    while (count < most && count < kMaxFeedsPerCell && fits(count + 1)) ++count;
    return count;
  };
  if (!(lim.max_tool_force_n > 0.0))
    throw InvalidInput("expert grid: the tool force limit must be > 0 N (+inf: no limit)");
  cells_.clear();
  max_mrr_ = 0.0;
  max_dns_ = 0.0;
  for (double n : speeds_) {
    if (job.cancelled()) throw Cancelled();
    if (n > lim.max_spindle_rev_per_s * (1.0 + kEps)) continue;
    ++funnel_.below_max_speed;
    const double b_lim = std::min(boundary_.depthLimit(n), cap);
    // depths j * step < b_lim (strictly: b = b_lim is on the boundary)
    std::int64_t depths = static_cast<std::int64_t>(std::ceil(b_lim / depth_step_ * (1.0 - kEps))) - 1;
    depths = std::max<std::int64_t>(depths, 0);
    while (depths > 0 && static_cast<double>(depths) * depth_step_ >= b_lim) --depths;
    funnel_.stable_cells += depths;
    if (grid_feeds == 0 || depths == 0) continue;
    const std::int64_t drive_feeds =
        std::min(grid_feeds, countUpTo(lim.max_feed_velocity_m_per_s / (setup_.teeth * n), feed_step_));
    const double available_power = spindle.available(n);  // P_av(N): torque-limited below the base speed
    if (drive_feeds >= kUnbounded && !std::isfinite(available_power) && !std::isfinite(lim.max_tool_force_n))
      throw InvalidInput(
          "expert grid: the feed is unbounded; set a feed per tooth maximum, a feed-drive maximum, "
          "a spindle power limit or a tool force limit");
    funnel_.feed_drive_points =
        drive_feeds >= kUnbounded ? kUnbounded : std::min(kUnbounded, funnel_.feed_drive_points + depths * drive_feeds);
    if (drive_feeds == 0) continue;
    for (std::int64_t j = 1; j <= depths; ++j) {
      const double b = static_cast<double>(j) * depth_step_;
      const PeakLines& peak = peakAt(j);
      const double power_per_feed = peak.power_slope * n * b, power_at_zero_feed = peak.power_intercept * n * b;
      const std::int64_t power_feeds =
          exactFeeds(std::min(drive_feeds, feedsUnder(available_power - power_at_zero_feed, power_per_feed)),
                     drive_feeds, n, b, true, available_power);
      if (power_feeds == 0) break;  // the power grows with b: no deeper cell fits either
      funnel_.power_points = std::min(kUnbounded, funnel_.power_points + power_feeds);
      const std::int64_t feeds = exactFeeds(
          std::min(power_feeds, feedsUnder(lim.max_tool_force_n - peak.force_intercept * b, peak.force_slope * b)),
          power_feeds, n, b, false, lim.max_tool_force_n);
      if (feeds == 0) break;  // so does the force
      if (feeds > kMaxFeedsPerCell)
        throw InvalidInput("expert grid: more than 1e6 admissible feeds per cell; raise the feed step");
      funnel_.force_points += feeds;
      const double dns = boundary_.speedSecurity(n, b);
      if (!(dns > 0.0)) continue;
      GridCell cell;
      cell.speed_rev_per_s = n;
      cell.depth_m = b;
      cell.power_per_feed = power_per_feed;
      cell.power_at_zero_feed_w = power_at_zero_feed;
      cell.available_power_w = available_power;
      cell.mrr_per_feed = radial * b * setup_.teeth * n;
      cell.speed_security = dns;
      cell.feed_count = static_cast<int>(feeds);
      cells_.push_back(cell);
      funnel_.admissible_points += feeds;
      max_mrr_ = std::max(max_mrr_, cell.mrr_per_feed * feed_step_ * feeds);
      max_dns_ = std::max(max_dns_, dns);
    }
  }
}

ExpertPoint AdmissibleGrid::point(std::size_t cell, int feed_index) const {
  const GridCell& c = cells_.at(cell);
  const double s = feed_step_ * feed_index;
  return {c.speed_rev_per_s,  c.depth_m,       s, c.power_at_zero_feed_w + c.power_per_feed * s,
          c.mrr_per_feed * s, c.speed_security};
}

QConstraint AdmissibleGrid::violation(double n, double b, double s) const {
  const MachineLimits& lim = settings_.limits;
  if (!boundary_.covers(n) || !(b > 0.0) || !(s > 0.0)) return QConstraint::OutsideGrid;
  if (n > lim.max_spindle_rev_per_s * (1.0 + kEps)) return QConstraint::SpindleSpeed;
  if (!(b < boundary_.depthLimit(n))) return QConstraint::Stability;
  if (s > lim.max_feed_per_tooth_m * (1.0 + kEps)) return QConstraint::FeedPerTooth;
  if (s * setup_.teeth * n > lim.max_feed_velocity_m_per_s * (1.0 + kEps)) return QConstraint::FeedDrive;
  const CutPerformance perf = evaluateCut(setup_, {n, b, s});
  if (!(perf.peak_power_w <= lim.spindlePower().available(n) * (1.0 + 1e-6))) return QConstraint::SpindlePower;
  if (!(perf.peak_force_n <= lim.max_tool_force_n * (1.0 + 1e-6))) return QConstraint::ToolForce;
  if (!(boundary_.speedSecurity(n, b) > 0.0)) return QConstraint::SpeedSecurity;
  return QConstraint::None;
}

bool AdmissibleGrid::isAdmissible(double n, double b, double s) const {
  return violation(n, b, s) == QConstraint::None;
}

}  // namespace mx
