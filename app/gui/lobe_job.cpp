#include "lobe_job.h"

#include <cmath>
#include <limits>

#include "model/job_control.h"
#include "stability/zero_order_lobes.h"

namespace mx::gui {

namespace {
QVector<double> toMillimetres(const std::vector<double>& depth_m, double factor) {
  QVector<double> out;
  out.reserve(static_cast<qsizetype>(depth_m.size()));
  for (double b : depth_m) out.push_back(std::isfinite(b) ? b * factor * 1e3 : std::numeric_limits<double>::quiet_NaN());
  return out;
}
}  // namespace

LobeJobResult runLobeJob(const LobeJobInput& input, quint64 generation, const std::atomic<bool>& cancel) {
  LobeJobResult result;
  result.generation = generation;
  JobControl control;
  control.cancel = &cancel;
  try {
    for (const MillingSetup& setup : input.tools) {
      if (control.cancelled()) throw Cancelled();
      ZoaOptions options;
      options.max_depth_m = input.max_depth_m;
      const LobeDiagram nominal = computeZoaLobes(setup, input.speeds_rev_per_s, options, control);
      options.delta_per_s = input.delta_per_s;
      const LobeDiagram margined = computeZoaLobes(setup, input.speeds_rev_per_s, options, control);
      widgets::ToolLobeSeries series;
      series.tool_id = QString::fromStdString(setup.tool_id);
      for (double n : input.speeds_rev_per_s) series.speed_rpm.push_back(revPerSToRpm(n));
      series.nominal_mm = toMillimetres(nominal.envelope_depth_m, 1.0);
      series.margined_mm = toMillimetres(margined.envelope_depth_m, input.alpha);
      result.series.push_back(series);
    }
  } catch (const std::exception& e) {
    result.error = QString::fromStdString(e.what());
  }
  return result;
}

}  // namespace mx::gui
