#include "control_figures.h"

#include "control/beta_sweep.h"
#include "control_view.h"
#include "control_view_data.h"
#include "document/project.h"
#include "services/control_request.h"

namespace mx::gui {

QString renderControlResponse(const QString& project_path, double beta, const QString& out_png) {
  try {
    app::ControlRequest request = app::controlRequestFromProject(app::loadProject(project_path));
    request.settings.beta = beta;
    const ClosedLoopResult r = simulateAdaptiveForceControl(request.settings);
    widgets::ControlView view;
    view.resize(1900, 1000);
    view.setSettings(controllerSettingsOf(request));
    view.setBeta(beta);
    view.setTraces(controlTracesOf(r));
    view.setMetrics(controlMetricsOf(r));
    if (!view.saveResponsePlots(out_png)) return out_png + ": cannot write";
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

QString renderControlJc(const QString& project_path, double from, double to, double step, const QString& out_png) {
  try {
    const app::ControlRequest request = app::controlRequestFromProject(app::loadProject(project_path));
    const BetaSweepResult r = sweepBeta(request.settings, {from, to, step, 0});
    widgets::ControlView view;
    view.resize(1900, 1000);
    view.setBeta(request.settings.beta);
    view.setJcCurve(jcCurveOf(r, closedLoopZeroThreshold(request.settings)));
    if (!view.saveJcPlot(out_png)) return out_png + ": cannot write";
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace mx::gui
