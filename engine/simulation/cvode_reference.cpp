#include "simulation/cvode_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/invalid_input.h"
#include "model/axial_slices.h"
#include "model/cutting_force.h"
#include "simulation/cutter_edges.h"
#include "simulation/cvode_integrator.h"
#include "simulation/time_domain_simulator.h"

namespace mx {

namespace {

void require(bool ok, const char* quantity, double value, const char* range) {
  if (ok) return;
  std::ostringstream message;
  message << "simulateMillingCvode: " << quantity << " = " << value << " is outside the allowed range " << range;
  throw InvalidInput(message.str());
}

struct ModeCoefficients {
  bool x_axis;
  double two_zeta_w, w2, gain;  // q'' = gain F - two_zeta_w q' - w2 q
};

// The model of eq. 1-7 for CVODE: modal equations, delayed state from the output history.
class ReferenceModel {
 public:
  ReferenceModel(const MillingSetup& setup, const OperatingPoint& point, double sample_dt, int passes, int slices)
      : setup_(setup),
        point_(point),
        h_(sample_dt),
        delay_(point.toothPeriodS(setup.teeth)),
        edges_(cutterEdges(setup, point.axial_depth_m, slices)),
        passes_(toothPasses(setup, point.feed_per_tooth_m, passes)),
        xd_(passes_.feed_m.size()),
        yd_(passes_.feed_m.size()) {
    for (const Mode& mode : setup.modes_x) add(mode, true);
    for (const Mode& mode : setup.modes_y) add(mode, false);
  }

  int size() const { return 2 * static_cast<int>(modes_.size()); }
  const std::vector<ModeCoefficients>& modes() const { return modes_; }

  void axes(const double* s, double& x, double& y, double& vx, double& vy) const {
    x = y = vx = vy = 0.0;
    const std::size_t m = modes_.size();
    for (std::size_t r = 0; r < m; ++r) (modes_[r].x_axis ? x : y) += s[r];
    for (std::size_t r = 0; r < m; ++r) (modes_[r].x_axis ? vx : vy) += s[m + r];
  }

  void store(const double* s) {
    double x, y, vx, vy;
    axes(s, x, y, vx, vy);
    hx_.push_back(x);
    hy_.push_back(y);
    hvx_.push_back(vx);
    hvy_.push_back(vy);
  }

  // r(t - p T) (p tooth periods) by cubic Hermite interpolation of the stored output (zero before t = 0:
  // rigid pre-history).
  void delayed(double t, double periods, double& x, double& y) const {
    const double td = t - periods * delay_;
    x = y = 0.0;
    if (td <= 0.0 || hx_.empty()) return;
    const auto last = static_cast<long>(hx_.size()) - 1;
    const long i = std::min(static_cast<long>(std::floor(td / h_)), std::max(0L, last - 1));
    const double s = td / h_ - static_cast<double>(i);
    const auto a = static_cast<std::size_t>(i);
    const std::size_t b = std::min<std::size_t>(a + 1, static_cast<std::size_t>(last));
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    x = h00 * hx_[a] + h10 * h_ * hvx_[a] + h01 * hx_[b] + h11 * h_ * hvx_[b];
    y = h00 * hy_[a] + h10 * h_ * hvy_[a] + h01 * hy_[b] + h11 * h_ * hvy_[b];
  }

  // Summed edge forces at time t (eq. 2-3, 7 with each tooth's delays, feeds and runout terms of
  // cutter_edges.h; the chip is the minimum over the remembered passes), straight from mx::toothForce, and
  // the process damping -(C_i / V) b_e (n . v) n of each cutting edge, n = (sin phi, cos phi).
  StaticForce force(double t, const double* s) const {
    double x, y, vx, vy;
    axes(s, x, y, vx, vy);
    for (std::size_t i = 0; i < xd_.size(); ++i) delayed(t, passes_.delay_tooth_periods[i], xd_[i], yd_[i]);
    const double theta = 2.0 * std::numbers::pi * point_.spindle_rev_per_s * t;
    const double damping = setup_.processDampingPerDepth(point_.spindle_rev_per_s) * point_.axial_depth_m;
    StaticForce total;
    for (const CutterEdge& edge : edges_) {
      const double phi = theta + edge.angle_rad;
      const double sn = std::sin(phi), cs = std::cos(phi);
      const std::size_t first = passes_.index(edge.pass_set, 0);
      auto chipOfPass = [&](std::size_t i) {
        return passes_.feed_m[i] * sn + (x - xd_[i]) * sn + (y - yd_[i]) * cs + passes_.runout_m[i];
      };
      double chip = chipOfPass(first);
      for (int k = 1; k < passes_.passes; ++k) chip = std::min(chip, chipOfPass(first + static_cast<std::size_t>(k)));
      const ToothForce f = toothForce(setup_, point_.axial_depth_m * edge.depth_fraction, phi, chip);
      total.tangential_sum_n += f.tangential_n;
      const bool cutting = chip > 0.0 && setup_.immersion.contains(phi);
      const double pushed = cutting ? damping * edge.depth_fraction * (sn * vx + cs * vy) : 0.0;
      total.fx_n += f.fx_n - pushed * sn;
      total.fy_n += f.fy_n - pushed * cs;
    }
    return total;
  }

  void rhs(double t, const double* s, double* ds) const {
    const StaticForce f = force(t, s);
    const std::size_t m = modes_.size();
    for (std::size_t r = 0; r < m; ++r) {
      const ModeCoefficients& c = modes_[r];
      ds[r] = s[m + r];
      ds[m + r] = c.gain * (c.x_axis ? f.fx_n : f.fy_n) - c.two_zeta_w * s[m + r] - c.w2 * s[r];
    }
  }

