#include "supervisor/face_milling_process.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {

void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (!ok) throw InvalidInput("face-milling process: " + field + " = " + std::to_string(value) + ": must be " + range);
}

void validateMode(const StructuralMode& m, const std::string& name) {
  require(std::isfinite(m.natural_frequency_rad_s) && m.natural_frequency_rad_s > 0.0,
          name + ".natural_frequency_rad_s", m.natural_frequency_rad_s, "> 0");
  require(std::isfinite(m.damping_ratio) && m.damping_ratio > 0.0 && m.damping_ratio < 1.0, name + ".damping_ratio",
          m.damping_ratio, "in (0, 1)");
  require(std::isfinite(m.stiffness_N_per_m) && m.stiffness_N_per_m > 0.0, name + ".stiffness_N_per_m",
          m.stiffness_N_per_m, "> 0");
}

void validateLaw(const PressureLaw& l, const std::string& name) {
  require(std::isfinite(l.coefficient) && l.coefficient > 0.0, name + ".coefficient", l.coefficient, "> 0");
  require(std::isfinite(l.feed_exponent) && l.feed_exponent > -1.0 && l.feed_exponent < 0.5, name + ".feed_exponent",
          l.feed_exponent, "in (-1, 0.5)");
  require(std::isfinite(l.depth_exponent), name + ".depth_exponent", l.depth_exponent, "finite");
  require(std::isfinite(l.speed_exponent), name + ".speed_exponent", l.speed_exponent, "finite");
}

std::int64_t delaySteps(const FaceMillingParameters& p) {
  const double period = 60.0 / p.spindle_speed_rpm;
  const double delay = p.delay == RegenerationDelay::ToothPeriod ? period / p.teeth : period;
  return std::max<std::int64_t>(1, std::llround(delay / p.step_s));
}

}  // namespace

void validateFaceMillingParameters(const FaceMillingParameters& p) {
  require(std::isfinite(p.tool_radius_m) && p.tool_radius_m > 0.0, "tool_radius_m", p.tool_radius_m, "> 0");
  require(p.teeth >= 1 && p.teeth <= 100, "teeth", p.teeth, "in [1, 100]");
  require(std::isfinite(p.spindle_speed_rpm) && p.spindle_speed_rpm > 0.0, "spindle_speed_rpm", p.spindle_speed_rpm,
          "> 0");
  require(std::isfinite(p.lead_angle_rad) && p.lead_angle_rad >= 0.0 && p.lead_angle_rad < std::numbers::pi / 2,
          "lead_angle_rad", p.lead_angle_rad, "in [0, pi/2)");
  validateLaw(p.cutting, "cutting");
  validateLaw(p.thrust, "thrust");
  validateMode(p.tool_x, "tool_x");
  validateMode(p.tool_y, "tool_y");
  validateMode(p.part_x, "part_x");
  validateMode(p.part_y, "part_y");
  require(std::isfinite(p.part_start_x_m), "part_start_x_m", p.part_start_x_m, "finite");
  require(std::isfinite(p.part_length_m) && p.part_length_m > 0.0, "part_length_m", p.part_length_m, "> 0");
  require(std::isfinite(p.part_width_m) && p.part_width_m > 0.0, "part_width_m", p.part_width_m, "> 0");
  require(std::isfinite(p.part_center_y_m), "part_center_y_m", p.part_center_y_m, "finite");
  const double tooth_period = 60.0 / p.spindle_speed_rpm / p.teeth;
  require(std::isfinite(p.step_s) && p.step_s > 0.0 && p.step_s <= tooth_period / 8.0, "step_s", p.step_s,
          "in (0, tooth period / 8 = " + std::to_string(tooth_period / 8.0) + " s]");
}

