#include "gcode/arc_geometry.h"

#include <cmath>
#include <numbers>

namespace mx::arc {

double sweep(double a0, double a1, bool clockwise, bool full) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  if (full) return two_pi;
  double d = clockwise ? a0 - a1 : a1 - a0;
  while (d <= 0.0) d += two_pi;
  while (d > two_pi) d -= two_pi;
  return d;
}

double length(const Point& s, const Point& e, const Point& c, bool clockwise) {
  const double r0 = std::hypot(s[0] - c[0], s[1] - c[1]);
  const double r1 = std::hypot(e[0] - c[0], e[1] - c[1]);
  const bool full = std::hypot(e[0] - s[0], e[1] - s[1]) < 1e-9;
  const double angle =
      sweep(std::atan2(s[1] - c[1], s[0] - c[0]), std::atan2(e[1] - c[1], e[0] - c[0]), clockwise, full);
  return 0.5 * (r0 + r1) * angle;
}

std::optional<Point> centreFromRadius(const Point& s, const Point& e, double radius, bool clockwise) {
  const double dx = e[0] - s[0], dy = e[1] - s[1];
  const double chord = std::hypot(dx, dy);
  const double r = std::abs(radius);
  if (!(chord > 1e-12) || chord > 2.0 * r * (1.0 + 1e-9)) return std::nullopt;
  const double h = std::sqrt(std::max(0.0, r * r - 0.25 * chord * chord));
  // The centre of a counter-clockwise arc of at most half a turn lies left of the chord.
  const double side = (clockwise ? -1.0 : 1.0) * (radius > 0.0 ? 1.0 : -1.0);
  const double nx = -dy / chord, ny = dx / chord;
  return Point{s[0] + 0.5 * dx + side * h * nx, s[1] + 0.5 * dy + side * h * ny};
}

std::optional<TangentArc> tangentArc(const Point& s, const Point& e, const Point& t) {
  const double cx = e[0] - s[0], cy = e[1] - s[1];
  const double chord2 = cx * cx + cy * cy;
  const double cross = t[0] * cy - t[1] * cx;  // > 0: the end lies left of the tangent (counter-clockwise)
  if (!(chord2 > 1e-24) || std::abs(cross) < 1e-9 * std::sqrt(chord2)) return std::nullopt;
  const double rho = chord2 / (2.0 * cross);  // signed distance of the centre along the left normal
  TangentArc a;
  a.centre = {s[0] - t[1] * rho, s[1] + t[0] * rho};
  a.radius = std::abs(rho);
  a.clockwise = cross < 0.0;
  const double dot = t[0] * cx + t[1] * cy;
  a.length = a.radius * 2.0 * std::atan2(std::abs(cross), dot);
  return a;
}

}  // namespace mx::arc
