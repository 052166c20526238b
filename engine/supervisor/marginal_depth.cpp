#include "supervisor/marginal_depth.h"

#include <cmath>
#include <string>

namespace mx {

namespace {
void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (!ok) throw InvalidInput("marginal depth: " + field + " = " + std::to_string(value) + ": must be " + range);
}
}  // namespace

void validateMarginalDepthSettings(const MarginalDepthSettings& s) {
  require(std::isfinite(s.depth_low_m) && s.depth_low_m > 0.0, "depth_low_m", s.depth_low_m, "> 0");
  require(std::isfinite(s.depth_high_m) && s.depth_high_m > s.depth_low_m, "depth_high_m", s.depth_high_m,
          "> depth_low_m");
  require(std::isfinite(s.tolerance_m) && s.tolerance_m > 0.0, "tolerance_m", s.tolerance_m, "> 0");
  require(std::isfinite(s.feed_per_tooth_m) && s.feed_per_tooth_m > 0.0, "feed_per_tooth_m", s.feed_per_tooth_m, "> 0");
  require(s.revolutions >= 2 && s.revolutions <= 10000, "revolutions", s.revolutions, "in [2, 10000]");
  require(s.tail_revolutions >= 1 && s.tail_revolutions < s.revolutions, "tail_revolutions", s.tail_revolutions,
          "in [1, revolutions)");
  require(std::isfinite(s.threshold) && s.threshold > 0.0, "threshold", s.threshold, "> 0");
}

MarginalDepthSearch::MarginalDepthSearch(const FaceMillingParameters& process, MarginalDepthSettings settings)
    : p_(process), s_(settings) {
  validateMarginalDepthSettings(s_);
  p_.part_start_x_m = -10.0;  // a long part: the tool is in the full cut from t = 0
  p_.part_length_m = 20.0;
  validateFaceMillingParameters(p_);
}

DepthTrial MarginalDepthSearch::trial(double depth_m) const {
  require(std::isfinite(depth_m) && depth_m > 0.0, "depth_m", depth_m, "> 0");
  FaceMillingProcess proc(p_);
  proc.setDepth(depth_m);
  proc.setFeedRate(s_.feed_per_tooth_m * p_.teeth / proc.spindlePeriod());
  proc.reset(0.0);
  const auto per_rev = std::llround(proc.spindlePeriod() / proc.stepSize());
  const long long total = per_rev * s_.revolutions, tail_from = per_rev * (s_.revolutions - s_.tail_revolutions);
  double sum2 = 0.0;
  long long n = 0;
  for (long long k = 0; k < total; ++k) {
    proc.step();
    if (k >= tail_from) {
      sum2 += proc.output().regen_m * proc.output().regen_m;
      ++n;
    }
  }
  DepthTrial t;
  t.depth_m = depth_m;
  t.indicator = std::sqrt(sum2 / static_cast<double>(n)) / s_.feed_per_tooth_m;
  t.chatter = t.indicator > s_.threshold;
  return t;
}

MarginalDepthResult MarginalDepthSearch::search(const JobControl& job) const {
  MarginalDepthResult r;
  double lo = s_.depth_low_m, hi = s_.depth_high_m;
  const DepthTrial a = trial(lo);
  r.trials.push_back(a);
  const DepthTrial b = trial(hi);
  r.trials.push_back(b);
  r.bracketed = !a.chatter && b.chatter;
  if (!r.bracketed) {
    r.stable_depth_m = a.chatter ? 0.0 : hi;
    r.unstable_depth_m = a.chatter ? lo : hi;
    r.marginal_depth_m = a.chatter ? lo : hi;
    return r;
  }
  const double steps = std::max(1.0, std::ceil(std::log2((hi - lo) / s_.tolerance_m)));
  int done = 0;
  while (hi - lo > s_.tolerance_m) {
    if (job.cancelled()) throw Cancelled();
    const DepthTrial t = trial(0.5 * (lo + hi));
    r.trials.push_back(t);
    (t.chatter ? hi : lo) = t.depth_m;
    job.report(std::min(1.0, ++done / steps));
  }
  r.stable_depth_m = lo;
  r.unstable_depth_m = hi;
  r.marginal_depth_m = 0.5 * (lo + hi);
  return r;
}

}  // namespace mx
