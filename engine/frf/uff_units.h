#pragma once
// SI factors for the units labels of universal-file dataset 58 records 8-10 (UC-SDRL description of
// dataset 58: each record carries a units label and length/force/temperature exponents). The labels
// decide the factor; the exponents only matter with a dataset 164 unit system, which is not read.
// Labels are compared case-insensitively without blanks, with "**" and "\u00b2" read as "^" and "^2",
// "sec" as "s". An empty label or "NONE" means SI. Recognised:
//   length  m (1), mm (1e-3), um / \u00b5m / micron (1e-6), in (0.0254)
//   displacement  <length>;  velocity  <length>/s;  acceleration  <length>/s^2 (or /s2), and any
//   label containing "g" is standard gravity, 9.80665 m/s^2
//   force  N (1), kN (1e3), lbf / lb / lbs (4.4482216152605, the avoirdupois pound-force)
//   frequency  Hz (1)
//   time  s (1), ms (1e-3)
#include <optional>
#include <string>
#include <string_view>

#include "frf/frf_dataset.h"

namespace mx {

// The label in the compared form (lower case, no blanks, "^" powers, "s" for seconds).
std::string normaliseUnitsLabel(std::string_view label);

// Factor taking a value in the labelled unit of `quantity`'s numerator to SI; nullopt if not recognised.
std::optional<double> numeratorUnitsToSi(FrfQuantity quantity, std::string_view label);
// Factor taking a force in the labelled unit to newtons; nullopt if not recognised.
std::optional<double> forceUnitsToSi(std::string_view label);
// Factor taking a frequency in the labelled unit to Hz; nullopt if not recognised.
std::optional<double> frequencyUnitsToHz(std::string_view label);
// Factor taking a time in the labelled unit to seconds; nullopt if not recognised.
std::optional<double> timeUnitsToSeconds(std::string_view label);

}  // namespace mx
