#pragma once
// Ring buffer of the tool's past displacements and velocities on the uniform grid t_i = i dt, with
// cubic Hermite interpolation between samples (used for the delayed term x(t - T) of eq. 7).
// Samples before t = 0 are the rigid pre-history: zero displacement and velocity.
#include <cmath>
#include <cstdint>
#include <vector>

namespace mx {

struct AxisSample {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
};

struct AxisPosition {
  double x = 0.0, y = 0.0;
};

class DelayHistory {
 public:
  // Keeps at least max_lookback samples behind the newest one.
  DelayHistory(double dt_s, std::int64_t max_lookback);

  void push(const AxisSample& sample) {
    buffer_[static_cast<std::size_t>(count_ & mask_)] = sample;
    ++count_;
  }
  std::int64_t size() const { return count_; }  // samples pushed; the newest has index size() - 1
  double dt() const { return dt_; }

  // Sample i (i < 0: pre-history). Requires size() - capacity < i < size().
  AxisSample at(std::int64_t i) const { return i < 0 ? AxisSample{} : buffer_[static_cast<std::size_t>(i & mask_)]; }
  AxisPosition position(std::int64_t i) const {
    const AxisSample s = at(i);
    return {s.x, s.y};
  }

  // Hermite value half-way between samples i and i + 1: p = (p0 + p1)/2 + dt (v0 - v1)/8.
  AxisPosition midpoint(std::int64_t i) const {
    const AxisSample a = at(i);
    const AxisSample b = at(i + 1);
    const double c = 0.125 * dt_;
    return {0.5 * (a.x + b.x) + c * (a.vx - b.vx), 0.5 * (a.y + b.y) + c * (a.vy - b.vy)};
  }

  // Hermite value at time t = u dt (u may be fractional; needs floor(u) + 1 < size()).
  AxisPosition interpolate(double u) const {
    const double fl = std::floor(u);
    const auto i = static_cast<std::int64_t>(fl);
    const double s = u - fl;
    const AxisSample a = at(i);
    const AxisSample b = at(i + 1);
    // Cubic Hermite basis: h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = 1 - h00, h11 = s^3 - s^2.
    const double s2 = s * s;
    const double s3 = s2 * s;
    const double h01 = 3.0 * s2 - 2.0 * s3;
    const double h10 = (s3 - 2.0 * s2 + s) * dt_;
    const double h11 = (s3 - s2) * dt_;
    return {a.x + h01 * (b.x - a.x) + h10 * a.vx + h11 * b.vx, a.y + h01 * (b.y - a.y) + h10 * a.vy + h11 * b.vy};
  }

  std::int64_t capacity() const { return mask_ + 1; }

 private:
  double dt_;
  std::int64_t mask_ = 0;
  std::int64_t count_ = 0;
  std::vector<AxisSample> buffer_;
};

}  // namespace mx
