#include "simulation/time_domain_simulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>

#include "model/cutting_force.h"
#include "simulation/delay_history.h"
#include "simulation/engagement_plan.h"
#include "simulation/modal_dynamics.h"
#include "simulation/spindle_kinematics.h"

namespace mx {

namespace {

constexpr int kMinStepsPerToothPeriod = 32;
constexpr double kStepsPerVibrationPeriod = 40.0;
constexpr int kMaxTabulatedSteps = 1 << 18;

// Regenerative state of one RK4 stage for K remembered passes: for pass k (1-based)
//   h_k = (k s_t + x(t) - x(t - kT)) sin phi + (y(t) - y(t - kT)) cos phi,  h = min_k h_k  (eq. 7 for K = 1).
struct Regeneration {
  int passes = 1;
  std::array<double, kMaxRegenerativePasses> ax{}, ay{};
};

// Summed cutting force of the engaged teeth: F_tj = K_t b h_j for h_j > 0 (eq. 2), else 0.
struct CutForce {
  double fx = 0.0, fy = 0.0, tangential = 0.0, max_chip = 0.0;
};

inline CutForce cutForce(std::span<const ActiveTooth> teeth, const Regeneration& r, double depth, double kt) {
  double sum_h = 0.0, sum_x = 0.0, sum_y = 0.0, max_h = 0.0;
  for (const ActiveTooth& tooth : teeth) {
    double h = r.ax[0] * tooth.sin_phi + r.ay[0] * tooth.cos_phi;
    for (int k = 1; k < r.passes; ++k) h = std::min(h, r.ax[k] * tooth.sin_phi + r.ay[k] * tooth.cos_phi);
    if (h > 0.0) {
      sum_h += h;
      sum_x += h * tooth.fx_unit;
      sum_y += h * tooth.fy_unit;
      max_h = std::max(max_h, h);
    }
  }
  return {depth * sum_x, depth * sum_y, kt * depth * sum_h, max_h};
}

// Constant speed: step n uses the tabulated plan of step n mod m.
class TabulatedPlans {
 public:
  TabulatedPlans(const MillingSetup& setup, int steps_per_tooth) : table_(setup, steps_per_tooth) {}
  StepPlanView at(std::int64_t n) { return table_.step(n); }

 private:
  EngagementTable table_;
};

// Any speed law: the plan of step n from theta(t), event instants by safeguarded Newton on theta(t) = angle.
class KinematicPlans {
 public:
  KinematicPlans(const MillingSetup& setup, const SpindleKinematics& kinematics, double dt)
      : planner_(setup), kinematics_(kinematics), dt_(dt) {}
  StepPlanView at(std::int64_t n) {
    const double t0 = static_cast<double>(n) * dt_;
    auto theta = [&](double f) { return kinematics_.angleRad(t0 + f * dt_); };
    auto fraction = [&](double angle) {
      double lo = 0.0, hi = 1.0, f = 0.5;
      for (int i = 0; i < 60; ++i) {
        const double g = theta(f) - angle;
        if (g > 0.0)
          hi = f;
        else
          lo = f;
        double next = f - g / (2.0 * std::numbers::pi * kinematics_.speedRevPerS(t0 + f * dt_) * dt_);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - f) < 1e-15) return next;
        f = next;
      }
      return f;
    };
    steps_.clear();
    pool_.clear();
    planner_.plan(theta, fraction, steps_, pool_);
    return {steps_, pool_.data()};
  }

 private:
  EngagementPlanner planner_;
  const SpindleKinematics& kinematics_;
  double dt_;
  std::vector<SubStep> steps_;
  std::vector<ActiveTooth> pool_;
};

using PastPositions = std::array<AxisPosition, kMaxRegenerativePasses>;

// Constant speed: tau_k = k T = k m dt, so r(t_n - kT) is sample n - k m, the mid-step value is the
// Hermite midpoint, and other sub-step instants are Hermite-interpolated.
class FixedDelay {
 public:
  FixedDelay(int steps_per_tooth, int passes) : m_(steps_per_tooth), passes_(passes) {}
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    for (int k = 0; k < passes_; ++k) {
      const std::int64_t i = n - (k + 1) * m_;
      AxisPosition& p = past_[static_cast<std::size_t>(k)];
      if (fraction == 0.0)
        p = history.position(i);
      else if (fraction == 0.5)
        p = history.midpoint(i);
      else if (fraction == 1.0)
        p = history.position(i + 1);
      else
        p = history.interpolate(static_cast<double>(i) + fraction);
    }
    return past_;
  }

 private:
  std::int64_t m_;
  int passes_;
  PastPositions past_{};
};

