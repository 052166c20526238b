#include "control/plant_integrator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/invalid_input.h"
#include "simulation/cvode_integrator.h"

namespace mx {

double ControlWorkpiece::totalLength() const {
  double sum = 0.0;
  for (const auto& s : steps) sum += s.length_m;
  return sum;
}

double ControlWorkpiece::boundaryAfter(int segment) const {
  double sum = 0.0;
  for (int i = 0; i <= segment && i < static_cast<int>(steps.size()); ++i)
    sum += steps[static_cast<std::size_t>(i)].length_m;
  return sum;
}

int ControlWorkpiece::segmentAt(double position_m) const {
  double end = 0.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    end += steps[i].length_m;
    if (position_m < end) return static_cast<int>(i);
  }
  return static_cast<int>(steps.size()) - 1;
}

ControlWorkpiece rubio2006ControlWorkpiece() {
  return {{{5.87e-3, 2e-3, 0.0}, {5.87e-3, 3e-3, 0.0}, {5.87e-3, 5e-3, 0.0}, {7.55e-3, 3e-3, 0.0}}};
}

void validateControlWorkpiece(const ControlWorkpiece& w) {
  if (w.steps.empty()) throw InvalidInput("workpiece: steps = 0: must have at least one depth step");
  for (std::size_t i = 0; i < w.steps.size(); ++i) {
    const auto& s = w.steps[i];
    if (!(s.length_m > 0.0) || !std::isfinite(s.length_m))
      throw InvalidInput("workpiece: steps[" + std::to_string(i) + "].length = " + std::to_string(s.length_m) +
                         " m: must be finite and > 0");
    if (!(s.depth_m > 0.0) || !std::isfinite(s.depth_m))
      throw InvalidInput("workpiece: steps[" + std::to_string(i) + "].depth = " + std::to_string(s.depth_m) +
                         " m: must be finite and > 0");
    if (!(s.spindle_rev_s >= 0.0) || !std::isfinite(s.spindle_rev_s))
      throw InvalidInput("workpiece: steps[" + std::to_string(i) + "].spindle_rev_s = " +
                         std::to_string(s.spindle_rev_s) + " rev/s: must be finite and >= 0 (0: the process's)");
  }
}

CuttingProcess stepProcess(const CuttingProcess& process, const ControlDepthStep& step) {
  CuttingProcess p = process;
  if (step.spindle_rev_s > 0.0) p.spindle_rev_s = step.spindle_rev_s;
  return p;
}

double FrohHold::at(double t) const {
  return std::clamp(u_k + beta * (u_k - u_prev) * (t - t0) / period, lo, hi);
}

ForcePlantIntegrator::ForcePlantIntegrator(const CuttingProcess& process, const ControlWorkpiece& workpiece,
                                           double rtol)
    : process_(process), workpiece_(workpiece), rtol_(rtol) {
  validateCuttingProcess(process_);
  validateControlWorkpiece(workpiece_);
  if (!(rtol > 0.0 && rtol < 1e-2))
    throw InvalidInput("plant integrator: rtol = " + std::to_string(rtol) + ": must be in (0, 1e-2)");
  for (const auto& s : workpiece_.steps) {
    const CuttingProcess p = stepProcess(process_, s);
    gains_.push_back(makeForcePlant(p, s.depth_m).gain_N_s_per_m);
    tau_c_s_.push_back(processTimeConstant(p));
    speeds_.push_back(p.spindle_rev_s);
  }
}

double ForcePlantIntegrator::spindleRevS() const {
  return speeds_[static_cast<std::size_t>(segment_)];
}

double ForcePlantIntegrator::depth() const {
  return workpiece_.steps[static_cast<std::size_t>(segment_)].depth_m;
}

PlantDensePoint ForcePlantIntegrator::point(const FrohHold& hold) const {
  return {t_, x_[1], hold.at(t_), x_[0], x_[2], depth()};
}

void ForcePlantIntegrator::integrate(const FrohHold& hold, double t_end, std::unique_ptr<CvodeIntegrator>& ode) {
  if (t_end <= t_) return;
  if (!ode) {
    const double gain = gains_[static_cast<std::size_t>(segment_)];
    const double tau_m = process_.drive_time_constant_s, tau_c = tau_c_s_[static_cast<std::size_t>(segment_)];
    // `hold` outlives `ode` (both live for one call of advance)
    auto rhs = [&hold, gain, tau_m, tau_c](double t, const double* x, double* dx) {
      dx[0] = (hold.at(t) - x[0]) / tau_m;
      dx[1] = (gain * x[0] - x[1]) / tau_c;
      dx[2] = x[0];
    };
    const double feed_scale = std::max(hold.hi, 1e-6);
    const double force_scale = std::max(gain * feed_scale, 1.0);
    const std::vector<double> atol{1e-3 * rtol_ * feed_scale, 1e-3 * rtol_ * force_scale, 1e-3 * rtol_ * 1e-2};
    ode = std::make_unique<CvodeIntegrator>(rhs, t_, std::vector<double>{x_[0], x_[1], x_[2]}, rtol_, atol, 1000000,
                                            CvodeIntegrator::Method::Bdf);
    steps_base_ = 0;
  }
  ode->advanceTo(t_end);
  steps_ += ode->steps() - steps_base_;
  steps_base_ = ode->steps();
  std::copy(ode->state(), ode->state() + 3, x_);
  t_ = t_end;
}

void ForcePlantIntegrator::advance(const FrohHold& hold, int points, std::vector<PlantDensePoint>& out) {
  if (points < 1) throw InvalidInput("plant integrator: dense points = " + std::to_string(points) + ": must be >= 1");
  if (std::abs(hold.t0 - t_) > 1e-12 * std::max(1.0, t_))
    throw InvalidInput("plant integrator: hold.t0 = " + std::to_string(hold.t0) + " s: must equal the current time");
  const int last = static_cast<int>(workpiece_.steps.size()) - 1;
  std::unique_ptr<CvodeIntegrator> ode;  // one CVODE run per interval (the hold output jumps at sampling instants)
  for (int j = 1; j <= points; ++j) {
    const double target = j == points ? hold.t0 + hold.period : hold.t0 + hold.period * j / points;
    const double t_prev = t_;
    const double x_prev[3] = {x_[0], x_[1], x_[2]};
    integrate(hold, target, ode);
    while (segment_ < last && x_[2] >= workpiece_.boundaryAfter(segment_)) {
      // Locate the crossing: Newton on p(t) = boundary from the last accepted point (p' = f_a > 0).
      const double boundary = workpiece_.boundaryAfter(segment_);
      const double p_end = x_[2];
      double lo = t_prev, hi = t_;
      double guess = t_prev + (t_ - t_prev) * (boundary - x_prev[2]) / std::max(p_end - x_prev[2], 1e-300);
      for (int it = 0; it < 30; ++it) {
        guess = std::clamp(guess, lo, hi);
        t_ = t_prev;
        std::copy(x_prev, x_prev + 3, x_);
        std::unique_ptr<CvodeIntegrator> probe;
        integrate(hold, guess, probe);
        const double miss = x_[2] - boundary;
        if (miss >= 0.0)
          hi = guess;
        else
          lo = guess;
        if (std::abs(miss) <= 1e-13 || hi - lo <= 1e-14) break;
        const double next = guess - miss / std::max(x_[0], 1e-12);
        guess = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
      }
      crossings_.push_back(t_);
      out.push_back(point(hold));
      ++segment_;
      out.back().depth_m = depth();
      ode.reset();  // restart at the crossing with the new gain
      integrate(hold, target, ode);
    }
    out.push_back(point(hold));
  }
}

}  // namespace mx
