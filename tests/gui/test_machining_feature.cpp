// The surface-finish view of a project without an "sdnrp" section says that the loop would run on
// Cus and Zuperl's defaults instead of running on them unseen; its button writes those defaults into
// the project (one undo step) and the panel shows them.
#include <QPushButton>
#include <QTest>
#include <QUndoStack>

#include "machining_feature.h"
#include "main_window.h"
#include "notice_stack.h"
#include "sdnrp/sdnrp_simulator.h"
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
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj"));
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
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/cus-zuperl-sdnrp.mxproj"));
    QVERIFY(!test::windowPart<gui::MachiningFeature>(window, "machiningFeature")->surfaceNotice()->noticeShown());
  }
};

MX_REGISTER_TEST(TestMachiningFeature)
#include "test_machining_feature.moc"