// Time-varying delay: r(t - tau_k(t)) by Hermite interpolation, theta(t) - theta(t - tau_k) = k 2 pi / n_t
// by Newton. The last three instants are cached (the RK4 mid point is used twice, a step's end is the
// next step's start).
class VariableDelay {
 public:
  VariableDelay(const SpindleKinematics& kinematics, double dt, int passes)
      : kinematics_(kinematics), dt_(dt), passes_(passes) {
    for (int k = 0; k < passes; ++k) guess_[static_cast<std::size_t>(k)] = (k + 1) * kinematics.nominalToothPeriodS();
    times_.fill(-1.0);
  }
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    const double t = (static_cast<double>(n) + fraction) * dt_;
    for (std::size_t c = 0; c < times_.size(); ++c)
      if (times_[c] == t) return values_[c];
    next_ = (next_ + 1) % times_.size();
    for (int k = 0; k < passes_; ++k) {
      const auto K = static_cast<std::size_t>(k);
      guess_[K] = kinematics_.angleDelayS(t, (k + 1) * kinematics_.pitchRad(), guess_[K]);
      values_[next_][K] = history.interpolate((t - guess_[K]) / dt_);
    }
    times_[next_] = t;
    return values_[next_];
  }

 private:
  const SpindleKinematics& kinematics_;
  double dt_;
  int passes_;
  std::array<double, kMaxRegenerativePasses> guess_{};
  std::array<double, 3> times_{};
  std::array<PastPositions, 3> values_{};
  std::size_t next_ = 0;
};

}  // namespace

int automaticStepsPerToothPeriod(const MillingSetup& setup, double spindle_rev_per_s) {
  double highest_hz = 0.0;
  for (const Mode& mode : setup.modes_x) highest_hz = std::max(highest_hz, mode.natural_frequency_hz);
  for (const Mode& mode : setup.modes_y) highest_hz = std::max(highest_hz, mode.natural_frequency_hz);
  const double tooth_period = 1.0 / (spindle_rev_per_s * setup.teeth);
  const double needed = std::ceil(kStepsPerVibrationPeriod * highest_hz * tooth_period - 1e-9);
  return std::max(kMinStepsPerToothPeriod, static_cast<int>(std::min(needed, 1e9)));
}

TimeDomainSimulator::TimeDomainSimulator(const MillingSetup& setup, const OperatingPoint& point,
                                         const SimulationOptions& options)
    : setup_(setup), point_(point), options_(options) {
  steps_per_tooth_ = options.steps_per_tooth_period > 0 ? options.steps_per_tooth_period
                                                        : automaticStepsPerToothPeriod(setup, point.spindle_rev_per_s);
  dt_ = point.toothPeriodS(setup.teeth) / steps_per_tooth_;
  steps_per_rev_ = static_cast<std::int64_t>(steps_per_tooth_) * setup.teeth;
  total_steps_ = steps_per_rev_ * options.revolutions;
}

void TimeDomainSimulator::run(const JobControl& control, Kernel kernel) {
  const SpindleKinematics kinematics(point_.spindle_rev_per_s, options_.ssv, setup_.teeth);
  // The tabulated plans cost memory per step of a tooth period: beyond kMaxTabulatedSteps (very low
  // speeds) the general kernel, identical at a = 0 up to roundoff, plans each step on the fly.
  if (kernel == Kernel::Automatic)
    kernel = kinematics.constantSpeed() && steps_per_tooth_ <= kMaxTabulatedSteps ? Kernel::ConstantSpeed
                                                                                  : Kernel::VariableSpeed;
  if (kernel == Kernel::ConstantSpeed) {
    if (!kinematics.constantSpeed())
      throw std::logic_error("TimeDomainSimulator: the constant-speed kernel needs a = 0 or f = 0");
    TabulatedPlans plans(setup_, steps_per_tooth_);
    FixedDelay delays(steps_per_tooth_, options_.regenerative_passes);
    integrate(plans, delays, control);
  } else {
    KinematicPlans plans(setup_, kinematics, dt_);
    VariableDelay delays(kinematics, dt_, options_.regenerative_passes);
    integrate(plans, delays, control);
  }
}

