#include "control/closed_loop.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "control/rst_controller.h"
#include "control/sampled_reference_model.h"
#include "control/zero_threshold.h"
#include "pareto/sampling_time.h"

namespace mx {

namespace {

[[noreturn]] void bad(const std::string& field, double value, const std::string& range) {
  throw InvalidInput("adaptive control: " + field + " = " + std::to_string(value) + ": must be " + range);
}

// The period that starts now: one spindle period, or Rule 4 of the Pareto paper (k periods while the programmed
// N and b stay constant, one after a change).
class SamplePeriodClock {
 public:
  explicit SamplePeriodClock(const AdaptiveControlSettings& s)
      : rule_(s.sample_period), selector_(SamplingTimeSettings{s.rule4_periods, 1e-9}) {}
  double next(double spindle_rev_s, double depth_m) {
    return rule_ == SamplePeriodRule::Rule4 ? selector_.update(spindle_rev_s, depth_m) : 1.0 / spindle_rev_s;
  }

 private:
  SamplePeriodRule rule_;
  SamplingTimeSelector selector_;
};

double fastestSpindlePeriod(const AdaptiveControlSettings& s) {
  double T = spindlePeriod(s.process);
  for (const auto& step : s.workpiece.steps) T = std::min(T, spindlePeriod(stepProcess(s.process, step)));
  return T;
}

// One sample per spindle period for at most max_time_s: bounded before anything is allocated, in
// floating point so that a huge speed cannot overflow the count.
int sampleBudget(const AdaptiveControlSettings& s) {
  const double periods = std::ceil(s.max_time_s / fastestSpindlePeriod(s)) + 1.0;
  if (!(periods <= kMaxClosedLoopSamples)) {
    std::ostringstream message;
    message << "the closed loop would sample " << periods << " spindle periods (max_time_s = " << s.max_time_s
            << " s at the fastest spindle speed): at most " << kMaxClosedLoopSamples
            << "; lower the spindle speed or max_time_s";
    throw InvalidInput(message.str());
  }
  return static_cast<int>(periods);
}

double lagged(const std::vector<double>& v, std::size_t k, std::size_t lag) {
  return k >= lag ? v[k - lag] : 0.0;
}

}  // namespace

void validateAdaptiveControlSettings(const AdaptiveControlSettings& s) {
  validateCuttingProcess(s.process);
  validateControlWorkpiece(s.workpiece);
  validateRlsSettings(s.rls);
  validatePolePlacementSettings(s.design);
  if (!(s.force_reference_N > 0.0) || !std::isfinite(s.force_reference_N))
    bad("force_reference_N", s.force_reference_N, "finite and > 0");
  if (!(s.feed_max_m_s > 0.0) || !std::isfinite(s.feed_max_m_s)) bad("feed_max_m_s", s.feed_max_m_s, "finite and > 0");
  if (!(s.beta >= -1.0 && s.beta <= 1.0)) bad("beta", s.beta, "in [-1, 1]");
  if (!(s.damping_ratio > 0.0 && s.damping_ratio <= 5.0)) bad("damping_ratio", s.damping_ratio, "in (0, 5]");
  if (!(s.rise_time_periods >= 0.5 && s.rise_time_periods <= 1000.0))
    bad("rise_time_periods", s.rise_time_periods, "in [0.5, 1000]");
  if (!(s.control_force_unit_N > 0.0) || !std::isfinite(s.control_force_unit_N))
    bad("control_force_unit_N", s.control_force_unit_N, "finite and > 0");
  if (!(s.control_feed_unit_m_s > 0.0) || !std::isfinite(s.control_feed_unit_m_s))
    bad("control_feed_unit_m_s", s.control_feed_unit_m_s, "finite and > 0");
  if (s.dense_points_per_sample < 1 || s.dense_points_per_sample > 10000)
    bad("dense_points_per_sample", s.dense_points_per_sample, "in [1, 10000]");
  if (!(s.rtol >= 1e-13 && s.rtol <= 1e-4)) bad("rtol", s.rtol, "in [1e-13, 1e-4]");
  if (!(s.max_time_s > 0.0 && s.max_time_s <= 3600.0)) bad("max_time_s", s.max_time_s, "in (0, 3600]");
  if (!(s.settling_band > 0.0 && s.settling_band < 1.0)) bad("settling_band", s.settling_band, "in (0, 1)");
  if (s.rule4_periods < 1 || s.rule4_periods > 100) bad("rule4_periods", s.rule4_periods, "an integer in [1, 100]");
}

ClosedLoopResult simulateAdaptiveForceControl(const AdaptiveControlSettings& s, const JobControl& job) {
  validateAdaptiveControlSettings(s);
  ClosedLoopResult run;
  const CuttingProcess first = stepProcess(s.process, s.workpiece.steps.front());
  const double T0 = spindlePeriod(first);
  run.beta = s.beta;
  run.sampling_period_s = T0;
  run.tau_c_s = processTimeConstant(first);
  run.plant = frohDiscretize(makeForcePlant(first, s.workpiece.steps.front().depth_m).stateSpace(), T0, s.beta);
  // The reference model's rise time is rise_time_periods sampling periods, T_r = 4 T with T the sampling period
  // (Pareto paper, section 6; 2006 paper): with Rule 4 it follows the actual period, and the RST design follows its
  // discretisation at each change of T.
  const auto naturalFrequency = [&](double T) { return 2.5 / (s.rise_time_periods * T); };
  run.model = frohDiscretize(referenceModel(s.damping_ratio, naturalFrequency(T0)), T0, s.beta);
  DiscreteTransferFunction model_at_T = run.model;

  const bool third_order = s.beta != 0.0;  // eq. 30-33
  const int nb = third_order ? 3 : 2;
  RlsEstimator rls(2 + nb, s.rls);
  const double unit = s.control_feed_unit_m_s;
  RstController controller(0.0, s.feed_max_m_s / unit);
  ForcePlantIntegrator plant(s.process, s.workpiece, s.rtol);
  SampledReferenceModel model(s.damping_ratio, naturalFrequency(T0), s.beta);
  SamplePeriodClock clock(s);

  const double funit = s.control_force_unit_N;
  const double fr = s.force_reference_N / funit;
  std::vector<double> y, u;  // controller units: kN and mm/s
  std::vector<PlantDensePoint> dense;
  dense.push_back({0.0, 0.0, 0.0, 0.0, 0.0, s.workpiece.steps.front().depth_m});
  const double length = s.workpiece.totalLength();
  const int max_samples = sampleBudget(s);
  double u_prev = 0.0, T_prev = T0;

  for (int k = 0; k < max_samples && plant.time() < s.max_time_s + T0; ++k) {
    if (job.cancelled()) throw Cancelled();
    const std::size_t kk = static_cast<std::size_t>(k);
    ClosedLoopSample smp;
    smp.t = plant.time();
    smp.force_N = plant.force();
    smp.depth_m = plant.depth();
    smp.spindle_rev_s = plant.spindleRevS();
    smp.position_m = plant.position();
    smp.reference_N = s.force_reference_N;
    smp.model_N = model.output();
    smp.error_N = smp.force_N - smp.model_N;
    y.push_back(smp.force_N / funit);

    // RLS (eq. 26) on y(k) = -a1 y(k-1) - a2 y(k-2) + b0 u(k-1) + b1 u(k-2) [+ b2 u(k-3)]
    Eigen::VectorXd phi(2 + nb);
    phi(0) = -lagged(y, kk, 1);
    phi(1) = -lagged(y, kk, 2);
    for (int j = 0; j < nb; ++j) phi(2 + j) = lagged(u, kk, static_cast<std::size_t>(j) + 1);
    if (k > 0) rls.update(phi, y.back(), fr);
    smp.rls_reset = k > 0 && rls.lastUpdateReset();
    const Eigen::VectorXd& th = rls.theta();
    smp.theta.assign(th.data(), th.data() + th.size());

    const bool done = plant.position() >= length;
    const double T = done ? 0.0 : clock.next(smp.spindle_rev_s, smp.depth_m);
    if (!done && T != T_prev) {
      // The estimated discrete model belongs to the previous period: re-identify it (covariance reset) and
      // design for the reference model sampled at the new period.
      model_at_T = frohDiscretize(referenceModel(s.damping_ratio, naturalFrequency(T)), T, s.beta);
      if (k > 0) rls.resetCovariance();
      T_prev = T;
    }
    smp.sampling_period_s = T;
    if (done && !run.samples.empty()) {  // last sample: measured only, no new control
      const ClosedLoopSample& prev = run.samples.back();
      smp.design_ok = prev.design_ok;
      smp.model_zeros_followed = prev.model_zeros_followed;
      smp.common_factors_removed = prev.common_factors_removed;
    } else if (!done) {
      // pole placement on the estimate (eq. 27-29)
      Poly A{1.0, th(0), th(1)}, B{th(2), th(3)};
      if (third_order) {
        A.push_back(0.0);
        B.push_back(th(4));
      }
      const RstDesign design = designModelFollowing(A, B, model_at_T.den, model_at_T.num, s.design);
      smp.design_ok = design.ok;
      smp.model_zeros_followed = design.ok && design.model_zeros_followed;
      smp.common_factors_removed = design.common_factors_removed;
      smp.diophantine_residual = design.ok ? design.diophantine_residual : 0.0;
      if (design.ok) controller.setDesign(design.R, design.S, design.T);
    }
    const double uk = done ? u_prev : controller.step(fr, y.back());
    smp.feed_m_s = uk * unit;
    smp.feed_unsaturated_m_s = done ? smp.feed_m_s : controller.lastUnsaturated() * unit;
    u.push_back(uk);
    run.samples.push_back(smp);
    if (done) break;

    model.advance(s.force_reference_N, T, naturalFrequency(T));
    const FrohHold hold{plant.time(), T, uk * unit, u_prev * unit, s.beta, 0.0, s.feed_max_m_s};
    plant.advance(hold, s.dense_points_per_sample, dense);
    u_prev = uk;
    job.report(std::min(1.0, plant.position() / length));
  }

  run.depth_change_times_s = plant.crossingTimes();
  // continuous output and the linear interpolation of its samples
  run.dense.reserve(dense.size());
  std::size_t seg = 0;
  for (const auto& p : dense) {
    while (seg + 1 < run.samples.size() && run.samples[seg + 1].t < p.t) ++seg;
    double interp = run.samples[seg].force_N, model_interp = run.samples[seg].model_N;
    if (seg + 1 < run.samples.size()) {
      const auto &a = run.samples[seg], &b = run.samples[seg + 1];
      const double w = (p.t - a.t) / (b.t - a.t);
      interp = a.force_N + (b.force_N - a.force_N) * w;
      model_interp = a.model_N + (b.model_N - a.model_N) * w;
    }
    run.dense.push_back(
        {p.t, p.force_N, interp, model_interp, p.feed_command_m_s, p.feed_actual_m_s, p.position_m, p.depth_m});
  }
  run.metrics = closedLoopMetrics(run, s.force_reference_N, s.settling_band);
  run.metrics.completed = plant.position() >= length;
  run.metrics.cvode_steps = plant.cvodeSteps();
  samplingMetrics(run.samples, run.metrics);
  return run;
}

void samplingMetrics(const std::vector<ClosedLoopSample>& samples, ClosedLoopMetrics& m) {
  m.min_sampling_period_s = m.max_sampling_period_s = m.spindle_revolutions = 0.0;
  bool first = true;
  for (const auto& smp : samples) {
    if (!(smp.sampling_period_s > 0.0)) continue;
    m.min_sampling_period_s = first ? smp.sampling_period_s : std::min(m.min_sampling_period_s, smp.sampling_period_s);
    m.max_sampling_period_s = std::max(m.max_sampling_period_s, smp.sampling_period_s);
    m.spindle_revolutions += smp.sampling_period_s * smp.spindle_rev_s;
    first = false;
  }
}

double closedLoopZeroThreshold(const AdaptiveControlSettings& s) {
  if (s.workpiece.steps.empty()) return -1.0;
  const double depth = s.workpiece.steps.front().depth_m > 0.0 ? s.workpiece.steps.front().depth_m : 1e-3;
  const CuttingProcess first = stepProcess(s.process, s.workpiece.steps.front());
  return unstableZeroThreshold(makeForcePlant(first, depth).stateSpace(), 1.0 / first.spindle_rev_s).threshold_beta;
}

}  // namespace mx
