// File > Batch study's dialog (widgets/batch_study_dialog.h): the choices fill the lists (every tool,
// the project's material and its machine checked), machines added from files listed once and checked,
// the settings round-trip, the speed range shows for lobes only, the
// buttons follow what is checked and whether a run is going, the domain signals carry the settings,
// and the merged table shows its columns with units.
#include <QComboBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>

#include "batch_study_dialog.h"
#include "test_registry.h"

using mx::widgets::BatchStudyDialog;
using mx::widgets::BatchStudySettings;

namespace {
mx::widgets::BatchStudyChoices choices() {
  mx::widgets::BatchStudyChoices c;
  c.tools = {"R1", "R2", "R3"};
  c.materials = {"Aluminium", "Steel C45", "Ti6Al4V"};
  c.machines = {"DMU-50: 15 kW (this project)", "Mazak: 22 kW (cell-2.mxproj)"};
  c.max_jobs = 2;
  c.project_name = "shop.mxproj";
  return c;
}
}  // namespace

class TestBatchStudyDialog : public QObject {
  Q_OBJECT

 private slots:
  void choicesFillTheLists() {
    BatchStudyDialog d;
    d.setChoices(choices());
    const BatchStudySettings s = d.settings();
    QCOMPARE(s.tools, (QStringList{"R1", "R2", "R3"}));
    QCOMPARE(s.materials, QStringList{"Aluminium"});  // the project's material only
    QCOMPARE(s.jobs, 2);
    QCOMPARE(s.computation, QString("lobes"));
    QCOMPARE(d.windowTitle(), QString("Batch study - shop.mxproj"));
    QCOMPARE(s.machines, QStringList{"DMU-50: 15 kW (this project)"});  // the project's own only
    QCOMPARE(d.machineList()->count(), 2);
  }

  void addedMachinesAreListedOnceAndChecked() {
    BatchStudyDialog d;
    d.setChoices(choices());
    QSignalSpy asked(&d, &BatchStudyDialog::addMachinesRequested);
    d.addMachinesButton()->click();
    QCOMPARE(asked.size(), 1);
    d.addMachines({"Hermle: 30 kW (cell-4.mxproj)", "Mazak: 22 kW (cell-2.mxproj)"});
    QCOMPARE(d.machineList()->count(), 3);  // Mazak was listed already
    QCOMPARE(d.settings().machines, (QStringList{"DMU-50: 15 kW (this project)", "Hermle: 30 kW (cell-4.mxproj)"}));
  }

  void settingsRoundTrip() {
    BatchStudyDialog d;
    d.setChoices(choices());
    BatchStudySettings s;
    s.computation = "rank";
    s.tools = {"R1", "R3"};
    s.materials = {"Steel C45", "Ti6Al4V"};
    s.machines = {"Mazak: 22 kW (cell-2.mxproj)"};
    s.from_rpm = 2000;
    s.to_rpm = 9000;
    s.step_rpm = 25;
    s.method = "sdm";
    s.jobs = 1;
    d.setSettings(s);
    QCOMPARE(d.settings(), s);
  }

  void speedRangeForLobesOnly() {
    BatchStudyDialog d;
    d.setChoices(choices());
    d.show();
    QWidget* range = d.findChild<QWidget*>("batchFrom")->parentWidget();
    QVERIFY(range->isVisible());
    d.computationBox()->setCurrentIndex(d.computationBox()->findData("point"));
    QVERIFY(!range->isVisible());
    d.computationBox()->setCurrentIndex(d.computationBox()->findData("lobes"));
    QVERIFY(range->isVisible());
  }

