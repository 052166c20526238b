// Main window (offscreen): save/reopen, autosave recovery after a simulated crash, the untitled
// autosave's folder, a bad file that keeps the project, and saves that fail (a read-only folder, the
// file replaced by a directory) showing the error and keeping the changes; the default layout at
// 1080p (the chart's height, nothing of the docks cut) and the toolbar's steady Undo button.
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QToolBar>
#include <QUndoStack>

#include "document/project_validation.h"
#include "main_window.h"
#include "support/hostile_files.h"
#include "support/project_files.h"
#include "support/read_only_folder.h"
#include "test_registry.h"
#include "tool_library_editor.h"
#include "weights_panel.h"

using namespace mx;

namespace {
using mx::test::kRubio;

QString copyToTemp(const QTemporaryDir& dir, const QString& source) {
  QString target = dir.filePath("project.mxproj");
  QFile::remove(target);
  QFile::copy(source, target);
  QFile(target).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
  return target;
}

// A quiet window (no dialogs) with `path` open.
bool openQuietly(gui::MainWindow& window, const QString& path) {
  window.setQuiet(true);
  return window.openProject(path);
}

// No saved window layout: a window made next starts in the default one.
void forgetSavedLayout() {
  QSettings().remove("window/state");
  QSettings().remove("window/geometry");
}

// `window` on screen at 1920 x 1080 with `path` open.
bool openAt1080p(gui::MainWindow& window, const QString& path) {
  window.setQuiet(true);
  window.document()->setAutosaveInterval(0);
  window.resize(1920, 1080);
  window.show();
  return QTest::qWaitForWindowExposed(&window) && window.openProject(path);
}
}  // namespace

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void saveThenReopenIsIdentical() {
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    gui::MainWindow window;
    QVERIFY(openQuietly(window, path));
    app::Project edited = *window.project();
    edited.tools[0].modes_x[0].stiffness_N_per_um = 6.25;
    QCOMPARE(window.document()->applyEdit(edited, "stiffness"), QString());
    QVERIFY(window.document()->isDirty());
    const QString saved = dir.filePath("saved.mxproj");
    QVERIFY(window.saveProject(saved));
    QVERIFY(!window.document()->isDirty());
    const app::Project reopened = app::loadProject(saved);
    QCOMPARE(app::projectToJson(reopened), app::projectToJson(*window.project()));
    QCOMPARE(reopened.tools[0].modes_x[0].stiffness_N_per_um, 6.25);
  }

  void autosaveRecoveryAfterCrash() {
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    {
      gui::MainWindow window;
      QVERIFY(openQuietly(window, path));
      app::Project edited = *window.project();
      edited.machine->spindle_power_W = 999.0;
      QCOMPARE(window.document()->applyEdit(edited, "power"), QString());
      window.document()->writeAutosave();
      QVERIFY(QFile::exists(path + ".autosave"));
      // Simulated crash: the window goes away without closing (no save, autosave left behind).
    }
    QCOMPARE(app::ProjectDocument::recoveryCandidate(path), path + ".autosave");
    gui::MainWindow window;
    window.setQuiet(true);
    window.setRecoveryPolicy(gui::MainWindow::RecoveryPolicy::Recover);
    QVERIFY(window.openProject(path));
    QCOMPARE(window.project()->machine->spindle_power_W, 999.0);
    QVERIFY(window.document()->isDirty());   // recovered, not yet saved
    window.document()->undoStack()->undo();  // back to the file's content
    QCOMPARE(window.project()->machine->spindle_power_W, 745.3);
  }

  void untitledAutosaveGoesToTheDataFolder() {  // below the runner's private HOME, never a fixed path
    app::ProjectDocument document;
    document.newProject();
    app::Project edited = document.project();
    edited.name = "untitled edit";
    QCOMPARE(document.applyEdit(edited, "name"), QString());
    document.writeAutosave();
    const QString autosave = document.autosavePath();
    QVERIFY2(QFile::exists(autosave), qPrintable(autosave));
    QVERIFY2(autosave.startsWith(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/"),
             qPrintable(autosave));
    QVERIFY2(autosave.startsWith(QDir::homePath() + "/"), qPrintable(autosave));
    QVERIFY(QFile::remove(autosave));
  }

  void failedSavesShowTheErrorAndKeepTheChanges() {
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    const QByteArray original = [&] {
      QFile f(path);
      return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }();
    gui::MainWindow window;
    QVERIFY(openQuietly(window, path));
    app::Project edited = *window.project();
    edited.machine->spindle_power_W = 999.0;
    QCOMPARE(window.document()->applyEdit(edited, "power"), QString());
    QVERIFY(window.isWindowModified());
    {
      test::ReadOnlyFolder read_only(dir.path());
      QVERIFY2(!read_only.writable(), "the folder is still writable: the test would prove nothing");
      QVERIFY(!window.saveProject());
    }
    QString shown = window.statusBar()->currentMessage();
    QVERIFY2(shown.startsWith("Cannot save project: " + path + ": cannot write project file: "), qPrintable(shown));
    QVERIFY(window.document()->isDirty() && window.isWindowModified());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), original);
    file.close();

    QVERIFY(QFile::remove(path) && QDir().mkpath(path));  // the file replaced by a directory
    QAction* save = nullptr;                              // File > Save, as the user reaches it
    for (QAction* action : window.findChildren<QAction*>())
      if (action->shortcut() == QKeySequence(QKeySequence::Save)) save = action;
    QVERIFY(save);
    save->trigger();
    shown = window.statusBar()->currentMessage();
    QVERIFY2(shown.startsWith("Cannot save project: " + path + ": cannot write project file: ") &&
                 shown.contains("directory"),
             qPrintable(shown));
    QVERIFY(window.document()->isDirty() && window.isWindowModified());
    QCOMPARE(window.project()->machine->spindle_power_W, 999.0);
  }

  // A file that cannot be a project (over 64 MB, a FIFO, a device) is refused before it is read: the
  // message names it and the limit, and the open project keeps its edits, point, undo steps and file.
  void unreadableProjectKeepsTheCurrentOne_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("why");
    QTest::newRow("80 MB") << QString("bytes:%1").arg(80 * test::kMB)
                           << "80.0 MB (83886080 bytes) is over the 64 MB limit of a project file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: a project file must be a regular file";
    QTest::newRow("/dev/zero") << "/dev/zero"
                               << "a character device, not a regular file: a project file must be a regular file";
  }
  void unreadableProjectKeepsTheCurrentOne() {
    QFETCH(QString, kind);
    QFETCH(QString, why);
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    gui::MainWindow window;
    QVERIFY(openQuietly(window, path));
    app::Project edited = *window.project();
    edited.machine->spindle_power_W = 999.0;
    const app::PickedPoint point{5800.0, 0.49, 0.27};
    QCOMPARE(window.document()->applyEditAndMovePoint(edited, point, "power and point"), QString());
    const int steps = window.document()->undoStack()->count();
    const QString bad = test::hostileInput(dir, kind);
    QVERIFY(!bad.isEmpty());
    QElapsedTimer clock;
    clock.start();
    QVERIFY(!window.openProject(bad));
    QVERIFY(clock.elapsed() < 5000);
    QCOMPARE(window.statusBar()->currentMessage(), "Cannot open project: " + bad + ": " + why);
    QVERIFY(window.document()->isDirty());
    QCOMPARE(window.document()->filePath(), path);
    QCOMPARE(window.project()->machine->spindle_power_W, 999.0);
    QVERIFY(window.document()->point() == point);
    QCOMPARE(window.document()->undoStack()->count(), steps);
  }

  // Without a saved layout the chart keeps most of the height at 1920 x 1080 (the bottom docks about
  // a third); the toolbar's Undo keeps its place and width whatever it undoes.
  void defaultLayoutLeavesTheChartTheHeight() {
    forgetSavedLayout();
    gui::MainWindow window;
    QVERIFY(openAt1080p(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QTRY_VERIFY2(window.centralWidget()->height() >= 1080 / 2,
                 qPrintable(QString::number(window.centralWidget()->height())));
    auto* toolbar = window.findChild<QToolBar*>("mainToolbar");
    auto* undo = window.findChild<QAction*>("toolbarUndo");
    QVERIFY(toolbar && undo);
    QWidget* button = toolbar->widgetForAction(undo);
    const QRect before = button->geometry();
    QVERIFY(!undo->isEnabled());
    window.document()->setPoint({4000.0, 0.5, 0.1});  // an undoable point move, with its own text
    QVERIFY(undo->isEnabled());
    QVERIFY2(undo->toolTip().startsWith("Undo "), qPrintable(undo->toolTip()));
    QCOMPARE(undo->text(), QString("Undo"));
    QCOMPARE(button->geometry(), before);
    const auto tab_bars = window.findChildren<QTabBar*>(Qt::FindDirectChildrenOnly);
    QVERIFY(!tab_bars.isEmpty());  // the tabbed docks'
    for (const QTabBar* bar : tab_bars) QCOMPARE(bar->elideMode(), Qt::ElideNone);
  }

  // Nothing of the docks is cut at 1920 x 1080 in the default layout: every header of the tool and
  // mode tables is as wide as its text (the tool table scrolls, the mode tables fit), the five tool
  // buttons are whole, and the cost weights fit their dock without scrolling.
  void defaultLayoutCutsNothingAt1080p() {
    forgetSavedLayout();
    gui::MainWindow window;
    QVERIFY(openAt1080p(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    auto* editor = window.findChild<widgets::ToolLibraryEditor*>();
    QVERIFY(editor);
    QTRY_VERIFY(editor->modeModel(widgets::ModeTableModel::Axis::Y)->rowCount() > 0);
    QTest::qWait(100);                                            // the docks' last layout
    const QString shot = qEnvironmentVariable("MX_LAYOUT_SHOT");  // for a look: the window, then with the weights
    if (!shot.isEmpty()) window.grab().save(shot + "-tools.png");
    using Axis = widgets::ModeTableModel::Axis;
    for (QTableView* view : {editor->toolView(), editor->modeView(Axis::X), editor->modeView(Axis::Y)}) {
      const QHeaderView* header = view->horizontalHeader();
      for (int s = 0; s < header->count(); ++s) {
        const QString text = view->model()->headerData(s, Qt::Horizontal).toString();
        QVERIFY2(header->sectionSize(s) >= header->fontMetrics().horizontalAdvance(text),
                 qPrintable(QString("%1: %2 px").arg(text).arg(header->sectionSize(s))));
      }
      if (view != editor->toolView())
        QVERIFY2(header->length() <= view->viewport()->width(),
                 qPrintable(QString("%1 > %2 px").arg(header->length()).arg(view->viewport()->width())));
    }
    int buttons = 0;
    for (const QPushButton* b : editor->findChildren<QPushButton*>())
      if (QStringList{"Add tool", "Duplicate", "Remove", "Import library…", "Export library…"}.contains(b->text())) {
        ++buttons;
        QVERIFY2(b->visibleRegion() == QRegion(b->rect()), qPrintable(b->text()));
      }
    QCOMPARE(buttons, 5);

    auto* weights = window.findChild<QDockWidget*>("weightsDock");
    QVERIFY(weights);
    weights->raise();
    auto* area = qobject_cast<QScrollArea*>(weights->widget());
    QVERIFY(area);
    QTRY_VERIFY(area->isVisible());
    QTest::qWait(100);
    if (!shot.isEmpty()) window.grab().save(shot + "-weights.png");
    QVERIFY2(area->verticalScrollBar()->maximum() == 0,
             qPrintable(QString("the weights need %1 px more").arg(area->verticalScrollBar()->maximum())));
    QCOMPARE(area->horizontalScrollBar()->maximum(), 0);
  }

  // The Pareto weights dock is no wider than the right dock area a 1920 x 1080 window gives it.
  void paretoWeightsFitTheirDockAt1080p() {
    forgetSavedLayout();
    gui::MainWindow window;
    QVERIFY(openAt1080p(window, mx::test::exampleCopy("rubio-pareto-case.mxproj")));
    auto* dock = window.findChild<QDockWidget*>("paretoWeightsDock");
    QVERIFY(dock);
    dock->raise();
    auto* area = qobject_cast<QScrollArea*>(dock->widget());
    QVERIFY(area);
    QTRY_VERIFY(area->isVisible());
    QTest::qWait(100);
    QVERIFY2(area->horizontalScrollBar()->maximum() == 0,
             qPrintable(QString("the Pareto weights need %1 px more").arg(area->horizontalScrollBar()->maximum())));
  }

  void badProjectIsRefusedAndKeepsTheCurrentOne() {
    gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(mx::test::exampleCopy("benchmark-insperger-1dof.mxproj")));
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

MX_REGISTER_TEST(TestMainWindow)
#include "test_main_window.moc"
