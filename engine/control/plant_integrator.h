#pragma once
// Continuous integration of the force plant between samples with SUNDIALS CVODE (BDF + Newton: with
// T / tau_m ~ 840 the drive makes the system stiff). State: actual feed f_a (m/s), force F (N), tool position p (m):
//   tau_m f_a' = f_c(t) - f_a,   tau_c F' = K_p(b(p)) f_a - F,   p' = f_a,
// where f_c(t) is the beta-FROH hold output clamped to the drive's range and the depth b(p) is piecewise constant
// along the tool path, as are K_p and tau_c when a step programmes its own spindle speed (a sequence of programmed
// points, Pareto paper Fig. 6). A depth change is located exactly (Newton on the position with fresh integrations), the
// integrator is restarted there, and the crossing becomes a dense output point.
#include <memory>
#include <vector>

#include "control/force_plant.h"

namespace mx {

class CvodeIntegrator;

struct ControlDepthStep {
  double length_m = 0.0;       // along the feed direction
  double depth_m = 0.0;        // axial depth of cut b
  double spindle_rev_s = 0.0;  // programmed N of the step; 0: the process's
};

struct ControlWorkpiece {
  std::vector<ControlDepthStep> steps;
  double totalLength() const;
  int segmentAt(double position_m) const;   // the last segment continues beyond the end
  double boundaryAfter(int segment) const;  // position where `segment` ends
};
// Paper (2006, fig. 7): 2, 3, 5 and 3 mm over 5.87, 5.87, 5.87 and 7.55 mm.
ControlWorkpiece rubio2006ControlWorkpiece();
void validateControlWorkpiece(const ControlWorkpiece& w);  // InvalidInput naming the step and field
// The process while cutting `step`: its spindle speed when it programmes one.
CuttingProcess stepProcess(const CuttingProcess& process, const ControlDepthStep& step);

// The beta-FROH hold over [t0, t0 + T): f(t) = u_k + beta (u_k - u_{k-1}) (t - t0) / T, clamped to [lo, hi].
struct FrohHold {
  double t0 = 0.0, period = 1.0, u_k = 0.0, u_prev = 0.0, beta = 0.0, lo = 0.0, hi = 0.0;
  double at(double t) const;
};

struct PlantDensePoint {
  double t = 0.0, force_N = 0.0, feed_command_m_s = 0.0, feed_actual_m_s = 0.0, position_m = 0.0, depth_m = 0.0;
};

class ForcePlantIntegrator {
 public:
  ForcePlantIntegrator(const CuttingProcess& process, const ControlWorkpiece& workpiece, double rtol = 1e-8);

  // Integrates over [time(), time() + hold.period] (hold.t0 must equal time()), appending `points` evenly spaced
  // dense points (the last one at the next sampling instant) and one point at every depth change.
  void advance(const FrohHold& hold, int points, std::vector<PlantDensePoint>& out);

  double time() const { return t_; }
  double force() const { return x_[1]; }
  double feedActual() const { return x_[0]; }
  double position() const { return x_[2]; }
  int segment() const { return segment_; }
  double depth() const;
  double spindleRevS() const;  // programmed N of the current segment
  std::vector<double> crossingTimes() const { return crossings_; }
  long cvodeSteps() const { return steps_; }

 private:
  // CVODE from (t_, x_) with the current depth; `ode` is kept between calls within one interval and segment
  // (reset it to start afresh).
  void integrate(const FrohHold& hold, double t_end, std::unique_ptr<CvodeIntegrator>& ode);
  PlantDensePoint point(const FrohHold& hold) const;

  CuttingProcess process_;
  ControlWorkpiece workpiece_;
  double rtol_;
  std::vector<double> gains_;    // K_p per segment
  std::vector<double> tau_c_s_;  // tau_c per segment
  std::vector<double> speeds_;   // N per segment (rev/s)
  double t_ = 0.0;
  double x_[3] = {0.0, 0.0, 0.0};
  int segment_ = 0;
  std::vector<double> crossings_;
  long steps_ = 0;
  long steps_base_ = 0;
};

}  // namespace mx
