// GUI smoke test (offscreen): the main window opens a project, computes the lobes on the engine
// thread and shows one nominal and one margined envelope per tool; a bad file is refused.
#include <QApplication>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "main_window.h"
#include "test_main.h"

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void opensProjectAndPlotsLobes() {
    mx::gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(&window, &mx::gui::MainWindow::lobesShown);
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj"));
    QVERIFY(shown.wait(20000));
    QCOMPARE(window.project()->tools.size(), size_t{2});
    QVERIFY(window.windowTitle().contains("rubio2006"));
  }

  void badProjectIsRefusedAndKeepsTheCurrentOne() {
    mx::gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/benchmark-insperger-1dof.mxproj"));
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.mxproj");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{ \"format\": \"millexpert-project\", \"version\": 1 ");
    f.close();
    QVERIFY(!window.openProject(bad));
    QCOMPARE(window.project()->tools.front().id, QString("FULL"));
  }
};

MX_TEST_MAIN_WITH_APP(TestMainWindow, QApplication)
#include "test_main_window.moc"
