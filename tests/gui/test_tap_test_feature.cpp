// The tap-test view in the main window: the example project's FRFs are shown on load and its lobes run
// on them ("measured FRF (ZOA)"); a fit gives back the stated modes; Accept writes the modes and the
// FRF reference into the tool as one undo step; a y FRF imported as x is refused with a message.
#include <QSignalSpy>

#include "document/project.h"
#include "frf/frf_csv.h"
#include "lobes_feature.h"
#include "main_window.h"
#include "support/frf_samples.h"
#include "support/project_files.h"
#include "tap_test_feature.h"
#include "tap_test_panel.h"
#include "test_registry.h"

using namespace mx;

namespace {

gui::TapTestFeature* tapTest(const gui::MainWindow& w) {
  return w.findChild<gui::TapTestFeature*>("tapTestFeature");
}

widgets::TapTestFitRequest automatic(const QString& direction) {
  widgets::TapTestFitRequest r;
  r.direction = direction;
  r.from_hz = 500.0;
  r.to_hz = 3500.0;
  return r;
}

}  // namespace

class TestTapTestFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void exampleFitAndAccept() {
    QTemporaryDir dir;
    // A copy next to its tap-test files, so that Accept writes paths relative to it.
    QVERIFY(QDir(dir.path()).mkpath("taps"));
    for (const char* f : {"tap-test-example.mxproj", "taps/T9-x.uff", "taps/T9-y.uff"})
      QVERIFY(QFile::copy(test::projectsPath(f), dir.filePath(f)));
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QSignalSpy shown(tapTest(window), &gui::TapTestFeature::measurementShown);
    QSignalSpy lobes(window.findChild<gui::LobesFeature*>("lobesFeature"), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(dir.filePath("tap-test-example.mxproj")));
    QTRY_COMPARE_WITH_TIMEOUT(shown.count(), 2, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(lobes.count() >= 1, 20000);
    const auto* snapshot = window.findChild<gui::LobesFeature*>("lobesFeature")->snapshot().get();
    QVERIFY(snapshot && snapshot->tools.size() == 2);
    QVERIFY(snapshot->tools[0].measured_only);  // T9: the FRFs only
    QCOMPARE(snapshot->series().at(0).dynamics, QString("measured FRF (ZOA)"));
    QVERIFY(!snapshot->tools[1].measured_only);  // T9-fit: modes and FRFs, both drawn
    QCOMPARE(snapshot->series().at(1).dynamics, QString("fitted modes (ZOA)"));
    QVERIFY(!snapshot->series().at(1).measured_mm.isEmpty());
    // the modes fitted to the measurement give its lobes within 3 % (the files have 1 % noise; 1.9 % here)
    const widgets::ToolLobeSeries fit = snapshot->series().at(1);
    double worst = 0.0;
    for (qsizetype i = 0; i < fit.nominal_mm.size(); ++i)
      if (std::isfinite(fit.nominal_mm[i]) && std::isfinite(fit.measured_mm[i]))
        worst = std::max(worst, std::abs(fit.measured_mm[i] / fit.nominal_mm[i] - 1.0));
    qInfo("T9-fit: worst difference of the measured-FRF and the fitted-mode lobes: %.2f %%", 100 * worst);
    QCOMPARE_LE(worst, 0.03);

    QSignalSpy fitted(tapTest(window), &gui::TapTestFeature::fitShown);
    emit tapTest(window)->panel()->fitRequested(automatic("x"));
    QVERIFY(fitted.wait(30000));
    QString why;
    const std::optional<app::Project> edited = tapTest(window)->acceptedProject("x", &why);
    QVERIFY2(edited, qPrintable(why));
    const app::ToolSpec& t = edited->tools[0];
    const MillingSetup stated = app::loadProject(test::projectsPath("taps/T9-stated-modes.mxproj")).setupFor("T9");
    QCOMPARE(t.modes_x.size(), stated.modes_x.size());
    for (std::size_t i = 0; i < t.modes_x.size(); ++i) {
      QCOMPARE_LE(std::abs(t.modes_x[i].freq_Hz / stated.modes_x[i].natural_frequency_hz - 1.0), 0.005);
      QCOMPARE_LE(std::abs(t.modes_x[i].damping_pct / (100 * stated.modes_x[i].damping_ratio) - 1.0), 0.10);
      QCOMPARE_LE(std::abs(t.modes_x[i].stiffness_N_per_um / (1e-6 * stated.modes_x[i].stiffness_n_per_m) - 1.0), 0.05);
    }
    QCOMPARE(t.frf_x->file, QString("taps/T9-x.uff"));
    QCOMPARE(t.frf_x->datasetIndex(), 0);
    QVERIFY(t.modes_y.empty());  // only x was accepted

    emit tapTest(window)->panel()->acceptRequested("x");
    QCOMPARE(window.project()->tools[0].modes_x.size(), stated.modes_x.size());
    QCOMPARE(window.document()->undoStack()->count(), 1);
    window.document()->undoStack()->undo();
    QVERIFY(window.project()->tools[0].modes_x.empty());
  }

  // T9-fit without its tap-test files: the modes still give the lobes, and the status says what is missing.
  void aMissingFrfFileLeavesTheModalLobes() {
    QTemporaryDir dir;
    app::Project p = app::loadProject(test::projectsPath("tap-test-example.mxproj"));
    p.tools.erase(p.tools.begin());
    p.folder = dir.path();  // taps/ does not exist there
    app::saveProject(p, dir.filePath("p.mxproj"));
    gui::MainWindow window;
    window.setQuiet(true);
    auto* lobes = window.findChild<gui::LobesFeature*>("lobesFeature");
    QSignalSpy shown(lobes, &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(dir.filePath("p.mxproj")));
    QVERIFY(shown.wait(20000));
    const auto& snapshot = *lobes->snapshot();
    QCOMPARE(snapshot.tools.size(), std::size_t{1});
    QVERIFY(!snapshot.tools[0].measured);
    QCOMPARE(snapshot.warnings.size(), 1);
    QVERIFY2(snapshot.warnings[0].contains("tool 'T9-fit'") && snapshot.warnings[0].contains("not found"),
             qPrintable(snapshot.warnings[0]));
  }

  void refusesAnFrfOfTheOtherDirection() {
    gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(test::exampleCopy("tap-test-example.mxproj")));
    QSignalSpy shown(tapTest(window), &gui::TapTestFeature::measurementShown);
    QTRY_COMPARE_WITH_TIMEOUT(shown.count(), 2, 20000);
    shown.clear();
    tapTest(window)->importFile(test::projectsPath("taps/T9-y.uff"), "x", 0, std::nullopt);
    QTest::qWait(500);
    QCOMPARE(shown.count(), 0);
    QString why;
    QVERIFY(!tapTest(window)->acceptedProject("x", &why));  // nothing fitted
    QVERIFY(why.contains("no fit for x"));
  }

  void importsACsv() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("tap.csv");
    test::writeBytes(csv.toStdString(), frfCsvString(test::modalFrf(test::kTwoModes, FrfQuantity::Mobility,
                                                                    test::evenFrequencies(0.0, 1.0, 2001))));
    gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QSignalSpy shown(tapTest(window), &gui::TapTestFeature::measurementShown);
    tapTest(window)->importFile(csv, "y", std::nullopt, FrfQuantity::Mobility);
    QVERIFY(shown.wait(20000));
    QCOMPARE(shown.at(0).at(0).toString(), QString("y"));
  }
};

MX_REGISTER_TEST(TestTapTestFeature)
#include "test_tap_test_feature.moc"
