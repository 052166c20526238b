#include "expert/simulation_cache.h"

#include "core/parallel_for.h"
#include "simulation/milling_simulation.h"

namespace mx {

ResponseMetrics SimulationCache::simulate(const Request& r) const {
  SimulationOptions options;
  options.revolutions = settings_.revolutions;
  options.evaluated_revolutions = settings_.evaluated_revolutions;
  options.record_every = 1;
  const SimulationResult result = simulateMilling(*r.setup, r.point, options);
  return responseMetrics(*r.setup, r.point, result, settings_.evaluated_revolutions);
}

std::vector<ResponseMetrics> SimulationCache::evaluate(const std::vector<Request>& requests) {
  std::vector<Request> missing;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::map<Key, bool> queued;
    for (const Request& r : requests) {
      const Key key = keyOf(r);
      if (cache_.count(key) == 0 && !queued[key]) {
        queued[key] = true;
        missing.push_back(r);
      }
    }
  }
  std::vector<ResponseMetrics> computed(missing.size());
  parallelFor(missing.size(), settings_.threads, [&](std::size_t i) { computed[i] = simulate(missing[i]); });
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t i = 0; i < missing.size(); ++i) cache_[keyOf(missing[i])] = computed[i];
  runs_ += missing.size();
  std::vector<ResponseMetrics> out;
  out.reserve(requests.size());
  for (const Request& r : requests) out.push_back(cache_.at(keyOf(r)));
  return out;
}

std::size_t SimulationCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return cache_.size();
}

std::size_t SimulationCache::simulationsRun() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return runs_;
}

}  // namespace mx
