#pragma once
// Test helper: the constants that many test files use.
#include <limits>
#include <numbers>

namespace mx::test {

inline constexpr double kPi = std::numbers::pi;
// The quiet NaN that a computation reports for "none" and a view must never show as a number.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace mx::test
