#pragma once
// Runtime of the RST law (2006 paper, eq. 29) R u = T uc - S y with feed saturation and anti-windup.
// The control is limited to [u_min, u_max] (0 and the feed drive's maximum). Anti-windup (Astrom &
// Wittenmark, with a dead-beat anti-windup observer A_aw = z^deg R): the controller's own past outputs in
// R u are the SATURATED values actually applied, so the law never integrates an error it cannot act on:
//   u(k) = sat( sum t_i uc(k-i) - sum s_i y(k-i) - sum_{i>=1} r_i u_sat(k-i) ).
// Designs may change every sample (adaptive); the signal histories carry over.
#include <deque>

#include "control/polynomial.h"

namespace mx {

class RstController {
 public:
  RstController(double u_min, double u_max);  // InvalidInput unless finite and u_min < u_max

  // R monic, deg S <= deg R, deg T <= deg R; InvalidInput otherwise (the previous design is kept).
  void setDesign(const Poly& R, const Poly& S, const Poly& T);
  bool hasDesign() const { return !R_.empty(); }
  // One sample: returns the saturated control. Without a design, or if the law evaluates to a non-finite value,
  // the previous applied control is held (u_min at the start).
  double step(double reference, double measurement);
  void reset();

  double lastUnsaturated() const { return last_v_; }
  bool lastSaturated() const { return last_saturated_; }
  double uMin() const { return u_min_; }
  double uMax() const { return u_max_; }

 private:
  double u_min_, u_max_;
  Poly R_, S_, T_;                 // padded to deg R + 1
  std::deque<double> uc_, y_, u_;  // most recent first
  double last_v_ = 0.0;
  bool last_saturated_ = false;
};

}  // namespace mx
