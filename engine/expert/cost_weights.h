#pragma once
// Weight vectors of the 2006 cost functions: c = (c1, c2, c3) of the tool cost C (eq. 13),
// c_r = (c1r, c2r, c3r) of C_resultant (eq. 20), c_t (eq. 18) and c_f (eq. 19). Each lies on the
// simplex: non-negative and summing to 1 (within 1e-6).
#include <array>
#include <string>
#include <vector>

namespace mx {

inline constexpr double kWeightSumTolerance = 1e-6;

// Throws InvalidInput naming `name`, the values and the violated condition (wrong count, negative,
// or a sum that differs from 1 by more than kWeightSumTolerance).
void validateSimplexWeights(const std::string& name, const std::vector<double>& values, std::size_t count);

struct CostWeights {
  std::array<double, 3> c{0.2, 0.725, 0.075};  // power, MRR, Delta N_s (eq. 13)
  std::array<double, 3> cr{0.8, 0.1, 0.1};     // C, C_t, C_f (eq. 20)
  std::array<double, 2> ct{0.5, 0.5};          // t_s, M_p (eq. 18)
  std::array<double, 2> cf{0.5, 0.5};          // R12h, R1ch (eq. 19)

  void validate() const;  // all four on the simplex, else InvalidInput
};

// One step of Rule 6: c2 <- 0.99 c2, c3 <- c3 + 0.01 c2 (the printed "0.01 c1" read as a typo, see
// shared/notes/seed-reading.md), then divide by the sum so that the weights stay on the simplex.
std::array<double, 3> malfunctionStep(const std::array<double, 3>& c);

}  // namespace mx
