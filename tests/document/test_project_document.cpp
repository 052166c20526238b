// ProjectDocument::changed: an edit emits the sections it changed, and its undo and redo emit the
// same; a load emits every section; an edit that changes nothing leaves no undo entry; the edits of
// one gesture merge into one undo step, which is dropped when the gesture ends where it started.
#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <limits>

#include "document/frf_paths.h"
#include "document/project_document.h"
#include "support/project_edits.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;
using app::ProjectSection;

namespace {

const QString kProject = MX_PROJECTS_DIR "/rubio2006-adaptive-control.mxproj";

app::ProjectChanges lastChanges(const QSignalSpy& spy) {
  return spy.last().at(0).value<app::ProjectChanges>();
}

// A project file as MillExpert writes it, with an operating point on C1: 6000 rpm, 2 mm, 0.12 mm/tooth.
QString savedWithPoint(const QTemporaryDir& dir) {
  app::Project p = app::loadProject(kProject);
  p.operating_point = app::OperatingPointSpec{"C1", 6000.0, 2.0, 0.12};
  QString path = dir.filePath("point.mxproj");
  app::saveProject(p, path);
  return path;
}

std::optional<app::OperatingPointSpec> pointInFile(const QString& path) {
  return app::loadProject(path).operating_point;
}

}  // namespace

class TestProjectDocument : public QObject {
  Q_OBJECT

