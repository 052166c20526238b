#pragma once
// Plane arc geometry shared by the dialect interpreters: ISO centre offsets (I, J), radius arcs
// (Sinumerik CR=, Heidenhain CR) and tangential arcs (Heidenhain CT).
#include <array>
#include <optional>

namespace mx::arc {

using Point = std::array<double, 2>;

// Swept angle (0, 2π] from angle a0 to a1 in the given sense; full: a whole turn.
double sweep(double a0, double a1, bool clockwise, bool full);
// The arc's length in the plane from start to end about centre (radius averaged over both ends).
double length(const Point& start, const Point& end, const Point& centre, bool clockwise);
// The centre of the arc of this radius from start to end: radius > 0 sweeps at most half a turn,
// radius < 0 more. nullopt when the chord is longer than the diameter (or zero).
std::optional<Point> centreFromRadius(const Point& start, const Point& end, double radius, bool clockwise);

struct TangentArc {
  Point centre{};
  double radius = 0.0;
  double length = 0.0;  // in the plane
  bool clockwise = false;
};
// The arc leaving start along the unit tangent and ending at end; nullopt when end lies on the tangent
// line (the move is straight).
std::optional<TangentArc> tangentArc(const Point& start, const Point& end, const Point& tangent);

}  // namespace mx::arc
