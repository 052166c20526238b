#include "simulation/smith_tlusty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

namespace {

constexpr double kRelativeSlack = 1e-12;  // speeds that hit a range limit up to roundoff count as inside
constexpr double kMaxK = 1e9;

void require(bool ok, const char* quantity, double value, const char* range) {
  if (ok) return;
  std::ostringstream message;
  message << "smithTlustySpeed: " << quantity << " = " << value << " is outside the allowed range " << range;
  throw InvalidInput(message.str());
}

}  // namespace

std::optional<SmithTlustyChoice> smithTlustyChoice(double chatter_hz, int teeth, double current_rev_per_s,
                                                   double min_rev_per_s, double max_rev_per_s) {
  require(std::isfinite(chatter_hz) && chatter_hz > 0.0, "chatter frequency [Hz]", chatter_hz, "(0, inf)");
  require(teeth >= 1, "teeth", teeth, "[1, inf)");
  require(std::isfinite(current_rev_per_s) && current_rev_per_s > 0.0, "current speed [rev/s]", current_rev_per_s,
          "(0, inf)");
  require(std::isfinite(min_rev_per_s) && min_rev_per_s >= 0.0, "minimum speed [rev/s]", min_rev_per_s, "[0, inf)");
  require(!std::isnan(max_rev_per_s) && max_rev_per_s >= min_rev_per_s, "maximum speed [rev/s]", max_rev_per_s,
          "[minimum speed, inf]");

  // N_k = f_c / (n_t k) decreases with k: N_k <= max <=> k >= q / max, N_k >= min <=> k <= q / min.
  const double q = chatter_hz / teeth;
  const double k_lo = std::max(1.0, std::ceil(q / max_rev_per_s * (1.0 - kRelativeSlack)));
  const double k_hi =
      min_rev_per_s > 0.0 ? std::min(kMaxK, std::floor(q / min_rev_per_s * (1.0 + kRelativeSlack))) : kMaxK;
  if (k_lo > k_hi) return std::nullopt;

  // |N_k - N| is unimodal in k: the nearest is at floor or ceil of k* = q / N, clamped to the range.
  const double k_star = q / current_rev_per_s;
  double best_k = 0.0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (double candidate : {std::floor(k_star), std::ceil(k_star)}) {
    const double k = std::clamp(candidate, k_lo, k_hi);
    const double distance = std::abs(q / k - current_rev_per_s);
    if (distance < best_distance || (distance == best_distance && k < best_k)) {
      best_distance = distance;
      best_k = k;
    }
  }
  const double speed = std::clamp(q / best_k, min_rev_per_s, max_rev_per_s);
  return SmithTlustyChoice{speed, static_cast<int>(best_k)};
}

std::optional<double> smithTlustySpeed(double chatter_hz, int teeth, double current_rev_per_s, double min_rev_per_s,
                                       double max_rev_per_s) {
  const auto choice = smithTlustyChoice(chatter_hz, teeth, current_rev_per_s, min_rev_per_s, max_rev_per_s);
  if (!choice) return std::nullopt;
  return choice->rev_per_s;
}

}  // namespace mx
