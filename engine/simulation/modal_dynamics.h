#pragma once
// The tool's structural dynamics in modal coordinates (2006, eq. 1, extended to several modes per axis):
//   q_r'' + 2 zeta_r w_r q_r' + w_r^2 q_r = (w_r^2 / k_r) F_axis(r),   x = sum_{r in X} q_r, y = sum_{r in Y} q_r.
// State layout: [q_0 .. q_{M-1}, q_0' .. q_{M-1}'], the x-modes first. An empty axis is rigid.
#include <vector>

#include "model/milling_setup.h"

namespace mx {

class ModalDynamics {
 public:
  explicit ModalDynamics(const MillingSetup& setup);

  int modeCount() const { return static_cast<int>(damping_.size()); }
  int stateSize() const { return 2 * modeCount(); }
  int xModeCount() const { return x_modes_; }
  double highestFrequencyHz() const { return highest_hz_; }

  // Initial state: released from displacement (x0, y0) at rest, split like a static deflection.
  std::vector<double> initialState(double x0_m, double y0_m) const;

  // Displacements and velocities of the two axes.
  void axes(const double* state, double& x, double& y) const {
    const int m = modeCount();
    x = 0.0;
    y = 0.0;
    for (int r = 0; r < x_modes_; ++r) x += state[r];
    for (int r = x_modes_; r < m; ++r) y += state[r];
  }
  void axisVelocities(const double* state, double& vx, double& vy) const { axes(state + modeCount(), vx, vy); }

  // d(state)/dt for the forces (fx, fy) acting on the tool.
  void derivative(const double* state, double fx, double fy, double* out) const {
    const int m = modeCount();
    const double* q = state;
    const double* qd = state + m;
    for (int r = 0; r < m; ++r) {
      const double f = r < x_modes_ ? fx : fy;
      out[r] = qd[r];
      out[m + r] = gain_[r] * f - damping_[r] * qd[r] - stiffness_[r] * q[r];
    }
  }

 private:
  int x_modes_ = 0;
  double highest_hz_ = 0.0;
  std::vector<double> damping_;     // 2 zeta w
  std::vector<double> stiffness_;   // w^2
  std::vector<double> gain_;        // w^2 / k = 1 / m_modal
  std::vector<double> compliance_;  // 1 / k
};

}  // namespace mx
