#include "expert/cost_weights.h"

#include <cmath>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

namespace {
std::string listOf(const std::vector<double>& values) {
  std::ostringstream s;
  s << '[';
  for (std::size_t i = 0; i < values.size(); ++i) s << (i ? ", " : "") << values[i];
  s << ']';
  return s.str();
}
}  // namespace

void validateSimplexWeights(const std::string& name, const std::vector<double>& values, std::size_t count) {
  std::ostringstream msg;
  if (values.size() != count) {
    msg << name << " = " << listOf(values) << ": must have " << count << " weights";
    throw InvalidInput(msg.str());
  }
  double sum = 0.0;
  for (double v : values) {
    if (!std::isfinite(v) || v < 0.0) {
      msg << name << " = " << listOf(values) << ": weights must be finite and >= 0";
      throw InvalidInput(msg.str());
    }
    sum += v;
  }
  if (std::abs(sum - 1.0) > kWeightSumTolerance) {
    msg.precision(10);
    msg << name << " = " << listOf(values) << ": weights must sum to 1 (within 1e-6), sum = " << sum;
    throw InvalidInput(msg.str());
  }
}

void CostWeights::validate() const {
  validateSimplexWeights("c", {c.begin(), c.end()}, 3);
  validateSimplexWeights("cr", {cr.begin(), cr.end()}, 3);
  validateSimplexWeights("ct", {ct.begin(), ct.end()}, 2);
  validateSimplexWeights("cf", {cf.begin(), cf.end()}, 2);
}

std::array<double, 3> malfunctionStep(const std::array<double, 3>& c) {
  std::array<double, 3> next{c[0], 0.99 * c[1], c[2] + 0.01 * c[1]};
  const double sum = next[0] + next[1] + next[2];
  for (double& v : next) v /= sum;
  return next;
}

}  // namespace mx
