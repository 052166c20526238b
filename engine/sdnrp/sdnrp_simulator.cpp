#include "sdnrp/sdnrp_simulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "sdnrp/gp_models.h"

namespace mx {
namespace {

void requirePositive(const char* field, double v, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InvalidInput(std::string("sdnrp: ") + field + " = " + std::to_string(v) + " " + unit + ": must be > 0");
}

constexpr double kMmMin = 1e-3 / 60.0;  // 1 mm/min in m/s
constexpr double kRpm = 1.0 / 60.0;     // 1 rpm in rev/s

// Sums of the deviation from the target, so that a constant signal gives std = 0 up to rounding.
struct SpreadSum {
  double target = 0.0, lo = 0.0, hi = 0.0, sum = 0.0, sum_sq = 0.0;
  long long n = 0;
  void add(double v) {
    lo = n == 0 ? v : std::min(lo, v);
    hi = n == 0 ? v : std::max(hi, v);
    sum += v - target;
    sum_sq += (v - target) * (v - target);
    ++n;
  }
  SdnrpSpread spread(double scale) const {
    const double m = static_cast<double>(n), d = sum / m, ms = sum_sq / m;
    return {lo * scale, hi * scale, (target + d) * scale, std::sqrt(std::max(0.0, ms - d * d)) * scale,
            std::sqrt(ms) * scale};
  }
};

}  // namespace

SdnrpSimulator::SdnrpSimulator(SdnrpSettings s) : settings_(s) {
  const double ra_um = s.ra_desired_m * 1e6;
  if (!(ra_um >= 0.25 && ra_um <= 2.5))
    throw InvalidInput("sdnrp: Ra = " + std::to_string(ra_um) +
                       " um: must be in [0.25, 2.5] um (where K1-K4 are defined and F_d reachable)");
  requirePositive("duration", s.duration_s, "s");
  requirePositive("time_step", s.time_step_s, "s");
  requirePositive("output_period", s.output_period_s, "s");
  requirePositive("final_window", s.final_window_s, "s");
  requirePositive("integral_rate", s.integral_rate_per_s, "1/s");
  requirePositive("feed_natural_frequency", s.drives.feed_natural_frequency_rad_s, "rad/s");
  requirePositive("feed_damping", s.drives.feed_damping, "");
  requirePositive("spindle_time_constant", s.drives.spindle_time_constant_s, "s");
  if (s.time_step_s > s.output_period_s || s.final_window_s > s.duration_s)
    throw InvalidInput("sdnrp: time_step = " + std::to_string(s.time_step_s) +
                       " s: must be <= output_period and final_window <= duration");
  if (!(s.min_feed_m_per_s >= SdnrpModels::turningFeed() * kMmMin) || !(s.max_feed_m_per_s > s.min_feed_m_per_s))
    throw InvalidInput("sdnrp: feed limits = [" + std::to_string(s.min_feed_m_per_s / kMmMin) + ", " +
                       std::to_string(s.max_feed_m_per_s / kMmMin) +
                       "] mm/min: need 69.7 <= min < max (K4 turns at 69.7)");
  if (!(s.min_speed_rev_per_s > 0.0) || !(s.max_speed_rev_per_s > s.min_speed_rev_per_s))
    throw InvalidInput("sdnrp: speed limits = [" + std::to_string(s.min_speed_rev_per_s / kRpm) + ", " +
                       std::to_string(s.max_speed_rev_per_s / kRpm) + "] rpm: need 0 < min < max");
  for (double v : {s.initial_feed_m_per_s, s.initial_speed_rev_per_s})
    if (v == v && !(v > 0.0 && std::isfinite(v)))
      throw InvalidInput("sdnrp: initial feed/speed = " + std::to_string(v) + ": must be > 0 (or unset)");
  UnmodelledDynamics check(s.disturbance);  // validates sigma and hold
  (void)check;
}

SdnrpResult SdnrpSimulator::run(const JobControl& job) const {
  const auto& s = settings_;
  // Paper units inside the loop: N, mm/min, rpm, um.
  const double f_min = s.min_feed_m_per_s / kMmMin, f_max = s.max_feed_m_per_s / kMmMin;
  const double n_min = s.min_speed_rev_per_s / kRpm, n_max = s.max_speed_rev_per_s / kRpm;
  const double ra_d = s.ra_desired_m * 1e6;
  const double Fd = SdnrpModels::desiredForce(ra_d);
  const double f_ff_raw = SdnrpModels::feedCommand(Fd);
  const double f_ff = std::clamp(f_ff_raw, f_min, f_max);
  const double n_c = std::clamp(SdnrpModels::speedCommand(std::min(Fd, 236.0)), n_min, n_max);
  const double w = s.drives.feed_natural_frequency_rad_s, zeta = s.drives.feed_damping;
  const double tau_s = s.drives.spindle_time_constant_s, lambda = s.integral_rate_per_s;

  SdnrpResult r;
  r.ra_desired_m = s.ra_desired_m;
  r.fd_N = Fd;
  r.feed_feedforward_raw_m_per_s = f_ff_raw * kMmMin;
  r.speed_command_rev_per_s = n_c * kRpm;
  const double f0 = s.initial_feed_m_per_s == s.initial_feed_m_per_s ? s.initial_feed_m_per_s / kMmMin : f_ff;
  const double n0 = s.initial_speed_rev_per_s == s.initial_speed_rev_per_s ? s.initial_speed_rev_per_s / kRpm : n_c;
  r.initial_feed_m_per_s = f0 * kMmMin;
  r.initial_speed_rev_per_s = n0 * kRpm;
  r.control = s.control;
  // Without SDNRP the commands stay at the starting point, so the drives rest there (derivatives 0).
  const double n_cmd = s.control ? n_c : n0;

  // state: f_a, f_a', n_a, x (integral); bumpless start: f_c(0) = f0
  using State = std::array<double, 4>;
  State y{f0, 0.0, n0, f0 - f_ff};
  auto force = [](double n, double f) { return SdnrpModels::cuttingForce(std::max(n, 0.0), std::max(f, 1.0)); };
  auto command = [&](double x) { return s.control ? std::clamp(f_ff + x, f_min, f_max) : f0; };
  auto deriv = [&](const State& q, double dist) {
    const double F_meas = force(q[2], q[0]) + dist;
    const double e = Fd - F_meas;
    const double gain = SdnrpModels::cuttingForceFeedSensitivity(std::max(q[0], f_min));
    double dx = s.control ? lambda * e / std::max(gain, 1e-6) : 0.0;
    const double raw = f_ff + q[3];
    if ((raw >= f_max && dx > 0.0) || (raw <= f_min && dx < 0.0)) dx = 0.0;  // anti-windup
    const double fc = command(q[3]);
    return State{q[1], w * w * (fc - q[0]) - 2.0 * zeta * w * q[1], (n_cmd - q[2]) / tau_s, dx};
  };

  UnmodelledDynamics disturbance(s.disturbance);
  const double dt = s.time_step_s;
  const auto steps = static_cast<long long>(std::llround(s.duration_s / dt));
  const auto out_every = std::max<long long>(1, std::llround(s.output_period_s / dt));
  const auto window_steps = std::max<long long>(1, std::llround(s.final_window_s / dt));
  const auto cancel_every = std::max<long long>(1, std::llround(0.1 / dt));
  r.samples.reserve(static_cast<std::size_t>(steps / out_every + 2));
  double sum_F = 0.0, sum_f = 0.0, sum_n = 0.0, sum_ra = 0.0;
  long long in_window = 0;
  SpreadSum force_run{Fd}, force_final{Fd}, ra_run{ra_d}, ra_final{ra_d};

  for (long long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * dt;
    const double dist = disturbance.at(t);
    const double F = force(y[2], y[0]);
    const double F_meas = F + dist;
    if (k % out_every == 0 || k == steps) {
      SdnrpSample smp;
      smp.t_s = t;
      smp.force_N = F;
      smp.force_dynamic_N = F_meas;
      smp.ra_m = SdnrpModels::roughness(std::min(F, 292.0)) * 1e-6;
      smp.ra_dynamic_m = SdnrpModels::roughness(std::min(F_meas, 292.0)) * 1e-6;
      smp.feed_m_per_s = y[0] * kMmMin;
      smp.speed_rev_per_s = y[2] * kRpm;
      smp.feed_command_m_per_s = command(y[3]) * kMmMin;
      smp.speed_command_rev_per_s = n_cmd * kRpm;
      r.samples.push_back(smp);
    }
    const double ra_meas = SdnrpModels::roughness(std::min(F_meas, 292.0));
    force_run.add(F_meas);
    ra_run.add(ra_meas);
    if (k > steps - window_steps) {
      sum_F += F_meas;
      sum_f += y[0];
      sum_n += y[2];
      sum_ra += ra_meas;
      force_final.add(F_meas);
      ra_final.add(ra_meas);
      ++in_window;
    }
    if (k == steps) break;
    if (k % cancel_every == 0) {
      if (job.cancelled()) throw Cancelled();
      job.report(static_cast<double>(k) / static_cast<double>(steps));
    }
    // RK4, disturbance held over the step
    const State k1 = deriv(y, dist);
    State tmp;
    for (int i = 0; i < 4; ++i)
      tmp[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(i)] + 0.5 * dt * k1[static_cast<std::size_t>(i)];
    const State k2 = deriv(tmp, dist);
    for (int i = 0; i < 4; ++i)
      tmp[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(i)] + 0.5 * dt * k2[static_cast<std::size_t>(i)];
    const State k3 = deriv(tmp, dist);
    for (int i = 0; i < 4; ++i)
      tmp[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(i)] + dt * k3[static_cast<std::size_t>(i)];
    const State k4 = deriv(tmp, dist);
    for (std::size_t i = 0; i < 4; ++i) y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  const double m = static_cast<double>(in_window);
  r.f_final_N = sum_F / m;
  r.feed_final_m_per_s = sum_f / m * kMmMin;
  r.speed_final_rev_per_s = sum_n / m * kRpm;
  r.ra_produced_m = sum_ra / m * 1e-6;
  const double raw = f_ff + y[3];
  r.feed_saturated = s.control && (raw >= f_max || raw <= f_min);
  r.force_run = force_run.spread(1.0);
  r.force_final = force_final.spread(1.0);
  r.ra_run = ra_run.spread(1e-6);
  r.ra_final = ra_final.spread(1e-6);
  job.report(1.0);
  return r;
}

}  // namespace mx
