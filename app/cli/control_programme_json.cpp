#include "cli/control_programme_json.h"

#include <QJsonArray>

#include "control/programme_summary.h"

namespace mx::app {

void addSamplingPeriodJson(const AdaptiveControlSettings& s, const ClosedLoopResult& run, QJsonObject& out) {
  out.insert("sample_period", s.sample_period == SamplePeriodRule::Rule4 ? "rule4" : "spindle");
  out.insert("rule4_periods", s.rule4_periods);
  out.insert("sampling_period_min_s", run.metrics.min_sampling_period_s);
  out.insert("sampling_period_max_s", run.metrics.max_sampling_period_s);
  out.insert("spindle_revolutions", run.metrics.spindle_revolutions);
}

namespace {

QJsonObject segmentJson(const ProgrammeSegmentSummary& seg, const std::optional<double>& programmed_feed_m_s,
                        const CuttingProcess& process) {
  QJsonObject o{{"speed_rpm", seg.spindle_rev_s * 60.0},
                {"depth_mm", seg.depth_m * 1e3},
                {"start_s", seg.start_s},
                {"end_s", seg.end_s},
                {"samples", seg.samples},
                {"mean_force_N", seg.mean_force_N},
                {"peak_force_N", seg.peak_force_N},
                {"overshoot_pct", seg.overshoot_pct},
                {"settled_force_N", seg.settled_force_N},
                {"settled_feed_mm_s", seg.settled_feed_m_s * 1e3},
                {"analytic_feed_mm_s", seg.analytic_feed_m_s * 1e3}};
  QJsonValue feed, force;
  if (programmed_feed_m_s) {
    CuttingProcess p = process;
    p.spindle_rev_s = seg.spindle_rev_s;
    feed = *programmed_feed_m_s * 1e3;
    force = makeForcePlant(p, seg.depth_m).gain_N_s_per_m * *programmed_feed_m_s;
  }
  o.insert("programmed_feed_mm_s", feed);
  o.insert("force_at_programmed_feed_N", force);
  return o;
}

}  // namespace

QJsonObject programmeJson(const ControlRequest& request, const ClosedLoopResult& run) {
  QJsonArray segments;
  const std::vector<ProgrammeSegmentSummary> summary = programmeSegmentSummaries(run, request.settings);
  for (std::size_t i = 0; i < summary.size(); ++i)
    segments.append(segmentJson(summary[i],
                                i < request.programmed_feed_m_s.size() ? request.programmed_feed_m_s[i] : std::nullopt,
                                request.settings.process));
  QJsonArray t, feed, force, period;
  for (const ClosedLoopSample& smp : run.samples) {
    t.append(smp.t);
    feed.append(smp.feed_m_s * 1e3);
    force.append(smp.force_N);
    period.append(smp.sampling_period_s);
  }
  return {{"segments", segments},
          {"history", QJsonObject{{"t_s", t}, {"feed_mm_s", feed}, {"force_N", force}, {"sampling_period_s", period}}}};
}

}  // namespace mx::app