template <class Plans, class Delays>
void TimeDomainSimulator::integrate(Plans& plans, Delays& delays, const JobControl& control) {
  const ModalDynamics dynamics(setup_);
  const SpindleKinematics kinematics(point_.spindle_rev_per_s, options_.ssv, setup_.teeth);
  const int passes = options_.regenerative_passes;
  const auto lookback = static_cast<std::int64_t>(std::ceil(passes * kinematics.maxToothDelayS() / dt_)) + 2;
  DelayHistory history(dt_, lookback);

  const int size = dynamics.stateSize();
  state_ = dynamics.initialState(options_.initial_x_m, options_.initial_y_m);
  std::vector<double> scratch(static_cast<std::size_t>(5 * size + 1), 0.0);
  double* y = state_.data();
  double* k1 = scratch.data();
  double* k2 = k1 + size;
  double* k3 = k2 + size;
  double* k4 = k3 + size;
  double* tmp = k4 + size;

  const double depth = point_.axial_depth_m;
  const double feed = point_.feed_per_tooth_m;
  const double kt = toothForce(setup_, 1.0, 0.5 * (setup_.immersion.entry_rad + setup_.immersion.exit_rad), 1.0)
                        .tangential_n;                                // K_t via the force model (F_t per unit b h)
  const double circumference = std::numbers::pi * setup_.diameter_m;  // v = pi D N
  const bool constant_speed = kinematics.constantSpeed();
  const double dt = dt_;

  const auto record_every = static_cast<std::int64_t>(options_.record_every);
  const auto recorded = static_cast<std::size_t>((total_steps_ + record_every - 1) / record_every);
  trace_ = SimulationTrace{};
  for (auto* v :
       {&trace_.time_s, &trace_.x_m, &trace_.y_m, &trace_.fx_n, &trace_.fy_n, &trace_.force_n, &trace_.power_w})
    v->reserve(recorded);

  // Indicator inputs per revolution, and the signals of the last E revolutions in rings, so that a run
  // stopped by divergence is evaluated over the last E revolutions it simulated.
  struct RevolutionStats {
    double max_force = 0.0, max_static_force = 0.0, max_chip = 0.0, max_static_chip = 0.0, peak_power = 0.0;
  };
  const int revolutions = options_.revolutions;
  std::vector<RevolutionStats> stats(static_cast<std::size_t>(revolutions));
  const std::int64_t ring_size = steps_per_rev_ * options_.evaluated_revolutions;
  std::vector<double> ring(static_cast<std::size_t>(ring_size)), ring_x(ring.size()), ring_y(ring.size());
  const double divergence_limit =
      options_.divergence_limit_m > 0.0 ? options_.divergence_limit_m : 0.5 * setup_.diameter_m;

  std::size_t chunk_begin = 0;
  auto finishRevolution = [&](int revolution) {
    if (options_.on_chunk && trace_.size() > chunk_begin) {
      const std::size_t count = trace_.size() - chunk_begin;
      auto view = [&](const std::vector<double>& v) { return std::span<const double>(v.data() + chunk_begin, count); };
      options_.on_chunk(SimulationChunk{revolution, revolutions, chunk_begin, view(trace_.time_s), view(trace_.x_m),
                                        view(trace_.y_m), view(trace_.fx_n), view(trace_.fy_n), view(trace_.force_n),
                                        view(trace_.power_w)});
    }
    chunk_begin = trace_.size();
    control.report(static_cast<double>(revolution) / revolutions);
  };

  auto pushHistory = [&](const double* s) {
    AxisSample sample;
    dynamics.axes(s, sample.x, sample.y);
    dynamics.axisVelocities(s, sample.vx, sample.vy);
    history.push(sample);
  };
  Regeneration regeneration;
  regeneration.passes = passes;
  Regeneration rigid;  // the rigid tool: h = s_t sin phi
  rigid.ax[0] = feed;
  // One RK4 stage at t = (n + fraction) dt with the engaged teeth `teeth`: forces, then d(s)/dt into out.
  auto stage = [&](const double* s, std::int64_t n, double fraction, std::span<const ActiveTooth> teeth, double* out) {
    double x, yy;
    dynamics.axes(s, x, yy);
    const PastPositions& past = delays.at(history, n, fraction);
    for (int p = 0; p < passes; ++p) {
      const auto P = static_cast<std::size_t>(p);
      regeneration.ax[P] = (p + 1) * feed + x - past[P].x;
      regeneration.ay[P] = yy - past[P].y;
    }
    const CutForce f = cutForce(teeth, regeneration, depth, kt);
    dynamics.derivative(s, f.fx, f.fy, out);
    return f;
  };

  pushHistory(y);
  diverged_ = false;
  std::int64_t until_record = 0;
  std::int64_t n = 0;
  RevolutionStats* current = stats.data();
  for (; n < total_steps_; ++n) {
    if (n % steps_per_rev_ == 0) {
      if (n > 0) {
        const auto revolution = static_cast<int>(n / steps_per_rev_);
        finishRevolution(revolution);
        current = &stats[static_cast<std::size_t>(revolution)];
      }
      if (control.cancelled()) throw Cancelled();
    }
    double x, yy;
    dynamics.axes(y, x, yy);
    if (!(std::abs(x) <= divergence_limit && std::abs(yy) <= divergence_limit)) {  // also catches NaN
      diverged_ = true;
      break;
    }

    const StepPlanView plan = plans.at(n);
    bool first = true;
    for (const SubStep& sub : plan.sub_steps) {
      const double h = sub.length * dt;
      const double f0 = sub.begin, fm = sub.begin + 0.5 * sub.length, f1 = sub.begin + sub.length;
      const CutForce c1 = stage(y, n, f0, plan.teeth(sub, 0), k1);
      if (first) {
        // Stage 1 at t_n (right-hand limit): the recorded force; the static reference uses the same teeth.
        first = false;
        const double speed = constant_speed ? point_.spindle_rev_per_s : kinematics.speedRevPerS(n * dt);
        const double force = std::hypot(c1.fx, c1.fy);
        const double power = circumference * speed * c1.tangential;
        const CutForce static_force = cutForce(plan.teeth(sub, 0), rigid, depth, kt);
        current->max_force = std::max(current->max_force, force);
        current->max_static_force = std::max(current->max_static_force, std::hypot(static_force.fx, static_force.fy));
        current->max_chip = std::max(current->max_chip, c1.max_chip);
        current->max_static_chip = std::max(current->max_static_chip, static_force.max_chip);
        current->peak_power = std::max(current->peak_power, power);
        const auto slot = static_cast<std::size_t>(n % ring_size);
        ring[slot] = force;
        ring_x[slot] = x;
        ring_y[slot] = yy;
        if (until_record == 0) {
          trace_.time_s.push_back(n * dt);
          trace_.x_m.push_back(x);
          trace_.y_m.push_back(yy);
          trace_.fx_n.push_back(c1.fx);
          trace_.fy_n.push_back(c1.fy);
          trace_.force_n.push_back(force);
          trace_.power_w.push_back(power);
          until_record = record_every;
        }
        --until_record;
      }
      for (int i = 0; i < size; ++i) tmp[i] = y[i] + 0.5 * h * k1[i];
      stage(tmp, n, fm, plan.teeth(sub, 1), k2);
      for (int i = 0; i < size; ++i) tmp[i] = y[i] + 0.5 * h * k2[i];
      stage(tmp, n, fm, plan.teeth(sub, 1), k3);
      for (int i = 0; i < size; ++i) tmp[i] = y[i] + h * k3[i];
      stage(tmp, n, f1, plan.teeth(sub, 2), k4);
      for (int i = 0; i < size; ++i) y[i] += (h / 6.0) * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    }
    pushHistory(y);
  }
  // Revolutions with at least one sample; a diverged run ends inside one.
  const auto touched = static_cast<int>((n + steps_per_rev_ - 1) / steps_per_rev_);
  if (!diverged_ || n % steps_per_rev_ != 0) finishRevolution(touched);
  if (diverged_) control.report(1.0);

  // The evaluated window: the last E revolutions simulated (ending early if the run diverged).
  simulated_revolutions_ = static_cast<int>(n / steps_per_rev_);
  const int first_revolution = std::max(0, touched - options_.evaluated_revolutions);
  window_ = WindowSignals{};
  window_.sample_rate_hz = 1.0 / dt;
  for (int r = first_revolution; r < touched; ++r) {
    const RevolutionStats& st = stats[static_cast<std::size_t>(r)];
    window_.max_force_n = std::max(window_.max_force_n, st.max_force);
    window_.max_static_force_n = std::max(window_.max_static_force_n, st.max_static_force);
    window_.max_chip_m = std::max(window_.max_chip_m, st.max_chip);
    window_.max_static_chip_m = std::max(window_.max_static_chip_m, st.max_static_chip);
    window_.peak_power_w = std::max(window_.peak_power_w, st.peak_power);
  }
  for (auto* v : {&window_.force_n, &window_.x_m, &window_.y_m})
    v->reserve(static_cast<std::size_t>(n - first_revolution * steps_per_rev_));
  for (std::int64_t i = first_revolution * steps_per_rev_; i < n; ++i) {
    const auto slot = static_cast<std::size_t>(i % ring_size);
    window_.force_n.push_back(ring[slot]);
    window_.x_m.push_back(ring_x[slot]);
    window_.y_m.push_back(ring_y[slot]);
  }
}

}  // namespace mx
