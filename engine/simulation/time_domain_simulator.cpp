#include "simulation/time_domain_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>

#include "model/cutting_force.h"
#include "simulation/delay_history.h"
#include "simulation/delayed_positions.h"
#include "simulation/engagement_plan.h"
#include "simulation/modal_dynamics.h"
#include "simulation/rk4_stepper.h"
#include "simulation/simulation_recorders.h"
#include "simulation/spindle_kinematics.h"
#include "simulation/step_plans.h"

namespace mx {

namespace {

constexpr int kMinStepsPerToothPeriod = 32;
constexpr double kStepsPerVibrationPeriod = 40.0;
constexpr int kMaxTabulatedSteps = 1 << 18;

// The cut's coefficients: K_t, K_te and the process damping C_i / V per unit b at the nominal speed.
CutParameters cutParameters(const MillingSetup& setup, const OperatingPoint& point, int passes, int slices) {
  CutParameters cut;
  cut.depth_m = point.axial_depth_m;
  cut.feed_per_tooth_m = point.feed_per_tooth_m;
  cut.kt = setup.tangential_coefficient_pa;
  cut.extras.kte = setup.tangential_edge_n_per_m;
  cut.extras.damping = setup.processDampingPerDepth(point.spindle_rev_per_s);
  cut.extras.active = cut.extras.kte != 0.0 || setup.radial_edge_n_per_m != 0.0 || cut.extras.damping != 0.0;
  cut.passes = toothPasses(setup, point.feed_per_tooth_m, passes);
  cut.sliced = slices > 1;
  return cut;
}

// The rigid tool's chip coefficients: the static feed and runout terms alone (cutter_edges.h).
Regeneration rigidTool(const MillingSetup& setup, const CutParameters& cut) {
  const ToothPasses passes = rigidToolPasses(setup, cut.feed_per_tooth_m);
  Regeneration rigid(passes, cut.sliced);
  rigid.ax = passes.feed_m;
  return rigid;
}

// Turns the state at t_n and its stage-1 force into the sample the recorders keep, adding the power
// and the rigid tool's force over the same edges (the static reference; h = s_t sin phi for uniform teeth).
class StepSampler {
 public:
  StepSampler(const MillingSetup& setup, const OperatingPoint& point, const SpindleKinematics& kinematics,
              const CutParameters& cut, double dt)
      : kinematics_(kinematics),
        nominal_rev_per_s_(point.spindle_rev_per_s),
        constant_speed_(kinematics.constantSpeed()),
        circumference_(std::numbers::pi * setup.diameter_m),  // v = pi D N
        depth_(cut.depth_m),
        kt_(cut.kt),
        edges_{cut.extras.active, cut.extras.kte, 0.0, 0.0, 0.0},
        dt_(dt),
        rigid_(rigidTool(setup, cut)) {}

  StepSample at(std::int64_t n, double x, double y, const CutForce& c, std::span<const ActiveTooth> teeth) const {
    StepSample s;
    s.n = n;
    s.t_s = n * dt_;
    s.x_m = x;
    s.y_m = y;
    s.fx_n = c.fx;
    s.fy_n = c.fy;
    s.force_n = std::hypot(c.fx, c.fy);
    const double speed = constant_speed_ ? nominal_rev_per_s_ : kinematics_.speedRevPerS(n * dt_);
    s.power_w = circumference_ * speed * c.tangential;
    s.chip_m = c.max_chip;
    const CutForce static_force = cutForce(teeth, rigid_, depth_, kt_, edges_);
    s.static_force_n = std::hypot(static_force.fx, static_force.fy);
    s.static_chip_m = static_force.max_chip;
    return s;
  }

 private:
  const SpindleKinematics& kinematics_;
  double nominal_rev_per_s_;
  bool constant_speed_;
  double circumference_;
  double depth_, kt_;
  CutExtras edges_;  // the rigid tool's: edge forces, no vibration to damp
  double dt_;
  Regeneration rigid_;
};

// The recorders of one run; a finished revolution also reports the progress.
struct StepRecorders {
  const StepSampler& sampler;
  TraceRecorder& trace;
  WindowRecorder& window;
  const JobControl& control;
  int revolutions;

