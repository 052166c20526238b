#pragma once
// Rule 4 of the Pareto paper: sampling time selection and computer resources. The controller samples
// once per spindle period, T = 60 / N [s] (N in rpm; the force is periodic with the tooth period, one
// sample per revolution sees the same tooth phase). While N and b stay constant (steady state), the
// period may be lengthened to T = k 60 / N with k >= 1 predefined by the designer, to save computing
// resources; any change of N or b returns to T = 60 / N. (The printed symbols were lost; this is the
// reading of "If N and b remain constant T = k ... / N where k predefined by the designer, else T = ...".)
namespace mx {

struct SamplingTimeSettings {
  int steady_state_periods = 1;      // k >= 1
  double relative_tolerance = 1e-9;  // N and b count as constant within this relative change
};

// One spindle period, or k of them in steady state. Throws InvalidInput for N <= 0 or k < 1.
double samplingTime(double speed_rev_per_s, bool steady_state, int steady_state_periods);

// Tracks (N, b) between controller updates and applies the rule.
class SamplingTimeSelector {
 public:
  explicit SamplingTimeSelector(SamplingTimeSettings settings = {});
  // The sampling time for the next period given the current programmed (N, b).
  double update(double speed_rev_per_s, double depth_m);
  bool steady() const { return steady_; }

 private:
  SamplingTimeSettings settings_;
  double speed_ = 0.0;
  double depth_ = 0.0;
  bool has_previous_ = false;
  bool steady_ = false;
};

}  // namespace mx
