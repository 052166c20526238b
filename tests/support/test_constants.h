#pragma once
// Test helper: the constants that many test files use.
#include <limits>
#include <numbers>

namespace mx::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = kPi / 180.0;  // radians per degree
// The quiet NaN that a computation reports for "none" and a view must never show as a number.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace mx::test
