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

void FeatureContext::setReadout(const widgets::PointReadout& readout) {
  readout_ = readout;
  emit readoutChanged(readout_);
}

}  // namespace mx::gui
