#pragma once
// Chatter suppression by spindle speed selection (Smith & Tlusty 1992; Pareto paper, Rule 16): run so
// that the tooth-passing frequency is the chatter frequency divided by an integer k >= 1,
//   N = f_c / (n_t k)  [rev/s]  (N = 60 f_c / (n_t k) rpm),
// taking the k whose speed is nearest the current one inside the machine's speed range.
#include <optional>

namespace mx {

struct SmithTlustyChoice {
  double rev_per_s = 0.0;
  int k = 0;  // number of whole chatter waves per tooth period
};

// min_rev_per_s >= 0, max_rev_per_s >= min (may be +inf). Ties go to the higher speed (smaller k).
// nullopt when no N = f_c / (n_t k) lies in [min, max]. Throws InvalidInput for invalid arguments.
std::optional<SmithTlustyChoice> smithTlustyChoice(double chatter_hz, int teeth, double current_rev_per_s,
                                                   double min_rev_per_s, double max_rev_per_s);

std::optional<double> smithTlustySpeed(double chatter_hz, int teeth, double current_rev_per_s, double min_rev_per_s,
                                       double max_rev_per_s);

}  // namespace mx
