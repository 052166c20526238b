#include "lobe_job.h"

#include <cmath>
#include <limits>

#include "core/cancellation.h"
#include "services/measured_dynamics.h"
#include "services/service_errors.h"

namespace mx::gui {

namespace {
QVector<double> toMillimetres(const std::vector<double>& depth_m, double factor) {
  QVector<double> out;
  out.reserve(static_cast<qsizetype>(depth_m.size()));
  for (double b : depth_m)
    out.push_back(std::isfinite(b) ? b * factor * 1e3 : std::numeric_limits<double>::quiet_NaN());
  return out;
}

QString dynamicsLabel(const ToolLobes& t, LobeMethod method) {
  if (t.measured_only) return QObject::tr("measured FRF (ZOA)");
  const QString how = method == LobeMethod::ZeroOrder ? QObject::tr("ZOA") : QObject::tr("SDM");
  return t.fitted_modes ? QObject::tr("fitted modes (%1)").arg(how) : QObject::tr("modes (%1)").arg(how);
}
}  // namespace

QVector<widgets::ToolLobeSeries> LobeSnapshot::series() const {
  QVector<widgets::ToolLobeSeries> out;
  for (const ToolLobes& t : tools) {
    widgets::ToolLobeSeries s;
    s.tool_id = QString::fromStdString(t.setup.tool_id);
    s.dynamics = dynamicsLabel(t, method);
    for (double n : t.nominal.speed_rev_per_s) s.speed_rpm.push_back(revPerSToRpm(n));
    s.nominal_mm = toMillimetres(t.nominal.envelope_depth_m, 1.0);
    // Without modes there is no delta margin (a measured FRF gives G(i omega) only): alpha alone.
    s.margined_mm = toMillimetres(t.margined.envelope_depth_m, alpha);
    s.margin_needs_modes = t.measured_only && delta_per_s > 0.0;
    if (t.measured && !t.measured_only) s.measured_mm = toMillimetres(t.measured->envelope_depth_m, 1.0);
    out.push_back(s);
  }
  return out;
}

namespace {

// The measured-FRF ZOA lobes of tool i (delta = 0), read from its FRF files on this (engine) thread.
LobeDiagram measuredLobes(const LobeJobInput& input, const ToolLobes& t, const LobeFrfSource& frf,
                          const JobControl& control) {
  const MillingSetup setup =
      app::dynamicsSetupFor(*frf.project, QString::fromStdString(t.setup.tool_id), DynamicsSource::Measured);
  LobeSettings settings{LobeMethod::ZeroOrder, 0.0, input.max_depth_m, input.sdm_steps, DynamicsSource::Measured};
  return computeLobes(setup, input.speeds_rev_per_s, settings, control);
}

}  // namespace

LobeJobResult runLobeJob(const LobeJobInput& input, quint64 generation, const std::atomic<bool>& cancel,
                         const std::function<void(double)>& progress) {
  LobeJobResult result;
  result.generation = generation;
  auto snapshot = std::make_shared<LobeSnapshot>();
  snapshot->method = input.method;
  snapshot->delta_per_s = input.delta_per_s;
  snapshot->alpha = input.alpha;
  const double jobs = 3.0 * static_cast<double>(std::max<size_t>(input.tools.size(), 1));
  try {
    for (size_t i = 0; i < input.tools.size(); ++i) {
      ToolLobes t;
      t.setup = input.tools[i];
      const std::optional<LobeFrfSource>& frf = i < input.frfs.size() ? input.frfs[i] : std::nullopt;
      if (frf) {
        JobControl control;
        control.cancel = &cancel;
        const double done = static_cast<double>(3 * i);
        if (progress) control.progress = [&](double f) { progress((done + f) / jobs); };
        try {
          t.measured = measuredLobes(input, t, *frf, control);
        } catch (const app::InputError& e) {
          if (!frf->has_modes) throw;  // nothing else to draw for this tool
          // The modes still give lobes; the chart goes without the measured ones, and says why.
          snapshot->warnings << QString::fromStdString(e.what());
        }
        t.fitted_modes = frf->has_modes;
        t.measured_only = !frf->has_modes;
        if (t.measured_only) {
          t.nominal = t.margined = *t.measured;
          snapshot->tools.push_back(std::move(t));
          continue;
        }
      }
      for (int pass = 0; pass < 2; ++pass) {
        JobControl control;
        control.cancel = &cancel;
        const double done = static_cast<double>(3 * i + 1 + pass);
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
