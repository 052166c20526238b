#include "control/beta_sweep.h"

#include <atomic>
#include <cmath>
#include <string>

#include "core/parallel_for.h"

namespace mx {

std::vector<double> betaGrid(double from, double to, double step) {
  if (!(from >= -1.0 && from <= to && to <= 1.0))
    throw InvalidInput("beta sweep: [from, to] = [" + std::to_string(from) + ", " + std::to_string(to) +
                       "]: must satisfy -1 <= from <= to <= 1");
  if (!(step > 0.0) || !std::isfinite(step))
    throw InvalidInput("beta sweep: step = " + std::to_string(step) + ": must be finite and > 0");
  const double span = (to - from) / step;
  if (span > 100000.0) throw InvalidInput("beta sweep: " + std::to_string(span) + " points: must be <= 100000");
  const long n = static_cast<long>(std::floor(span + 1e-9));
  std::vector<double> grid;
  for (long i = 0; i <= n; ++i) {
    double b = std::min(to, from + static_cast<double>(i) * step);
    if (std::abs(b) < 1e-9 * step) b = 0.0;  // beta = 0 exactly: the ZOH model structure (eq. 30), not 1e-16
    grid.push_back(b);
  }
  if (to - grid.back() > 1e-9 * std::max(1.0, step)) grid.push_back(to);
  return grid;
}

BetaSweepResult sweepBeta(const AdaptiveControlSettings& base, const BetaSweepSettings& sweep, const JobControl& job) {
  validateAdaptiveControlSettings(base);
  BetaSweepResult r;
  r.beta = betaGrid(sweep.from, sweep.to, sweep.step);
  const std::size_t n = r.beta.size();
  r.Jc_N_s.assign(n, 0.0);
  r.max_force_N.assign(n, 0.0);
  r.Jc_model_N_s.assign(n, 0.0);
  r.max_zero_modulus.assign(n, 0.0);
  std::vector<char> unstable(n, 0), completed(n, 0);
  std::atomic<std::size_t> done{0};
  parallelFor(n, sweep.threads, [&](std::size_t i) {
    if (job.cancelled()) throw Cancelled();
    AdaptiveControlSettings s = base;
    s.beta = r.beta[i];
    JobControl inner;
    inner.cancel = job.cancel;
    const ClosedLoopResult run = simulateAdaptiveForceControl(s, inner);
    r.Jc_N_s[i] = run.metrics.Jc_N_s;
    r.Jc_model_N_s[i] = run.metrics.Jc_model_N_s;
    r.max_force_N[i] = run.metrics.max_force_N;
    r.max_zero_modulus[i] = run.metrics.max_zero_modulus;
    unstable[i] = run.metrics.unstable_zero;
    completed[i] = run.metrics.completed;
    job.report(static_cast<double>(++done) / static_cast<double>(n));  // progress may arrive from any worker
  });
  r.unstable_zero.assign(unstable.begin(), unstable.end());
  r.completed.assign(completed.begin(), completed.end());
  for (std::size_t i = 0; i < n; ++i) {
    if (r.unstable_zero[i] || !r.completed[i]) continue;
    if (!r.found || r.Jc_N_s[i] < r.best_Jc_N_s) {
      r.found = true;
      r.best_beta = r.beta[i];
      r.best_Jc_N_s = r.Jc_N_s[i];
    }
  }
  return r;
}

}  // namespace mx