  void buttonsFollowTheChecksAndTheRun() {
    BatchStudyDialog d;
    d.setChoices(choices());
    QVERIFY(d.runButton()->isEnabled() && d.saveButton()->isEnabled() && !d.cancelButton()->isEnabled());
    for (int i = 0; i < d.toolList()->count(); ++i) d.toolList()->item(i)->setCheckState(Qt::Unchecked);
    QVERIFY(!d.runButton()->isEnabled() && !d.saveButton()->isEnabled());
    QVERIFY(d.statusLabel()->text().contains("at least one tool"));
    d.toolList()->item(1)->setCheckState(Qt::Checked);
    QVERIFY(d.runButton()->isEnabled());
    QVERIFY(d.statusLabel()->text().isEmpty());
    d.materialList()->item(0)->setCheckState(Qt::Unchecked);
    QVERIFY(!d.runButton()->isEnabled());
    d.materialList()->item(2)->setCheckState(Qt::Checked);
    QVERIFY(d.runButton()->isEnabled());
    d.machineList()->item(0)->setCheckState(Qt::Unchecked);
    QVERIFY(!d.runButton()->isEnabled());
    QVERIFY(d.statusLabel()->text().contains("one machine"));
    d.machineList()->item(1)->setCheckState(Qt::Checked);
    d.setRunning(true);
    QVERIFY(!d.runButton()->isEnabled() && !d.saveButton()->isEnabled() && d.cancelButton()->isEnabled());
    d.setRunning(false);
    QVERIFY(d.runButton()->isEnabled() && !d.cancelButton()->isEnabled());
  }

  void signalsCarryTheSettings() {
    BatchStudyDialog d;
    d.setChoices(choices());
    QSignalSpy run(&d, &BatchStudyDialog::runRequested);
    QSignalSpy save(&d, &BatchStudyDialog::saveRequested);
    QSignalSpy cancel(&d, &BatchStudyDialog::cancelRequested);
    d.materialList()->item(1)->setCheckState(Qt::Checked);
    d.runButton()->click();
    d.saveButton()->click();
    QCOMPARE(run.size(), 1);
    QCOMPARE(save.size(), 1);
    QCOMPARE(run.at(0).at(0).value<BatchStudySettings>().materials, (QStringList{"Aluminium", "Steel C45"}));
    d.setRunning(true);
    d.cancelButton()->click();
    QCOMPARE(cancel.size(), 1);
  }

  void progressAndTable() {
    BatchStudyDialog d;
    d.setProgress(3, 12);
    QCOMPARE(d.progressBar()->value(), 3);
    QCOMPARE(d.progressBar()->maximum(), 12);
    QCOMPARE(d.progressBar()->text(), QString("3 of 12 cases"));
    d.setProgress(0, 0);  // no case: an empty bar, not a busy one
    QCOMPARE(d.progressBar()->maximum(), 1);
    d.setResults({"tool", "speed_rpm", "blim_mm", "verdict"}, {{"R1", "5800", "0.49", ""}, {"R2", "4100", "1.2", ""}});
    QTableWidget* t = d.resultsTable();
    QCOMPARE(t->rowCount(), 2);
    QCOMPARE(t->horizontalHeaderItem(1)->text(), QString("Speed [rpm]"));
    QCOMPARE(t->horizontalHeaderItem(2)->text(), QString("b_lim [mm]"));
    QCOMPARE(t->item(1, 1)->text(), QString("4100"));
    QCOMPARE(t->item(0, 2)->text(), QString("0.490"));  // depths to the µm
    t->sortItems(1);                                    // by speed, as numbers
    QCOMPARE(t->item(0, 0)->text(), QString("R2"));
    QCOMPARE(BatchStudyDialog::columnTitle("feed_mm_per_tooth"), QString("Feed [mm/tooth]"));
    QVERIFY(t->isColumnHidden(3));  // no verdict in any row
    QVERIFY(!t->isColumnHidden(2));
    d.setResults({"operation", "verdict"},
                 {{R"({"max_feed_per_tooth_mm":0.15,"milling":"down","radial_immersion":0.5})", "stable"}});
    QCOMPARE(t->item(0, 0)->text(), QString("down milling, a_e/D 0.5, f_z max 0.15 mm"));
    QVERIFY(!t->isColumnHidden(1));
    QCOMPARE(BatchStudyDialog::columnTitle("other"), QString("other"));
  }
};

MX_REGISTER_TEST(TestBatchStudyDialog)
#include "test_batch_study_dialog.moc"
