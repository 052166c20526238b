#include "lobe_job.h"

#include <cmath>
#include <limits>

#include "core/cancellation.h"

namespace mx::gui {

namespace {
QVector<double> toMillimetres(const std::vector<double>& depth_m, double factor) {
  QVector<double> out;
  out.reserve(static_cast<qsizetype>(depth_m.size()));
  for (double b : depth_m)
    out.push_back(std::isfinite(b) ? b * factor * 1e3 : std::numeric_limits<double>::quiet_NaN());
  return out;
}
}  // namespace

QVector<widgets::ToolLobeSeries> LobeSnapshot::series() const {
  QVector<widgets::ToolLobeSeries> out;
  for (const ToolLobes& t : tools) {
    widgets::ToolLobeSeries s;
    s.tool_id = QString::fromStdString(t.setup.tool_id);
    for (double n : t.nominal.speed_rev_per_s) s.speed_rpm.push_back(revPerSToRpm(n));
    s.nominal_mm = toMillimetres(t.nominal.envelope_depth_m, 1.0);
    s.margined_mm = toMillimetres(t.margined.envelope_depth_m, alpha);
    out.push_back(s);
  }
  return out;
}

LobeJobResult runLobeJob(const LobeJobInput& input, quint64 generation, const std::atomic<bool>& cancel,
                         const std::function<void(double)>& progress) {
  LobeJobResult result;
  result.generation = generation;
  auto snapshot = std::make_shared<LobeSnapshot>();
  snapshot->method = input.method;
  snapshot->delta_per_s = input.delta_per_s;
  snapshot->alpha = input.alpha;
  const double jobs = 2.0 * static_cast<double>(std::max<size_t>(input.tools.size(), 1));
  try {
    for (size_t i = 0; i < input.tools.size(); ++i) {
      ToolLobes t;
      t.setup = input.tools[i];
      for (int pass = 0; pass < 2; ++pass) {
        JobControl control;
        control.cancel = &cancel;
        const double done = static_cast<double>(2 * i + pass);
        if (progress) control.progress = [&](double f) { progress((done + f) / jobs); };
        if (control.cancelled()) throw Cancelled();
        const LobeSettings settings{input.method, pass == 0 ? 0.0 : input.delta_per_s, input.max_depth_m,
                                    input.sdm_steps};
        (pass == 0 ? t.nominal : t.margined) = computeLobes(t.setup, input.speeds_rev_per_s, settings, control);
      }
      snapshot->tools.push_back(std::move(t));
    }
    result.snapshot = std::move(snapshot);
  } catch (const Cancelled&) {
    result.cancelled = true;
  } catch (const std::exception& e) {
    result.error = QString::fromStdString(e.what());
  }
  return result;
}

}  // namespace mx::gui
