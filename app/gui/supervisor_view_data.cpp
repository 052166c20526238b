#include "supervisor_view_data.h"

#include <map>

#include "grafcet/grafcet_validation.h"
#include "services/supervisor_request.h"

namespace mx::gui {

widgets::GrafcetChartData chartData(const GrafcetChart& c) {
  widgets::GrafcetChartData d;
  d.name = QString::fromStdString(c.name);
  for (const GrafcetStep& s : c.steps) {
    widgets::GrafcetStepView v{s.id, QString::fromStdString(s.name), s.initial, {}};
    for (const std::string& a : s.actions) v.actions << QString::fromStdString(a);
    d.steps.append(v);
  }
  for (const GrafcetTransition& t : c.transitions)
    d.transitions.append({t.id, QList<int>(t.from.begin(), t.from.end()), QList<int>(t.to.begin(), t.to.end()),
                          QString::fromStdString(t.receptivity), t.priority});
  return d;
}

GrafcetChart engineChart(const widgets::GrafcetChartData& d) {
  GrafcetChart c;
  c.name = d.name.toStdString();
  for (const widgets::GrafcetStepView& s : d.steps) {
    GrafcetStep step{s.id, s.name.toStdString(), s.initial, {}};
    for (const QString& a : s.actions) step.actions.push_back(a.toStdString());
    c.steps.push_back(step);
  }
  for (const widgets::GrafcetTransitionView& t : d.transitions)
    c.transitions.push_back({t.id, std::vector<int>(t.from.begin(), t.from.end()),
                             std::vector<int>(t.to.begin(), t.to.end()), t.receptivity.toStdString(), t.priority});
  return c;
}

widgets::SupervisionSeries supervisionSeriesOf(const std::vector<SupervisionSample>& samples,
                                               const SupervisionScenario& s, double reference_n) {
  widgets::SupervisionSeries out;
  for (const SupervisionSample& x : samples) {
    out.t_s << x.t_s;
    out.force_y_n << x.F_Y_N;
    out.power_w << x.power_W;
    out.feed_mm_s << x.feed_m_per_s * 1e3;
  }
  out.power_limit_w = s.limits.spindle_power_limit_W;
  out.force_reference_n = reference_n;
  return out;
}

widgets::SupervisionMetricsView supervisionMetricsOf(const QString& controller, const SupervisionMetrics& m) {
  widgets::SupervisionMetricsView v;
  v.controller = controller;
  v.max_power_pct_of_limit = m.max_power_pct_of_limit;
  v.overshoot_pct = m.overshoot_pct;
  v.chatter_detected = m.chatter_detected;
  if (m.chatter_time_s >= 0.0) v.chatter_time_s = m.chatter_time_s;
  v.passes = m.passes;
  v.cycle_time_s = m.cycle_time_s;
  for (const ForceTransient& t : m.force_transients) {
    if (t.settling_s < 0.0) {
      ++v.unsettled;
    } else {
      v.longest_settling_s = std::max(v.longest_settling_s.value_or(0.0), t.settling_s);
    }
  }
  return v;
}

QVector<widgets::ModuleSpan> moduleSpans(const std::vector<ModuleActivityRecord>& records, double end_s) {
  QVector<widgets::ModuleSpan> spans;
  std::map<char, double> open;
  auto close = [&](char m, double t) {
    spans.append({QString(QChar(m)), open[m], t});
    open.erase(m);
  };
  for (const ModuleActivityRecord& r : records) {
    for (auto it = open.begin(); it != open.end();) {
      const char m = it->first;
      ++it;
      if (r.active.find(m) == std::string::npos) close(m, r.t_s);
    }
    for (char m : r.active)
      if (!open.count(m)) open[m] = r.t_s;
  }
  while (!open.empty()) close(open.begin()->first, end_s);
  return spans;
}

QList<widgets::ChartIssue> chartIssues(const widgets::GrafcetChartData& d) {
  QList<widgets::ChartIssue> issues;
  for (const GrafcetIssue& i : validateGrafcetChart(engineChart(d), app::supervisionSignals())) {
    widgets::ChartIssue issue;
    issue.message = QString::fromStdString(i.describe());
    if (i.element == GrafcetElement::Step) {
      issue.step_id = i.id;
      issue.element = QString("step %1").arg(i.id);
    } else if (i.element == GrafcetElement::Transition) {
      issue.transition_id = i.id;
      issue.element = QString("transition %1").arg(i.id);
    } else {
      issue.element = "chart";
    }
    issues.append(issue);
  }
  return issues;
}

}  // namespace mx::gui
