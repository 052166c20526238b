#pragma once
// Test helper: the features of a main window, found by object name as a user of the window would
// reach them (the window has no getters for them).
#include <QTest>
#include <QtGlobal>

#include "batch_feature.h"
#include "editors_feature.h"
#include "engine_runner.h"
#include "expert_feature.h"
#include "feature_context.h"
#include "lobes_feature.h"
#include "main_window.h"
#include "pareto_feature.h"
#include "simulation_feature.h"

namespace mx::test {

template <class T>
T* windowPart(const gui::MainWindow& window, const char* name = nullptr) {
  T* part = name ? window.findChild<T*>(name) : window.findChild<T*>();
  if (!part) qFatal("the main window has no %s", name ? name : "such part");
  return part;
}

inline gui::LobesFeature* lobesOf(const gui::MainWindow& w) {
  return windowPart<gui::LobesFeature>(w, "lobesFeature");
}
inline gui::EditorsFeature* editorsOf(const gui::MainWindow& w) {
  return windowPart<gui::EditorsFeature>(w, "editorsFeature");
}
inline gui::SimulationFeature* simulationOf(const gui::MainWindow& w) {
  return windowPart<gui::SimulationFeature>(w, "simulationFeature");
}
inline gui::ExpertFeature* expertOf(const gui::MainWindow& w) {
  return windowPart<gui::ExpertFeature>(w, "expertFeature");
}
inline gui::ParetoFeature* paretoOf(const gui::MainWindow& w) {
  return windowPart<gui::ParetoFeature>(w, "paretoFeature");
}
inline gui::BatchFeature* batchOf(const gui::MainWindow& w) {
  return windowPart<gui::BatchFeature>(w, "batchFeature");
}
inline gui::FeatureContext* contextOf(const gui::MainWindow& w) {
  return windowPart<gui::FeatureContext>(w, "featureContext");
}
inline gui::EngineRunner* engineOf(const gui::MainWindow& w) {
  return windowPart<gui::EngineRunner>(w);
}

// The readouts are computed on the readout thread: waits until they show the current point.
inline bool waitForReadout(const gui::MainWindow& w, int timeout_ms = 10000) {
  return QTest::qWaitFor([&w] { return lobesOf(w)->readoutIsCurrent(); }, timeout_ms);
}

}  // namespace mx::test
