#pragma once
// Time-domain simulations of candidate points for Rule 5 and Rule 6, run in parallel (std::thread
// workers, one per core unless told otherwise) and cached: a point is simulated once per session, so a
// weight change re-uses every simulation already done. Only the ResponseMetrics are kept.
#include <cstddef>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "expert/expert_settings.h"
#include "expert/response_metrics.h"
#include "model/milling_setup.h"

namespace mx {

class SimulationCache {
 public:
  explicit SimulationCache(const RefinementSettings& settings) : settings_(settings) {}

  struct Request {
    std::size_t tool = 0;  // the cache key is (tool, N, b, s_t), exactly
    const MillingSetup* setup = nullptr;
    OperatingPoint point;
  };

  // Metrics of every request, in order; the uncached ones are simulated in parallel first.
  // Exceptions of a simulation are rethrown after all workers finished.
  std::vector<ResponseMetrics> evaluate(const std::vector<Request>& requests);

  std::size_t size() const;
  std::size_t simulationsRun() const;  // total simulations run by this cache

 private:
  using Key = std::tuple<std::size_t, double, double, double>;
  static Key keyOf(const Request& r) {
    return {r.tool, r.point.spindle_rev_per_s, r.point.axial_depth_m, r.point.feed_per_tooth_m};
  }
  ResponseMetrics simulate(const Request& request) const;

  RefinementSettings settings_;
  mutable std::mutex mutex_;
  std::map<Key, ResponseMetrics> cache_;
  std::size_t runs_ = 0;
};

}  // namespace mx
