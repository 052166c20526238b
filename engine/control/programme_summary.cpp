#include "control/programme_summary.h"

#include <algorithm>

namespace mx {

namespace {

bool inWindow(double t, double from, double to, bool last) {
  return t >= from && (last ? t <= to : t < to);
}

void forceOverWindow(const std::vector<ClosedLoopDensePoint>& dense, bool last, ProgrammeSegmentSummary& seg) {
  double area = 0.0;
  for (std::size_t i = 0; i < dense.size(); ++i) {
    const auto& p = dense[i];
    if (inWindow(p.t, seg.start_s, seg.end_s, last)) seg.peak_force_N = std::max(seg.peak_force_N, p.force_N);
    if (i > 0 && dense[i - 1].t >= seg.start_s && p.t <= seg.end_s)  // trapezoid over [start, end]
      area += 0.5 * (p.force_N + dense[i - 1].force_N) * (p.t - dense[i - 1].t);
  }
  const double span = seg.end_s - seg.start_s;
  seg.mean_force_N = span > 0.0 ? area / span : seg.peak_force_N;
}

// The last quarter of the step's control samples (at least one); the run's final, measurement-only sample is left
// out.
void settledOverWindow(const std::vector<ClosedLoopSample>& samples, ProgrammeSegmentSummary& seg) {
  std::vector<const ClosedLoopSample*> in;
  for (const auto& smp : samples)
    if (smp.sampling_period_s > 0.0 && smp.t >= seg.start_s && smp.t < seg.end_s) in.push_back(&smp);
  seg.samples = static_cast<int>(in.size());
  if (in.empty()) return;
  const std::size_t tail = std::max<std::size_t>(1, in.size() / 4);
  for (std::size_t i = in.size() - tail; i < in.size(); ++i) {
    seg.settled_force_N += in[i]->force_N / static_cast<double>(tail);
    seg.settled_feed_m_s += in[i]->feed_m_s / static_cast<double>(tail);
  }
}

}  // namespace

std::vector<ProgrammeSegmentSummary> programmeSegmentSummaries(const ClosedLoopResult& run,
                                                               const AdaptiveControlSettings& s) {
  std::vector<ProgrammeSegmentSummary> out;
  if (run.samples.empty() || run.dense.empty()) return out;
  const double t_end = run.dense.back().t;
  const std::size_t entered = std::min(s.workpiece.steps.size(), run.depth_change_times_s.size() + 1);
  for (std::size_t i = 0; i < entered; ++i) {
    const ControlDepthStep& step = s.workpiece.steps[i];
    const CuttingProcess process = stepProcess(s.process, step);
    ProgrammeSegmentSummary seg;
    seg.spindle_rev_s = process.spindle_rev_s;
    seg.depth_m = step.depth_m;
    seg.start_s = i == 0 ? 0.0 : run.depth_change_times_s[i - 1];
    seg.end_s = i < run.depth_change_times_s.size() ? run.depth_change_times_s[i] : t_end;
    const bool last = i + 1 == entered;
    forceOverWindow(run.dense, last, seg);
    settledOverWindow(run.samples, seg);
    seg.overshoot_pct = std::max(0.0, seg.peak_force_N - s.force_reference_N) / s.force_reference_N * 100.0;
    seg.analytic_feed_m_s = s.force_reference_N / makeForcePlant(process, step.depth_m).gain_N_s_per_m;
    out.push_back(seg);
  }
  return out;
}

}  // namespace mx