 private:
  void add(const Mode& mode, bool x_axis) {
    const double w = 2.0 * std::numbers::pi * mode.natural_frequency_hz;
    modes_.push_back({x_axis, 2.0 * mode.damping_ratio * w, w * w, w * w / mode.stiffness_n_per_m});
  }

  const MillingSetup& setup_;
  OperatingPoint point_;
  double h_;
  double delay_;
  std::vector<CutterEdge> edges_;
  ToothPasses passes_;
  mutable std::vector<double> xd_, yd_;  // the delayed positions of each pass (scratch of force())
  std::vector<ModeCoefficients> modes_;
  std::vector<double> hx_, hy_, hvx_, hvy_;
};

}  // namespace

SimulationTrace simulateMillingCvode(const MillingSetup& setup, const OperatingPoint& point, int revolutions,
                                     double rtol, int samples_per_tooth_period, int regenerative_passes,
                                     int axial_slices) {
  require(std::isfinite(point.spindle_rev_per_s) && point.spindle_rev_per_s > 0.0, "spindle speed [rev/s]",
          point.spindle_rev_per_s, "(0, inf)");
  require(std::isfinite(point.axial_depth_m) && point.axial_depth_m >= 0.0, "axial depth [m]", point.axial_depth_m,
          "[0, inf)");
  require(std::isfinite(point.feed_per_tooth_m) && point.feed_per_tooth_m > 0.0, "feed per tooth [m]",
          point.feed_per_tooth_m, "(0, inf)");
  require(revolutions >= 1, "revolutions", revolutions, "[1, inf)");
  require(rtol >= 1e-13 && rtol <= 1e-2, "relative tolerance", rtol, "[1e-13, 1e-2]");
  require(samples_per_tooth_period == 0 || samples_per_tooth_period >= 4, "samples per tooth period",
          samples_per_tooth_period, "0 (automatic) or [4, inf)");
  require(setup.teeth >= 1, "teeth", setup.teeth, "[1, inf)");
  setup.validateGeometry();
  require(axial_slices >= 0 && axial_slices <= kMaxAxialSlices, "axial slices", axial_slices,
          "0 (automatic) or [1, 720]");
  // The shortest delay spans >= 4 output samples, so every delayed instant is already stored.
  require(samples_per_tooth_period == 0 || samples_per_tooth_period >= minimumStepsPerToothPeriod(setup),
          "samples per tooth period (smallest pitch)", samples_per_tooth_period,
          "0 (automatic) or >= 4 (2 pi / n_t) / smallest pitch");
  require(regenerative_passes >= 1 && regenerative_passes <= kMaxRegenerativePasses, "regenerative passes",
          regenerative_passes, "[1, 8]");

  const int m = samples_per_tooth_period > 0 ? samples_per_tooth_period
                                             : automaticStepsPerToothPeriod(setup, point.spindle_rev_per_s);
  const double h = point.toothPeriodS(setup.teeth) / m;
  const long samples = static_cast<long>(m) * setup.teeth * revolutions;
  ReferenceModel model(setup, point, h, regenerative_passes,
                       simulationAxialSlices(setup, point.axial_depth_m, axial_slices));
  const int n = model.size();

  // Absolute tolerances scaled to the static deflection K_t b s_t / k_r (and w_r times it for velocities).
  std::vector<double> y0(static_cast<std::size_t>(n), 0.0), atol(static_cast<std::size_t>(n));
  const double force_scale = setup.tangential_coefficient_pa * point.axial_depth_m * point.feed_per_tooth_m;
  const auto& modes = model.modes();
  for (std::size_t r = 0; r < modes.size(); ++r) {
    const double q_scale = std::max(force_scale * modes[r].gain / modes[r].w2, 1e-15);
    atol[r] = 1e-2 * rtol * q_scale;
    atol[modes.size() + r] = 1e-2 * rtol * q_scale * std::sqrt(modes[r].w2);
  }

  SimulationTrace trace;
  for (auto* v : {&trace.time_s, &trace.x_m, &trace.y_m, &trace.fx_n, &trace.fy_n, &trace.force_n, &trace.power_w})
    v->reserve(static_cast<std::size_t>(samples));
  const double circumference_speed = std::numbers::pi * setup.diameter_m * point.spindle_rev_per_s;
  auto record = [&](double t, const double* s) {
    double x, y, vx, vy;
    model.axes(s, x, y, vx, vy);
    // Right-hand limit at t_k (like the RK4 trace): a tooth entering exactly at t_k is counted.
    const StaticForce f = model.force(t + 1e-9 * h, s);
    trace.time_s.push_back(t);
    trace.x_m.push_back(x);
    trace.y_m.push_back(y);
    trace.fx_n.push_back(f.fx_n);
    trace.fy_n.push_back(f.fy_n);
    trace.force_n.push_back(f.resultant());
    trace.power_w.push_back(circumference_speed * f.tangential_sum_n);
  };

  if (n == 0) {  // both axes rigid: nothing to integrate
    for (long k = 0; k < samples; ++k) record(k * h, nullptr);
    return trace;
  }
  CvodeIntegrator integrator([&model](double t, const double* s, double* ds) { model.rhs(t, s, ds); }, 0.0, y0, rtol,
                             atol);
  model.store(y0.data());
  record(0.0, y0.data());
  // Output spacing h <= T, so every delayed time the RHS needs inside [t_k, t_k+1] is already stored.
  for (long k = 1; k < samples; ++k) {
    const double t = k * h;
    integrator.advanceTo(t);
    model.store(integrator.state());
    record(t, integrator.state());
  }
  return trace;
}

}  // namespace mx