  void record(std::int64_t n, double x, double y, const CutForce& c, std::span<const ActiveTooth> teeth) {
    const StepSample s = sampler.at(n, x, y, c, teeth);
    trace.record(s);
    window.record(s);
  }
  void finishRevolution(int revolution) {
    trace.finishRevolution(revolution);
    control.report(static_cast<double>(revolution) / revolutions);
  }
};

}  // namespace

int automaticStepsPerToothPeriod(const MillingSetup& setup, double spindle_rev_per_s) {
  double highest_hz = 0.0;
  for (const Mode& mode : setup.modes_x) highest_hz = std::max(highest_hz, mode.natural_frequency_hz);
  for (const Mode& mode : setup.modes_y) highest_hz = std::max(highest_hz, mode.natural_frequency_hz);
  const double tooth_period = 1.0 / (spindle_rev_per_s * setup.teeth);
  const double needed = std::ceil(kStepsPerVibrationPeriod * highest_hz * tooth_period - 1e-9);
  return std::max(
      {kMinStepsPerToothPeriod, static_cast<int>(std::min(needed, 1e9)), minimumStepsPerToothPeriod(setup)});
}

int minimumStepsPerToothPeriod(const MillingSetup& setup) {
  double smallest = setup.toothPitchRad();
  for (int j = 0; j < setup.teeth; ++j) smallest = std::min(smallest, setup.pitchRad(j));
  return static_cast<int>(std::ceil(kMinDelaySteps * setup.toothPitchRad() / smallest - 1e-9));
}

int simulationAxialSlices(const MillingSetup& setup, double depth_m, int requested) {
  if (requested > 0) return requested;
  const double lag = std::abs(setup.helixLagRad(depth_m));
  if (!(lag > 0.0)) return 1;
  return static_cast<int>(
      std::clamp(std::ceil(lag / kSimulationSliceLagRad - 1e-9), 1.0, double(kMaxSimulationSlices)));
}

TimeDomainSimulator::TimeDomainSimulator(const MillingSetup& setup, const OperatingPoint& point,
                                         const SimulationOptions& options)
    : setup_(setup), point_(point), options_(options) {
  steps_per_tooth_ = options.steps_per_tooth_period > 0 ? options.steps_per_tooth_period
                                                        : automaticStepsPerToothPeriod(setup, point.spindle_rev_per_s);
  dt_ = point.toothPeriodS(setup.teeth) / steps_per_tooth_;
  steps_per_rev_ = static_cast<std::int64_t>(steps_per_tooth_) * setup.teeth;
  total_steps_ = steps_per_rev_ * options.revolutions;
  axial_slices_ = simulationAxialSlices(setup, point.axial_depth_m, options.axial_slices);
  edges_ = cutterEdges(setup, point.axial_depth_m, axial_slices_);
}

void TimeDomainSimulator::run(const JobControl& control, Kernel kernel) {
  const SpindleKinematics kinematics(point_.spindle_rev_per_s, options_.ssv, setup_.teeth);
  const ToothPasses passes = toothPasses(setup_, point_.feed_per_tooth_m, options_.regenerative_passes);
  // The plan repeats every tooth period when the teeth share their passes, else every revolution.
  const int period_teeth = passes.sets == 1 ? 1 : setup_.teeth;
  // The tabulated plans cost memory per step of their period and per slice: beyond kMaxTabulatedSteps
  // step-slices per tooth (very low speeds) the general kernel, identical at a = 0 up to roundoff, plans
  // each step on the fly.
  const double tabulated = double(steps_per_tooth_) * period_teeth * axial_slices_;
  if (kernel == Kernel::Automatic)
    kernel =
        kinematics.constantSpeed() && tabulated <= kMaxTabulatedSteps ? Kernel::ConstantSpeed : Kernel::VariableSpeed;
  if (kernel == Kernel::ConstantSpeed) {
    if (!kinematics.constantSpeed())
      throw std::logic_error("TimeDomainSimulator: the constant-speed kernel needs a = 0 or f = 0");
    TabulatedPlans plans(setup_, edges_, steps_per_tooth_, period_teeth);
    FixedDelay delays(passes, steps_per_tooth_);
    integrate(plans, delays, control);
  } else {
    KinematicPlans plans(setup_, edges_, kinematics, dt_);
    VariableDelay delays(kinematics, dt_, passes);
    integrate(plans, delays, control);
  }
}

double TimeDomainSimulator::divergenceLimit() const {
  return options_.divergence_limit_m > 0.0 ? options_.divergence_limit_m : 0.5 * setup_.diameter_m;
}

template <class Plans, class Delays>
void TimeDomainSimulator::integrate(Plans& plans, Delays& delays, const JobControl& control) {
  const ModalDynamics dynamics(setup_);
  const SpindleKinematics kinematics(point_.spindle_rev_per_s, options_.ssv, setup_.teeth);
  const CutParameters cut = cutParameters(setup_, point_, options_.regenerative_passes, axial_slices_);
  const auto lookback =
      static_cast<std::int64_t>(std::ceil(cut.passes.maxDelayToothPeriods() * kinematics.maxToothDelayS() / dt_)) + 2;
  DelayHistory history(dt_, lookback);
  state_ = dynamics.initialState(options_.initial_x_m, options_.initial_y_m);
  Rk4Stepper<Delays> stepper(dynamics, history, delays, cut, dt_);

  const StepSampler sampler(setup_, point_, kinematics, cut, dt_);
  TraceRecorder trace(trace_, options_, total_steps_);
  // Unequal teeth repeat the cut once a revolution: eta's reference is then the synchronous average.
  const bool synchronous_reference = cut.passes.sets > 1 && kinematics.constantSpeed();
  WindowRecorder window(options_.revolutions, options_.evaluated_revolutions, steps_per_rev_, dt_,
                        synchronous_reference);
  StepRecorders recorders{sampler, trace, window, control, options_.revolutions};
  const std::int64_t n = stepAll(dynamics, plans, stepper, recorders, control);

  // Revolutions with at least one sample; a diverged run ends inside one.
  const auto touched = static_cast<int>((n + steps_per_rev_ - 1) / steps_per_rev_);
  if (!diverged_ || n % steps_per_rev_ != 0) recorders.finishRevolution(touched);
  if (diverged_) control.report(1.0);
  simulated_revolutions_ = static_cast<int>(n / steps_per_rev_);
  // The evaluated window: the last E revolutions simulated (ending early if the run diverged).
  window_ = window.window(n, touched);
}

template <class Plans, class Stepper, class Recorders>
std::int64_t TimeDomainSimulator::stepAll(const ModalDynamics& dynamics, Plans& plans, Stepper& stepper,
                                          Recorders& recorders, const JobControl& control) {
  const double limit = divergenceLimit();
  double* y = state_.data();
  stepper.pushHistory(y);
  diverged_ = false;
  std::int64_t n = 0;
  for (; n < total_steps_; ++n) {
    if (n % steps_per_rev_ == 0) {
      if (n > 0) recorders.finishRevolution(static_cast<int>(n / steps_per_rev_));
      if (control.cancelled()) throw Cancelled();
    }
    double x, yy;
    dynamics.axes(y, x, yy);
    if (!(std::abs(x) <= limit && std::abs(yy) <= limit)) {  // also catches NaN
      diverged_ = true;
      break;
    }
    const StepPlanView plan = plans.at(n);
    const CutForce at_start = stepper.advance(y, n, plan);
    recorders.record(n, x, yy, at_start, plan.teeth(plan.sub_steps.front(), 0));
  }
  return n;
}

}  // namespace mx
