#pragma once
// Test helper: a shown main window on the Pareto case (projects/rubio-pareto-case.mxproj), its Pareto
// study built and its choice made; and the wait for the learning thread to answer.
#include <QSignalSpy>
#include <QTest>

#include "main_window.h"
#include "pareto_feature.h"
#include "pareto_runner.h"
#include "support/project_files.h"
#include "support/window_features.h"

namespace mx::test {

inline bool openParetoCase(gui::MainWindow& window) {
  window.setQuiet(true);
  window.resize(1600, 950);
  window.show();
  QSignalSpy shown(paretoOf(window), &gui::ParetoFeature::paretoShown);
  if (!window.openProject(exampleCopy("rubio-pareto-case.mxproj"))) return false;
  for (int i = 0; i < 120 && !paretoOf(window)->runner()->study(); ++i) shown.wait(1000);
  return paretoOf(window)->runner()->study() != nullptr && paretoOf(window)->choice().has_value();
}

// The learning thread has answered every record and history query (and the view shows the answer).
inline bool waitForLearning(const gui::MainWindow& window) {
  return QTest::qWaitFor([&window] { return paretoOf(window)->learningIdle(); }, 30000);
}

}  // namespace mx::test