FaceMillingProcess::FaceMillingProcess(FaceMillingParameters parameters)
    : p_((validateFaceMillingParameters(parameters), parameters)), history_(1.0, delaySteps(parameters) + 4) {
  omega_ = 2.0 * std::numbers::pi * p_.spindle_speed_rpm / 60.0;
  period_s_ = 60.0 / p_.spindle_speed_rpm;
  v_cut_ = omega_ * p_.tool_radius_m;
  delay_s_ = p_.delay == RegenerationDelay::ToothPeriod ? period_s_ / p_.teeth : period_s_;
  delay_steps_ = delaySteps(p_);
  dt_ = delay_s_ / static_cast<double>(delay_steps_);
  history_ = DelayHistory(dt_, delay_steps_ + 4);
  reset(0.0);
}

void FaceMillingProcess::reset(double tool_x_m) {
  s_.fill(0.0);
  tool_x_ = tool_x_m;
  steps_ = 0;
  history_ = DelayHistory(dt_, delay_steps_ + 4);
  history_.push(AxisSample{});
  out_ = FaceMillingOutput{};
  out_.tool_x_m = tool_x_m;
  setDepth(depth_);
}

void FaceMillingProcess::setFeedRate(double m_per_s) {
  require(std::isfinite(m_per_s) && m_per_s >= 0.0, "feed_rate_m_per_s", m_per_s, ">= 0");
  feed_rate_ = m_per_s;
}

double FaceMillingProcess::pressureCoeff(const PressureLaw& law) const {
  // Force [N] = 1000 * P [kN/mm^2] * h [mm] * d [mm] = (1000 c (V/1000)^ev d^(1+ed)) h^(1+ef).
  const double v_m_min = v_cut_ * 60.0;
  const double d_mm = depth_ * 1e3;
  if (d_mm <= 0.0) return 0.0;
  return 1000.0 * law.coefficient * std::pow(v_m_min / 1000.0, law.speed_exponent) *
         std::pow(d_mm, 1.0 + law.depth_exponent);
}

void FaceMillingProcess::setDepth(double m) {
  require(std::isfinite(m) && m >= 0.0, "depth_m", m, ">= 0");
  depth_ = m;
  kc_ = pressureCoeff(p_.cutting);
  kt_ = pressureCoeff(p_.thrust) * std::cos(p_.lead_angle_rad);
}

FaceMillingProcess::Forces FaceMillingProcess::forces(double t, double tool_x, double dx, double dy, bool rigid) const {
  Forces f;
  if (kc_ <= 0.0) return f;
  const double ft_mm = feed_rate_ * (period_s_ / p_.teeth) * 1e3;
  const double x0 = p_.part_start_x_m, x1 = p_.part_start_x_m + p_.part_length_m;
  const double y0 = p_.part_center_y_m - 0.5 * p_.part_width_m, y1 = p_.part_center_y_m + 0.5 * p_.part_width_m;
  const double ec = 1.0 + p_.cutting.feed_exponent, et = 1.0 + p_.thrust.feed_exponent;
  double sum_t = 0.0;
  for (int i = 0; i < p_.teeth; ++i) {
    const double q = omega_ * t + 2.0 * std::numbers::pi * i / p_.teeth;
    const double c = std::cos(q), s = std::sin(q);
    if (c <= 0.0) continue;  // back half: surface already machined in this pass
    const double px = tool_x + p_.tool_radius_m * c, py = p_.tool_radius_m * s;
    if (py < y0 || py > y1) continue;                      // A5: beyond the part's sides
    if (!rigid && (px < x0 || px > x1)) continue;          // A5: before the part's start or past its end
    const double h = ft_mm * c + (dx * c + dy * s) * 1e3;  // A10 [mm]
    if (h <= 0.0) continue;                                // tooth jumped out of the cut
    const double lh = std::log(h);
    const double Ft = kc_ * std::exp(ec * lh);  // P_C f d
    const double Fr = kt_ * std::exp(et * lh);  // P_T f d cos(psi)
    f.fx += -Fr * c + Ft * s;                   // A3
    f.fy += -Fr * s - Ft * c;                   // A4
    sum_t += Ft;
    ++f.in_cut;
  }
  f.power = sum_t * v_cut_;
  return f;
}

