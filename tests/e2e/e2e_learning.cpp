#include "e2e_learning.h"

#include <QDialog>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>

#include "e2e_driver.h"
#include "e2e_report.h"
#include "history_view.h"
#include "learning_database_dialog.h"
#include "main_window.h"
#include "pareto_feature.h"
#include "services/learning_database.h"
#include "support/window_features.h"

namespace mx::e2e {

namespace {

app::LearningRecord seedRecord(int i) {
  static const char* const kMachines[] = {"VMC-7 Hermle C42", "DMU 50", ""};
  const double w_mrr = 0.2 + 0.05 * i;
  app::LearningRecord r;
  r.uid = QString("e2e-learning-seed-%1").arg(i);
  r.time = QDateTime(QDate(2026, 11, 2 + i), QTime(7 + i % 3, 15 * (i % 4)), Qt::UTC);
  r.weights = {0.3 - 0.02 * i, w_mrr, 0.25, 0.25 - 0.03 * i};  // on the simplex
  r.tool = {i % 4 == 3 ? QString("R2") : QString("R1"), 30.0, 3};
  r.material = "Aluminium";
  const QString machine = QString::fromLatin1(kMachines[i % 3]);
  r.machine = {machine.isEmpty() ? std::nullopt : std::optional<QString>(machine), 2745.3, std::nullopt};
  r.q = {1450.0 + 180.0 * i, 1.2 + 0.35 * i, 0.08 + 0.01 * i};
  const double mrr = r.q.depth_mm * 30.0 * 3 * r.q.feed_mm_per_tooth * r.q.speed_rpm / 60.0 * 1e-3;  // cm³/s
  r.objectives =
      QJsonObject{{"tol", 38.0 - 2.5 * i}, {"mrr_cm3_s", mrr}, {"surf", 0.9 + 0.1 * i}, {"ros", 0.6 - 0.05 * i}};
  r.source = i % 3 == 0   ? app::LearningSource::Automatic
             : i % 3 == 1 ? app::LearningSource::Operator
                          : app::LearningSource::Feedback;
  return r;
}

}  // namespace

void seedLearningDatabase(Report& report) {
  try {
    app::LearningDatabase db(app::LearningDatabase::configuredOrDefault());
    std::vector<app::LearningRecord> records;
    records.reserve(9);
    for (int i = 0; i < 9; ++i) records.push_back(seedRecord(i));
    db.insertAll(records);
  } catch (const std::exception& e) {
    report.require("learning.seed", false, QString::fromStdString(e.what()));
  }
}

void waitForLearningHistory(gui::MainWindow& window, int timeout_ms) {
  gui::ParetoFeature* pareto = test::paretoOf(window);
  auto* history = test::windowPart<widgets::HistoryView>(window);
  waitFor([pareto, history] { return pareto->learningIdle() && history->rows().size() >= 9; }, timeout_ms,
          "the learning history");
}

QDialog* learningDatabaseDialog(gui::MainWindow& window, int timeout_ms) {
  widgets::LearningDatabaseDialog* dialog = test::paretoOf(window)->openLearningDatabaseSettings();
  dialog->resize(900, dialog->sizeHint().height());
  dialog->testButton()->click();
  waitFor([dialog] { return dialog->testButton()->isEnabled() && !dialog->resultLabel()->text().isEmpty(); },
          timeout_ms, "the connection test");
  return dialog;
}

}  // namespace mx::e2e
