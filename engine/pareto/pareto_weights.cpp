#include "pareto/pareto_weights.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

namespace {
std::string describe(const ParetoWeights& w) {
  std::ostringstream os;
  os << "w = [" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3] << "]";
  return os.str();
}
}  // namespace

void validateParetoWeights(const ParetoWeights& w) {
  double sum = 0.0;
  for (double v : w) {
    if (!(std::isfinite(v) && v >= 0.0)) throw InvalidInput(describe(w) + ": every weight must be >= 0 and finite");
    sum += v;
  }
  if (std::abs(sum - 1.0) > kParetoWeightTolerance)
    throw InvalidInput(describe(w) + ": the weights (TOL, MRR, SURF, ROS) must sum to 1");
}

bool onSimplex(const ParetoWeights& w, double tolerance) {
  double sum = 0.0;
  for (double v : w) {
    if (!(std::isfinite(v) && v >= -tolerance)) return false;
    sum += v;
  }
  return std::abs(sum - 1.0) <= tolerance;
}

ParetoWeights renormaliseBySum(ParetoWeights w) {
  double sum = 0.0;
  for (double& v : w) {
    if (!(std::isfinite(v) && v > 0.0)) v = 0.0;
    sum += v;
  }
  if (!(sum > 0.0)) {
    w.fill(1.0 / static_cast<double>(kObjectiveCount));
    return w;
  }
  for (double& v : w) v /= sum;
  return w;
}

ParetoWeights renormaliseKeeping(ParetoWeights w, Objective changed) {
  const std::size_t k = index(changed);
  const double wk = std::isfinite(w[k]) ? std::clamp(w[k], 0.0, 1.0) : 0.0;
  double others = 0.0;
  for (std::size_t i = 0; i < kObjectiveCount; ++i) {
    if (i == k) continue;
    if (!(std::isfinite(w[i]) && w[i] > 0.0)) w[i] = 0.0;
    others += w[i];
  }
  for (std::size_t i = 0; i < kObjectiveCount; ++i) {
    if (i == k) continue;
    w[i] = others > 0.0 ? (1.0 - wk) * w[i] / others : (1.0 - wk) / static_cast<double>(kObjectiveCount - 1);
  }
  w[k] = wk;
  return w;
}

ParetoWeights withWeight(const ParetoWeights& w, Objective k, double value) {
  ParetoWeights out = w;
  out[index(k)] = value;
  return renormaliseKeeping(out, k);
}

double objectiveJ(const ParetoWeights& w, const ObjectiveVector& scores) {
  double j = 0.0;
  for (std::size_t i = 0; i < kObjectiveCount; ++i) j += w[i] * scores[i];
  return j;
}

}  // namespace mx