 private slots:
  void saveAsElsewhereKeepsTheFrfFiles() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid() && QDir(dir.path()).mkpath("a") && QDir(dir.path()).mkpath("b"));
    app::ProjectDocument doc;
    doc.load(kProject);
    app::Project edited = doc.project();
    edited.tools[0].frf_x = app::FrfRefSpec{dir.filePath("a/taps/x.uff"), std::nullopt, std::nullopt, {}};
    QCOMPARE(doc.applyEdit(edited, "import tap test"), QString());
    doc.save(dir.filePath("a/p.mxproj"));
    QCOMPARE(doc.project().tools[0].frf_x->file, dir.filePath("a/taps/x.uff"));  // absolute paths stay
    edited = doc.project();
    edited.tools[0].frf_x->file = "taps/x.uff";
    QCOMPARE(doc.applyEdit(edited, "relative"), QString());
    doc.save(dir.filePath("b/p.mxproj"));
    QCOMPARE(doc.project().tools[0].frf_x->file, QString("../a/taps/x.uff"));
    QCOMPARE(app::resolvedFrfPath(doc.project(), *doc.project().tools[0].frf_x), dir.filePath("a/taps/x.uff"));
    QVERIFY(!doc.isDirty());
    doc.undoStack()->undo();  // the older snapshot keeps its own folder, so its path still resolves
    QCOMPARE(app::resolvedFrfPath(doc.project(), *doc.project().tools[0].frf_x), dir.filePath("a/taps/x.uff"));
  }

  void loadEmitsEverySection() {
    app::ProjectDocument doc;
    QSignalSpy changed(&doc, &app::ProjectDocument::changed);
    doc.load(kProject);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(lastChanges(changed), app::kAllSections);
    doc.newProject();
    QCOMPARE(lastChanges(changed), app::kAllSections);
  }

  void undoAndRedoEmitTheEditsSections() {
    app::ProjectDocument doc;
    doc.load(kProject);
    QSignalSpy changed(&doc, &app::ProjectDocument::changed);
    app::Project edited = doc.project();
    edited.tools[0].teeth = 2;
    edited.machine->spindle_power_W = 6000.0;
    QCOMPARE(doc.applyEdit(edited, "teeth and power"), QString());
    const app::ProjectChanges expected = ProjectSection::Tools | ProjectSection::Machine;
    QCOMPARE(changed.count(), 1);
    QCOMPARE(lastChanges(changed), expected);
    doc.undoStack()->undo();
    QCOMPARE(doc.project().tools[0].teeth, 4);
    QCOMPARE(lastChanges(changed), expected);
    doc.undoStack()->redo();
    QCOMPARE(doc.project().tools[0].teeth, 2);
    QCOMPARE(lastChanges(changed), expected);
    QCOMPARE(changed.count(), 3);
  }

  void aNoOpEditLeavesNoUndoEntry() {
    app::ProjectDocument doc;
    doc.load(kProject);
    QSignalSpy changed(&doc, &app::ProjectDocument::changed);
    app::Project same = doc.project();
    same.tools[0].teeth = 4;  // what the file has
    QCOMPARE(doc.applyEdit(same, "same teeth"), QString());
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(changed.count(), 0);
    QVERIFY(!doc.isDirty());
  }

  void oneGestureIsOneUndoStep() {
    app::ProjectDocument doc;
    doc.load(kProject);
    QCOMPARE(*doc.project().control->beta, -0.3);
    QSignalSpy changed(&doc, &app::ProjectDocument::changed);
    const int gesture = doc.newGesture();
    for (double beta : {-0.2, -0.1, 0.0, 0.1, 0.25})
      QCOMPARE(doc.applyEdit(test::withBeta(doc.project(), beta), "beta", gesture), QString());
    QCOMPARE(changed.count(), 5);  // every value of the drag reaches the views
    QCOMPARE(lastChanges(changed), app::ProjectChanges(ProjectSection::ControlBeta));
    QCOMPARE(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    QCOMPARE(*doc.project().control->beta, -0.3);  // the value before the drag
    QCOMPARE(lastChanges(changed), app::ProjectChanges(ProjectSection::ControlBeta));
    QVERIFY(!doc.isDirty());
    doc.undoStack()->redo();
    QCOMPARE(*doc.project().control->beta, 0.25);

    // The next gesture is its own step.
    const int next = doc.newGesture();
    QVERIFY(next != gesture);
    doc.applyEdit(test::withBeta(doc.project(), 0.5), "beta", next);
    doc.applyEdit(test::withBeta(doc.project(), 0.6), "beta", next);
    QCOMPARE(doc.undoStack()->count(), 2);
    doc.undoStack()->undo();
    QCOMPARE(*doc.project().control->beta, 0.25);
  }

  void aGestureBackToItsStartLeavesNoStep() {
    app::ProjectDocument doc;
    doc.load(kProject);
    const int gesture = doc.newGesture();
    doc.applyEdit(test::withBeta(doc.project(), 0.4), "beta", gesture);
    doc.applyEdit(test::withBeta(doc.project(), -0.3), "beta", gesture);
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(*doc.project().control->beta, -0.3);
    QVERIFY(!doc.isDirty());
  }

  void anEditAndAPointMoveAreOneUndoStep() {
    app::ProjectDocument doc;
    doc.load(kProject);
    doc.initPoint({8000.0, 1.0, 0.1});
    const app::PickedPoint moved{9000.0, 2.0, 0.12};
    QCOMPARE(doc.applyEditAndMovePoint(test::withBeta(doc.project(), 0.4), moved, "beta and point"), QString());
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(*doc.project().control->beta, 0.4);
    QCOMPARE(doc.point(), moved);
    doc.undoStack()->undo();
    QCOMPARE(*doc.project().control->beta, -0.3);
    QCOMPARE(doc.point(), app::PickedPoint({8000.0, 1.0, 0.1}));

    // The same project: the step is the point move alone.
    QCOMPARE(doc.applyEditAndMovePoint(doc.project(), moved, "point"), QString());
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.point(), moved);
    // Nothing changes: no step at all.
    QCOMPARE(doc.applyEditAndMovePoint(doc.project(), moved, "nothing"), QString());
    QCOMPARE(doc.undoStack()->count(), 1);
  }

  void aRefusedEditDoesNotMoveThePoint() {
    app::ProjectDocument doc;
    doc.load(kProject);
    doc.initPoint({8000.0, 1.0, 0.1});
    const QString error = doc.applyEditAndMovePoint(test::withBeta(doc.project(), 2.0), {9000.0, 2.0, 0.1}, "beta");
    QVERIFY2(error.contains("beta"), qPrintable(error));
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(doc.point().speed_rpm, 8000.0);
    QCOMPARE(*doc.project().control->beta, -0.3);
  }

  void editsWithoutGestureStaySeparate() {
    app::ProjectDocument doc;
    doc.load(kProject);
    doc.applyEdit(test::withBeta(doc.project(), 0.1), "beta");
    doc.applyEdit(test::withBeta(doc.project(), 0.2), "beta");
    QCOMPARE(doc.undoStack()->count(), 2);
  }

  // Opening a project with a stored point sets the point and its tool, without an undo step.
  void loadTakesTheStoredPoint() {
    QTemporaryDir dir;
    app::ProjectDocument doc;
    QSignalSpy tool(&doc, &app::ProjectDocument::pointToolChanged);
    doc.load(savedWithPoint(dir));
    QCOMPARE(doc.point(), app::PickedPoint({6000.0, 2.0, 0.12}));
    QCOMPARE(doc.pointTool(), QString("C1"));
    QCOMPARE(tool.count(), 1);
    QVERIFY(!doc.isDirty());
    QCOMPARE(doc.undoStack()->count(), 0);
    // A project without one has no point until a view picks one.
    doc.load(kProject);
    QCOMPARE(doc.point(), app::PickedPoint());
    QCOMPARE(doc.pointTool(), QString("C1"));  // the view's tool choice stays
  }

  // An unmodified project saves to the same bytes; a project without a point gains one on save only.
  void saveWritesThePointAndItsTool() {
    QTemporaryDir dir;
    const QString path = savedWithPoint(dir);
    const QByteArray before = test::readBytes(path);
    app::ProjectDocument doc;
    doc.load(path);
    doc.save();
    QCOMPARE(test::readBytes(path), before);

    const QString plain = dir.filePath("plain.mxproj");
    QVERIFY(QFile::copy(kProject, plain));
    doc.load(plain);
    doc.setPointTool("C1");
    doc.save();
    QVERIFY(!pointInFile(plain));  // no point picked yet: nothing to store
    doc.initPoint({4500.0, 1.25, 0.08});
    QVERIFY(!doc.isDirty());
    QVERIFY(!pointInFile(plain));
    doc.save();
    QCOMPARE(*pointInFile(plain), (app::OperatingPointSpec{"C1", 4500.0, 1.25, 0.08}));
    QCOMPARE(doc.project().operating_point, pointInFile(plain));  // what the file holds, without an undo step
    QCOMPARE(doc.undoStack()->count(), 0);
  }

  // A point move is an undoable edit: the moved point is saved, and after its undo the point before it.
  void theUndonePointIsSaved() {
    QTemporaryDir dir;
    const QString path = savedWithPoint(dir);
    app::ProjectDocument doc;
    doc.load(path);
    doc.setPoint({7000.0, 1.5, 0.12});
    QVERIFY(doc.isDirty());
    doc.save();
    QCOMPARE(*pointInFile(path), (app::OperatingPointSpec{"C1", 7000.0, 1.5, 0.12}));
    doc.undoStack()->undo();
    QVERIFY(doc.isDirty());
    doc.save();
    QCOMPARE(*pointInFile(path), (app::OperatingPointSpec{"C1", 6000.0, 2.0, 0.12}));
    doc.setPointTool("C2");  // not a tool of the project: the point stays on C1
    doc.undoStack()->redo();
    doc.save();
    QCOMPARE(*pointInFile(path), (app::OperatingPointSpec{"C1", 6000.0, 2.0, 0.12}));
  }

  // A point the file cannot hold is not written: the stored one stays.
  void anInvalidPointKeepsTheStoredOne_data() {
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("feed_mm_per_tooth");
    QTest::newRow("depth 0") << 6000.0 << 0.0 << 0.12;
    QTest::newRow("feed 0") << 6000.0 << 2.0 << 0.0;
    QTest::newRow("speed above 1e5") << 100001.0 << 2.0 << 0.12;
    QTest::newRow("depth above 1000") << 6000.0 << 1000.5 << 0.12;
    QTest::newRow("depth nan") << 6000.0 << std::numeric_limits<double>::quiet_NaN() << 0.12;
  }
  void anInvalidPointKeepsTheStoredOne() {
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    QFETCH(double, feed_mm_per_tooth);
    QTemporaryDir dir;
    const QString path = savedWithPoint(dir);
    app::ProjectDocument doc;
    doc.load(path);
    doc.setPoint({speed_rpm, depth_mm, feed_mm_per_tooth});
    doc.save();
    QCOMPARE(*pointInFile(path), (app::OperatingPointSpec{"C1", 6000.0, 2.0, 0.12}));
  }

  // Removing the stored point's tool is not refused: the stored point goes with it.
  void removingThePointsToolDropsTheStoredPoint() {
    QTemporaryDir dir;
    app::ProjectDocument doc;
    doc.load(savedWithPoint(dir));
    app::Project edited = doc.project();
    app::ToolSpec other = edited.tools[0];
    other.id = "C2";
    edited.tools = {other};
    QCOMPARE(doc.applyEdit(edited, "rename C1"), QString());
    QVERIFY(!doc.project().operating_point);
    QVERIFY(doc.project().findTool("C2"));
    doc.undoStack()->undo();
    QCOMPARE(doc.project().operating_point->tool, QString("C1"));
  }

  // The autosave holds the moved point; recovering it opens there.
  void recoveryOpensAtTheAutosavedPoint() {
    QTemporaryDir dir;
    const QString path = savedWithPoint(dir);
    {
      app::ProjectDocument doc;
      doc.setAutosaveInterval(0);
      doc.load(path);
      doc.setPoint({5000.0, 1.0, 0.1});
      QCOMPARE(doc.writeAutosave(), QString());
    }
    app::ProjectDocument doc;
    doc.setAutosaveInterval(0);
    doc.recover(path);
    QCOMPARE(doc.point(), app::PickedPoint({5000.0, 1.0, 0.1}));
    QCOMPARE(doc.pointTool(), QString("C1"));
    QVERIFY(doc.isDirty());
  }

  void aPointDragIsOneStep() {
    app::ProjectDocument doc;
    doc.initPoint({3000.0, 1.0, 0.1});
    for (double rpm : {3100.0, 3200.0, 3300.0}) doc.setPoint({rpm, 1.0, 0.1}, 7);
    QCOMPARE(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    QCOMPARE(doc.point().speed_rpm, 3000.0);
    doc.undoStack()->redo();
    doc.setPoint({3400.0, 1.0, 0.1}, 8);
    doc.setPoint({3300.0, 1.0, 0.1}, 8);  // dragged back to where it started
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.point().speed_rpm, 3300.0);
  }
};

MX_REGISTER_TEST(TestProjectDocument)
#include "test_project_document.moc"
