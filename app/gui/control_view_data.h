#pragma once
// Conversions between the adaptive controller (engine SI structs, the project's control section) and
// the control view's display structs (shop units). Used by the main window and millexpert-plot.
#include "control/beta_sweep.h"
#include "control/closed_loop.h"
#include "control_view.h"
#include "services/control_request.h"

namespace mx::gui {

widgets::ControlTraces controlTracesOf(const ClosedLoopResult& r);
widgets::ControlMetricsView controlMetricsOf(const ClosedLoopResult& r);
widgets::PoleZeroView poleZeroOf(const ClosedLoopResult& r);
widgets::JcCurveView jcCurveOf(const BetaSweepResult& r, double threshold_beta);

widgets::ControllerSettingsView controllerSettingsOf(const app::ControlRequest& request);
// Applies the view's values to a request (shop -> SI).
void applyControllerSettings(const widgets::ControllerSettingsView& view, app::ControlRequest& request);

QVector<widgets::DepthStepView> workpieceViewOf(const ControlWorkpiece& w);
// The edited steps keep the spindle speeds of `previous`'s steps at the same index (a programme's points).
ControlWorkpiece workpieceOf(const QVector<widgets::DepthStepView>& steps, const ControlWorkpiece& previous = {});

}  // namespace mx::gui
