// The surface-finish view of a project without an "sdnrp" section says that the loop would run on
// Cus and Zuperl's defaults instead of running on them unseen; its button writes those defaults into
// the project (one undo step) and the panel shows them. Part programs are read in their detected or
// chosen dialect on the engine thread; a Heidenhain program's AFC table is exported.
#include <QFile>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "machining_feature.h"
#include "main_window.h"
#include "notice_stack.h"
#include "part_program_panel.h"
#include "sdnrp/sdnrp_simulator.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "surface_finish_panel.h"
#include "test_registry.h"

using namespace mx;

class TestMachiningFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void surfaceFinishWithoutItsSectionSaysSoAndAddsIt() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    auto* machining = test::windowPart<gui::MachiningFeature>(window, "machiningFeature");
    widgets::NoticeStack* notice = machining->surfaceNotice();
    QVERIFY(notice->noticeShown());
    QVERIFY2(notice->noticeText().contains("\"sdnrp\""), qPrintable(notice->noticeText()));
    QTest::mouseClick(notice->actionButton(), Qt::LeftButton);
    QVERIFY(!notice->noticeShown());
    const SdnrpSettings defaults;
    QVERIFY(window.project()->sdnrp && window.project()->sdnrp->ra_um);
    QCOMPARE(*window.project()->sdnrp->ra_um, defaults.ra_desired_m * 1e6);
    QCOMPARE(*window.project()->sdnrp->seconds, defaults.duration_s);
    QCOMPARE(machining->surfacePanel()->desiredRaUm(), defaults.ra_desired_m * 1e6);
    window.document()->undoStack()->undo();
    QVERIFY(notice->noticeShown());
  }

  void projectWithTheSectionShowsThePanel() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(mx::test::exampleCopy("cus-zuperl-sdnrp.mxproj")));
    QVERIFY(!test::windowPart<gui::MachiningFeature>(window, "machiningFeature")->surfaceNotice()->noticeShown());
  }

  void heidenhainProgramDetectedAndItsAfcTableExported() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(mx::test::exampleCopy("cus-zuperl-sdnrp.mxproj")));
    auto* machining = test::windowPart<gui::MachiningFeature>(window, "machiningFeature");
    widgets::PartProgramPanel* panel = machining->programPanel();
    QSignalSpy shown(machining, &gui::MachiningFeature::partProgramShown);
    machining->openPartProgram(MX_PROJECTS_DIR "/programs/pocket_mm.h");
    QVERIFY(shown.wait(20000));
    QVERIFY2(panel->headerText().contains("Heidenhain Klartext, detected at line 1: BEGIN PGM \u2014 AFC-LOAD 0.115 kW "
                                          "for T1"),
             qPrintable(panel->headerText()));
    QCOMPARE(panel->changedCount(), 2);
    QVERIFY(panel->exportAfcButton()->isEnabled());
    QVERIFY2(panel->statusText().contains("AFC-LOAD 0.115 kW for tool R216-16B20-040 (T1), FMAX 145 %"),
             qPrintable(panel->statusText()));
    QTemporaryDir dir;
    const QString afc = dir.filePath("AFC.TAB");
    QVERIFY(machining->exportAfcTable(afc));
    QFile file(afc);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.value(0), QByteArray("BEGIN AFC .TAB MM"));
    QCOMPARE(lines.value(2).simplified(), QByteArray("0 MX_R21616B 50 145 100 100 E 8 100 0"));

    // Chosen as ISO, the Klartext program is refused with its first line; the AFC export goes.
    QSignalSpy failed(machining, &gui::WindowFeature::errorRaised);
    panel->setDialectChoice("iso");
    QVERIFY(failed.wait(20000));
    QVERIFY2(failed.at(0).at(1).toString().contains("line 1, column 1: 0: cannot be split into ISO / Fanuc words"),
             qPrintable(failed.at(0).at(1).toString()));
    // The ISO pocket, read as chosen: no AFC for a non-Heidenhain program.
    machining->openPartProgram(MX_TEST_DATA_DIR "/gcode/pocket_mm.nc");
    QVERIFY(shown.wait(20000));
    QVERIFY(panel->headerText().contains("ISO / Fanuc (chosen)"));
    QVERIFY(!panel->exportAfcButton()->isEnabled());
    QVERIFY(!machining->exportAfcTable(dir.filePath("none.TAB")));
    QVERIFY(!QFile::exists(dir.filePath("none.TAB")));
  }
};

MX_REGISTER_TEST(TestMachiningFeature)
#include "test_machining_feature.moc"
