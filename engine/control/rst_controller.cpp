#include "control/rst_controller.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {
constexpr std::size_t kHistory = 16;

Poly padFront(const Poly& p, std::size_t size) {
  Poly out(size, 0.0);
  std::copy(p.begin(), p.end(), out.begin() + static_cast<std::ptrdiff_t>(size - p.size()));
  return out;
}

void push(std::deque<double>& h, double v) {
  h.push_front(v);
  if (h.size() > kHistory) h.pop_back();
}

double at(const std::deque<double>& h, std::size_t i) {
  return i < h.size() ? h[i] : 0.0;
}
}  // namespace

RstController::RstController(double u_min, double u_max) : u_min_(u_min), u_max_(u_max) {
  if (!std::isfinite(u_min) || !std::isfinite(u_max) || !(u_min < u_max))
    throw InvalidInput("RST controller: feed limits [" + std::to_string(u_min) + ", " + std::to_string(u_max) +
                       "]: must be finite with min < max");
}

void RstController::setDesign(const Poly& R_in, const Poly& S_in, const Poly& T_in) {
  const Poly R = polyTrim(R_in), S = polyTrim(S_in), T = polyTrim(T_in);
  if (R.empty() || R[0] != 1.0) throw InvalidInput("RST controller: R must be monic");
  const std::size_t nr = R.size() - 1;
  if (nr + 1 > kHistory) throw InvalidInput("RST controller: deg R = " + std::to_string(nr) + ": must be < 16");
  if (S.size() > nr + 1 || T.size() > nr + 1)
    throw InvalidInput("RST controller: deg S = " + std::to_string(static_cast<int>(S.size()) - 1) + ", deg T = " +
                       std::to_string(static_cast<int>(T.size()) - 1) + ": must be <= deg R = " + std::to_string(nr));
  const auto finite = [](const Poly& p) {
    return std::all_of(p.begin(), p.end(), [](double c) { return std::isfinite(c); });
  };
  if (!finite(R) || !finite(S) || !finite(T))
    throw InvalidInput("RST controller: non-finite coefficients: must be finite");
  R_ = R;
  S_ = padFront(S, nr + 1);
  T_ = padFront(T, nr + 1);
}

double RstController::step(double reference, double measurement) {
  push(uc_, reference);
  push(y_, measurement);
  const double previous = u_.empty() ? u_min_ : u_.front();
  double v = previous;
  if (hasDesign()) {
    v = 0.0;
    for (std::size_t i = 0; i < R_.size(); ++i) v += T_[i] * at(uc_, i) - S_[i] * at(y_, i);
    for (std::size_t i = 1; i < R_.size(); ++i) v -= R_[i] * at(u_, i - 1);
    if (!std::isfinite(v)) v = previous;
  }
  last_v_ = v;
  const double u = std::clamp(v, u_min_, u_max_);
  last_saturated_ = u != v;
  push(u_, u);
  return u;
}

void RstController::reset() {
  uc_.clear();
  y_.clear();
  u_.clear();
  last_v_ = 0.0;
  last_saturated_ = false;
}

}  // namespace mx
