#include "e2e_batch.h"

#include <QDialog>
#include <QDir>
#include <QListWidget>
#include <QTableWidget>

#include "batch_feature.h"
#include "batch_study_dialog.h"
#include "e2e_driver.h"
#include "main_window.h"
#include "support/window_features.h"

namespace mx::e2e {

QDialog* batchStudyDialog(gui::MainWindow& window, const QString& folder, int timeout_ms) {
  gui::BatchFeature* batch = test::batchOf(window);
  batch->setCliProgram(MX_CLI_PATH);
  widgets::BatchStudyDialog* dialog = batch->openDialog();
  dialog->resize(1400, 820);
  for (int i = 1; i < 3 && i < dialog->materialList()->count(); ++i)
    dialog->materialList()->item(i)->setCheckState(Qt::Checked);
  widgets::BatchStudySettings study = dialog->settings();
  study.from_rpm = 3000;
  study.to_rpm = 12000;
  study.step_rpm = 50;
  dialog->setSettings(study);
  batch->runStudy(dialog->settings(), QDir(folder).filePath("batch-study.json"));
  waitFor([batch, dialog] { return !batch->running() && dialog->resultsTable()->rowCount() > 0; }, timeout_ms,
          "the batch study's run and table");
  return dialog;
}

}  // namespace mx::e2e