FaceMillingProcess::State FaceMillingProcess::derivative(const State& s, double t, double tool_x,
                                                         const AxisPosition& past, Forces* out) const {
  const double rel_x = s[0] - s[4], rel_y = s[2] - s[6];
  const Forces f = forces(t, tool_x, rel_x - past.x, rel_y - past.y, false);
  if (out) *out = f;
  auto mode = [](const StructuralMode& m, double q, double v, double force) {
    const double w = m.natural_frequency_rad_s;
    return -2.0 * m.damping_ratio * w * v - w * w * q + w * w / m.stiffness_N_per_m * force;
  };
  // Force on the tool F; the part carries the reaction -F (docs: sign convention of A6-A9).
  return {s[1], mode(p_.tool_x, s[0], s[1], f.fx),  s[3], mode(p_.tool_y, s[2], s[3], f.fy),
          s[5], mode(p_.part_x, s[4], s[5], -f.fx), s[7], mode(p_.part_y, s[6], s[7], -f.fy)};
}

void FaceMillingProcess::step() {
  const double t = static_cast<double>(steps_) * dt_;
  const std::int64_t n = steps_;
  const AxisPosition p0 = history_.position(n - delay_steps_);
  const AxisPosition pm = history_.midpoint(n - delay_steps_);
  const AxisPosition p1 = history_.position(n + 1 - delay_steps_);
  const double h = dt_, v = feed_rate_;
  auto add = [](const State& a, const State& b, double k) {
    State r;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + k * b[i];
    return r;
  };
  const State k1 = derivative(s_, t, tool_x_, p0, nullptr);
  const State k2 = derivative(add(s_, k1, 0.5 * h), t + 0.5 * h, tool_x_ + 0.5 * h * v, pm, nullptr);
  const State k3 = derivative(add(s_, k2, 0.5 * h), t + 0.5 * h, tool_x_ + 0.5 * h * v, pm, nullptr);
  const State k4 = derivative(add(s_, k3, h), t + h, tool_x_ + h * v, p1, nullptr);
  for (std::size_t i = 0; i < s_.size(); ++i) s_[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  tool_x_ += h * v;
  ++steps_;
  history_.push(AxisSample{s_[0] - s_[4], s_[2] - s_[6], s_[1] - s_[5], s_[3] - s_[7]});
  // Output at the new time (forces re-evaluated on the updated state).
  const double tn = static_cast<double>(steps_) * dt_;
  const AxisPosition pn = history_.position(steps_ - delay_steps_);
  const double dx = s_[0] - s_[4] - pn.x, dy = s_[2] - s_[6] - pn.y;
  const Forces fn = forces(tn, tool_x_, dx, dy, false);
  out_.t_s = tn;
  out_.fx_N = fn.fx;
  out_.fy_N = fn.fy;
  out_.power_W = fn.power;
  out_.teeth_in_cut = fn.in_cut;
  out_.tool_x_m = tool_x_;
  out_.regen_m = std::hypot(dx, dy);
}

void FaceMillingProcess::advance(double duration_s) {
  const auto n = std::llround(duration_s / dt_);
  for (long long i = 0; i < n; ++i) step();
}

RigidRevolution FaceMillingProcess::rigidRevolution(double depth_m, double feed_per_tooth_m, int samples) const {
  require(samples >= 8, "samples", samples, ">= 8");
  FaceMillingProcess copy(*this);
  copy.setDepth(depth_m);
  copy.setFeedRate(feed_per_tooth_m * p_.teeth / period_s_);
  RigidRevolution r;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double t = period_s_ * k / samples;
    const Forces f = copy.forces(t, 0.0, 0.0, 0.0, true);
    r.fy_max_N = std::max(r.fy_max_N, std::abs(f.fy));
    r.power_max_W = std::max(r.power_max_W, f.power);
    sum += f.power;
  }
  r.power_mean_W = sum / samples;
  return r;
}

}  // namespace mx
