// File > Batch study in the main window (app/gui/batch_feature.h), with the real millexpert-cli: the
// study written from the open project (manifest + project snapshot, read back as batch reads it, with
// the case count), run here with the progress bar reaching the case count and the merged table of one
// row per tool and material, and a cancelled run that a second run resumes: every case present once.
// Machines read from other project files (on the engine pool) join the study as cases, each a section
// of the manifest's machines; a file without one is named in the status.
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>

#include "batch_study_dialog.h"
#include "main_window.h"
#include "services/batch_manifest.h"
#include "services/batch_study.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

namespace {

widgets::BatchStudySettings lobesStudy(const QStringList& materials, double step_rpm) {
  widgets::BatchStudySettings s;
  s.computation = "lobes";
  s.tools = {"R1", "R2"};
  s.materials = materials;
  s.from_rpm = 3000;
  s.to_rpm = 12000;
  s.step_rpm = step_rpm;
  s.jobs = 1;
  return s;
}

QStringList resultLines(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
  return lines;
}

QSet<QString> hashesOf(const QStringList& lines) {
  QSet<QString> hashes;
  for (const QString& line : lines) hashes.insert(QJsonDocument::fromJson(line.toUtf8()).object()["hash"].toString());
  return hashes;
}

}  // namespace

class TestBatchFeature : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

  static void prepare(gui::MainWindow& window) {
    window.setQuiet(true);
    // R1, R2; Aluminium
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    test::batchOf(window)->setCliProgram(MX_CLI_PATH);
  }

 private slots:
  void writesTheStudy() {
    gui::MainWindow window;
    prepare(window);
    gui::BatchFeature* batch = test::batchOf(window);
    widgets::BatchStudyDialog* dialog = batch->openDialog();
    QCOMPARE(dialog->settings().tools, (QStringList{"R1", "R2"}));
    QCOMPARE(dialog->settings().materials, QStringList{"Aluminium"});
    QVERIFY(dialog->materialList()->count() > 3);  // the material library follows
    const QString library_material = dialog->materialList()->item(1)->text();

    const QString manifest = dir_.filePath("study.json");
    QVERIFY(batch->saveStudy(lobesStudy({"Aluminium", library_material}, 100), manifest));
    QVERIFY(QFile::exists(dir_.filePath("study.mxproj")));
    const app::BatchManifest m = app::readBatchManifest(manifest);
    QCOMPARE(m.computation, QString("lobes"));
    QCOMPARE(m.projects, QStringList{"study.mxproj"});
    QCOMPARE(m.tools, std::optional<QStringList>({"R1", "R2"}));
    QCOMPARE(m.materials.size(), std::size_t{2});
    QCOMPARE(m.materials[0]["name"].toString(), QString("Aluminium"));
    QCOMPARE(m.materials[0]["Kt_N_mm2"].toDouble(), 600.0);
    QCOMPARE(m.materials[1]["name"].toString(), library_material);
    QCOMPARE(m.options, (QJsonObject{{"from", 3000}, {"to", 12000}, {"step", 100}, {"method", "zoa"}}));
    QVERIFY2(dialog->statusLabel()->text().contains("4 cases"), qPrintable(dialog->statusLabel()->text()));

    // A study that names no tool is refused before anything is written.
    widgets::BatchStudySettings none = lobesStudy({"Aluminium"}, 100);
    none.tools.clear();
    QVERIFY(!batch->saveStudy(none, dir_.filePath("none.json")));
    QVERIFY(!QFile::exists(dir_.filePath("none.json")));
    QVERIFY(dialog->statusLabel()->text().contains("no tool"));
  }

  void machinesOfOtherProjects() {
    gui::MainWindow window;
    prepare(window);
    gui::BatchFeature* batch = test::batchOf(window);
    app::Project cell = app::loadProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj"));
    cell.machine = app::MachineSpec{};
    cell.machine->name = "Mazak VCN";
    cell.machine->spindle_power_W = 22000.0;
    cell.machine->max_spindle_rpm = 10000.0;
    const QString cell_file = dir_.filePath("cell-2.mxproj");
    app::saveProject(cell, cell_file);
    cell.machine.reset();
    const QString bare_file = dir_.filePath("bare.mxproj");
    app::saveProject(cell, bare_file);

    widgets::BatchStudyDialog* dialog = batch->openDialog();
    QCOMPARE(dialog->machineList()->count(), 1);
    const QString own = dialog->machineList()->item(0)->text();
    QCOMPARE(own, QString("unnamed machine: 745.3 W, max 12000 rpm (this project)"));
    QSignalSpy added(batch, &gui::BatchFeature::machinesAdded);
    batch->addMachinesFrom({cell_file, bare_file});
    QVERIFY(added.wait(30000));
    QCOMPARE(added.at(0).at(0).toInt(), 1);
    QCOMPARE(dialog->machineList()->count(), 2);
    const QString mazak = dialog->machineList()->item(1)->text();
    QCOMPARE(mazak, QString("Mazak VCN: 22000.0 W, max 10000 rpm (cell-2.mxproj)"));
    QVERIFY2(dialog->statusLabel()->text().contains(bare_file + ": no machine section"),
             qPrintable(dialog->statusLabel()->text()));
    batch->addMachinesFrom({cell_file});  // listed once
    QVERIFY(added.wait(30000));
    QCOMPARE(added.at(1).at(0).toInt(), 0);
    QCOMPARE(dialog->machineList()->count(), 2);

    widgets::BatchStudySettings both = lobesStudy({"Aluminium"}, 100);
    both.machines = {own, mazak};
    const QString manifest = dir_.filePath("machines.json");
    QVERIFY(batch->saveStudy(both, manifest));
    const app::BatchManifest m = app::readBatchManifest(manifest);
    QCOMPARE(m.machines.size(), std::size_t{2});
    QCOMPARE(m.machines[0]["spindle_power_W"].toDouble(), 745.3);
    QVERIFY(!m.machines[0].contains("name"));
    QCOMPARE(m.machines[1]["name"].toString(), QString("Mazak VCN"));
    QCOMPARE(m.machines[1]["spindle_power_W"].toDouble(), 22000.0);
    QCOMPARE(m.machines[1]["max_spindle_rpm"].toDouble(), 10000.0);
    QVERIFY2(dialog->statusLabel()->text().contains("(4 cases)"), qPrintable(dialog->statusLabel()->text()));

    widgets::BatchStudySettings own_only = both;
    own_only.machines = {own};
    QVERIFY(batch->saveStudy(own_only, manifest));
    QVERIFY(app::readBatchManifest(manifest).machines.empty());  // each case keeps the project's
    QVERIFY2(dialog->statusLabel()->text().contains("(2 cases)"), qPrintable(dialog->statusLabel()->text()));

    // A project without a machine section: its own "machine" cannot stand beside another one.
    QVERIFY(window.openProject(bare_file));
    dialog = batch->openDialog();
    QCOMPARE(dialog->machineList()->item(0)->text(), QString("this project's (no machine section: no power limit)"));
    QCOMPARE(dialog->machineList()->item(1)->text(), mazak);  // the machines added stay listed
    both.machines = {dialog->machineList()->item(0)->text(), mazak};
    QVERIFY(!batch->saveStudy(both, dir_.filePath("bare-study.json")));
    QVERIFY(!QFile::exists(dir_.filePath("bare-study.json")));
    QVERIFY2(dialog->statusLabel()->text().contains("the project has no machine section"),
             qPrintable(dialog->statusLabel()->text()));
    both.machines = {mazak};
    QVERIFY(batch->saveStudy(both, dir_.filePath("bare-study.json")));
  }

  void runsHereAndShowsTheMergedTable() {
    gui::MainWindow window;
    prepare(window);
    gui::BatchFeature* batch = test::batchOf(window);
    widgets::BatchStudyDialog* dialog = batch->openDialog();
    const QString library_material = dialog->materialList()->item(1)->text();
    QSignalSpy finished(batch, &gui::BatchFeature::runFinished);
    QSignalSpy shown(batch, &gui::BatchFeature::resultsShown);
    const QString manifest = dir_.filePath("run.json");
    QVERIFY(batch->runStudy(lobesStudy({"Aluminium", library_material}, 100), manifest));
    QVERIFY(batch->running());
    QVERIFY(!dialog->runButton()->isEnabled() && dialog->cancelButton()->isEnabled());
    QVERIFY(finished.wait(240000));
    QCOMPARE(finished.at(0).at(0).toInt(), 0);
    QVERIFY(shown.wait(60000) || shown.size() == 1);
    QCOMPARE(resultLines(app::batchStudyResultsPath(manifest)).size(), 4);
    QCOMPARE(dialog->progressBar()->value(), 4);
    QCOMPARE(dialog->progressBar()->maximum(), 4);
    QTableWidget* table = dialog->resultsTable();
    QCOMPARE(table->rowCount(), 4);  // one line per tool of each material's row
    QStringList materials;
    int speed_column = -1;
    for (int c = 0; c < table->columnCount(); ++c)
      if (table->horizontalHeaderItem(c)->text() == "Speed [rpm]") speed_column = c;
    QVERIFY(speed_column >= 0);
    for (int r = 0; r < table->rowCount(); ++r) {
      const double speed = table->item(r, speed_column)->text().toDouble();
      QVERIFY2(speed >= 3000 && speed <= 12000, qPrintable(table->item(r, speed_column)->text()));  // a best pocket
    }
    QVERIFY(dialog->runButton()->isEnabled());
  }

  void cancelledRunResumes() {
    gui::MainWindow window;
    prepare(window);
    gui::BatchFeature* batch = test::batchOf(window);
    widgets::BatchStudyDialog* dialog = batch->openDialog();
    QStringList materials;
    for (int i = 0; i < 4; ++i) materials << dialog->materialList()->item(i)->text();
    widgets::BatchStudySettings study = lobesStudy(materials, 25);  // 8 cases of about 1 s each
    study.method = "sdm";
    const QString manifest = dir_.filePath("cancel.json");
    QSignalSpy finished(batch, &gui::BatchFeature::runFinished);
    QVERIFY(batch->runStudy(study, manifest));
    const QString results = app::batchStudyResultsPath(manifest);
    QVERIFY(QTest::qWaitFor([&] { return dialog->progressBar()->value() >= 1; }, 240000));
    QVERIFY(batch->running());
    batch->cancelRun();
    QVERIFY(finished.wait(30000));
    QVERIFY(finished.at(0).at(1).toBool());  // cancelled
    const QStringList partial = resultLines(results);
    QVERIFY2(partial.size() >= 1 && partial.size() < 8, qPrintable(QString::number(partial.size())));
    QVERIFY(dialog->statusLabel()->text().contains("resumes"));

    QVERIFY(batch->runStudy(study, manifest));
    QVERIFY(finished.wait(480000));
    QCOMPARE(finished.at(1).at(0).toInt(), 0);
    const QStringList all = resultLines(results);
    QCOMPARE(all.size(), 8);
    QCOMPARE(hashesOf(all).size(), 8);  // each case once: the first run's lines were kept, not redone
    for (const QString& line : partial) QVERIFY(all.contains(line));
  }
};

MX_REGISTER_TEST(TestBatchFeature)
#include "test_batch_feature.moc"
