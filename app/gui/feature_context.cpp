#include "feature_context.h"

namespace mx::gui {

FeatureContext::FeatureContext(const app::ProjectDocument& document, widgets::DisplayUnits& units,
                               QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), document_(document), units_(units), engine_pool_(engine_pool) {
  setObjectName("featureContext");
}

void FeatureContext::setActiveTool(const QString& id) {
  if (id.isEmpty() || id == active_tool_) return;
  active_tool_ = id;
  emit activeToolChanged(id);
}

bool FeatureContext::pointIsDefault() const {
  return point().speed_rpm <= 0.0 || (default_point_ && *default_point_ == point());
}

void FeatureContext::setReadout(const widgets::PointReadout& readout) {
  readout_ = readout;
  emit readoutChanged(readout_);
}

void FeatureContext::setSimulationRunning(const QString& tool, const app::PickedPoint& point) {
  simulated_tool_ = tool;
  simulated_point_ = point;
  simulation_running_ = true;
  simulation_.reset();
  emit simulationStateChanged();
}

void FeatureContext::setSimulationResult(const SimulationSummary& summary) {
  simulation_running_ = false;
  simulation_ = summary;
  emit simulationStateChanged();
}

void FeatureContext::clearSimulation() {
  simulation_running_ = false;
  simulation_.reset();
  emit simulationStateChanged();
}

bool FeatureContext::simulatesCurrentPoint() const {
  return simulated_tool_ == active_tool_ && simulated_point_ == point();
}

widgets::SimulationCheck FeatureContext::simulationCheck() const {
  widgets::SimulationCheck check;
  if (!simulatesCurrentPoint()) return check;
  if (simulation_running_) check.state = widgets::SimulationCheck::State::Running;
  if (simulation_) {
    check.state = widgets::SimulationCheck::State::Done;
    check.chatter = simulation_->chatter;
    check.eta = simulation_->eta;
  }
  return check;
}

const SimulationSummary* FeatureContext::currentSimulation() const {
  return simulation_ && simulatesCurrentPoint() ? &*simulation_ : nullptr;
}

}  // namespace mx::gui
