#pragma once
// One fixed step of classical RK4 for the regenerative milling model (2006, section 2E; eq. 1-7):
// the modal equations (ModalDynamics) driven by the cutting force of the engaged teeth, with the
// delayed positions from `Delays` (FixedDelay or VariableDelay). The step is split into the sub-steps
// of its engagement plan, so that a tooth entering or leaving the cut does not fall inside an RK4 step.
#include <cstdint>
#include <span>
#include <vector>

#include "simulation/cutter_edges.h"
#include "simulation/delay_history.h"
#include "simulation/delayed_positions.h"
#include "simulation/engagement_plan.h"
#include "simulation/modal_dynamics.h"
#include "simulation/regenerative_force.h"

namespace mx {

// The cut's constants: axial depth b, feed per tooth s_t, K_t (F_t per unit b h), the edge forces and
// process damping, and each tooth's remembered passes (delays, static feed and runout terms).
struct CutParameters {
  double depth_m = 0.0;
  double feed_per_tooth_m = 0.0;
  double kt = 0.0;
  CutExtras extras;  // edge forces and process damping; the velocities are the stage's
  ToothPasses passes;
  bool sliced = false;  // helical teeth as axial slices (each edge carries its share of b)
};

template <class Delays>
class Rk4Stepper {
 public:
  Rk4Stepper(const ModalDynamics& dynamics, DelayHistory& history, Delays& delays, const CutParameters& cut, double dt)
      : dynamics_(dynamics),
        history_(history),
        delays_(delays),
        cut_(cut),
        dt_(dt),
        size_(dynamics.stateSize()),
        scratch_(static_cast<std::size_t>(5 * size_ + 1), 0.0),
        regeneration_(cut.passes, cut.sliced) {}

  // Appends the positions and velocities of state s to the history (the delayed term's source).
  void pushHistory(const double* s) {
    AxisSample sample;
    dynamics_.axes(s, sample.x, sample.y);
    dynamics_.axisVelocities(s, sample.vx, sample.vy);
    history_.push(sample);
  }

  // Advances y from t_n to t_{n+1} over the sub-steps of `plan` and appends the new state to the history.
  // Returns stage 1 of the first sub-step: the force at t_n (right-hand limit, a tooth entering at t_n cuts).
  CutForce advance(double* y, std::int64_t n, const StepPlanView& plan) {
    const CutForce at_start = subStep(y, n, plan, plan.sub_steps.front());
    for (const SubStep& sub : plan.sub_steps.subspan(1)) subStep(y, n, plan, sub);
    pushHistory(y);
    return at_start;
  }

 private:
  // The RK4 update over [begin, begin + length] dt; each stage point has its own engaged teeth.
  CutForce subStep(double* y, std::int64_t n, const StepPlanView& plan, const SubStep& sub) {
    double* k1 = scratch_.data();
    double* k2 = k1 + size_;
    double* k3 = k2 + size_;
    double* k4 = k3 + size_;
    double* tmp = k4 + size_;
    const double h = sub.length * dt_;
    const double f0 = sub.begin, fm = sub.begin + 0.5 * sub.length, f1 = sub.begin + sub.length;
    const CutForce c1 = stage(y, n, f0, plan.teeth(sub, 0), k1);
    for (int i = 0; i < size_; ++i) tmp[i] = y[i] + 0.5 * h * k1[i];
    stage(tmp, n, fm, plan.teeth(sub, 1), k2);
    for (int i = 0; i < size_; ++i) tmp[i] = y[i] + 0.5 * h * k2[i];
    stage(tmp, n, fm, plan.teeth(sub, 1), k3);
    for (int i = 0; i < size_; ++i) tmp[i] = y[i] + h * k3[i];
    stage(tmp, n, f1, plan.teeth(sub, 2), k4);
    for (int i = 0; i < size_; ++i) y[i] += (h / 6.0) * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    return c1;
  }

  // One RK4 stage at t = (n + fraction) dt with the engaged teeth `teeth`: forces, then d(s)/dt into out.
  CutForce stage(const double* s, std::int64_t n, double fraction, std::span<const ActiveTooth> teeth, double* out) {
    double x, y;
    dynamics_.axes(s, x, y);
    const PastPositions& past = delays_.at(history_, n, fraction);
    const std::vector<double>& feed = cut_.passes.feed_m;
    for (std::size_t i = 0; i < past.size(); ++i) {
      regeneration_.ax[i] = feed[i] + x - past[i].x;
      regeneration_.ay[i] = y - past[i].y;
    }
    CutExtras& extras = cut_.extras;
    if (extras.active) dynamics_.axisVelocities(s, extras.vx, extras.vy);
    const CutForce f = cutForce(teeth, regeneration_, cut_.depth_m, cut_.kt, extras);
    dynamics_.derivative(s, f.fx, f.fy, out);
    return f;
  }

  const ModalDynamics& dynamics_;
  DelayHistory& history_;
  Delays& delays_;
  CutParameters cut_;
  double dt_;
  int size_;
  std::vector<double> scratch_;  // k1, k2, k3, k4 and the stage argument, size_ each
  Regeneration regeneration_;
};

}  // namespace mx
