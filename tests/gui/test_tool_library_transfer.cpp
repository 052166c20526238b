// The tool library's Import and Export in the window: the file is read on the engine thread (the event
// loop keeps turning), the chosen tools join the project as one undoable step with clashing ids
// renamed, a refused file changes nothing and says why, and an export reads back as the same tools.
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "main_window.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"
#include "tool_library_editor.h"
#include "tool_library_transfer.h"

using namespace mx;
using Transfer = gui::ToolLibraryTransfer;

using mx::test::writeText;

namespace {

const QByteArray kCsv =
    "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,damping_pct,stiffness_N_per_um\n"
    "R2,3,12,30,,,,x,900,2,5\n"
    "E16,4,16,30,,,,x,720,2.5,4.2\n";

bool open(gui::MainWindow& w) {
  w.setQuiet(true);
  w.document()->setAutosaveInterval(0);
  return w.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj"));
}

Transfer* transferOf(const gui::MainWindow& w) {
  return test::editorsOf(w)->libraryTransfer();
}

// Runs one import with `choice` and returns importFinished's error ("" on success).
QString runImport(gui::MainWindow& w, const QString& path, const std::optional<Transfer::Choice>& choice,
                  QString* summary = nullptr) {
  QSignalSpy finished(transferOf(w), &Transfer::importFinished);
  transferOf(w)->importFile(path, std::nullopt, {},
                            [choice](const QString&, const app::ImportedLibrary&) { return choice; });
  if (!finished.wait(30000)) return "no importFinished";
  if (summary) *summary = finished.at(0).at(1).toString();
  return finished.at(0).at(0).toString();
}

QStringList toolIds(const gui::MainWindow& w) {
  QStringList ids;
  for (const app::ToolSpec& t : w.project()->tools) ids << t.id;
  return ids;
}

}  // namespace

class TestToolLibraryTransfer : public QObject {
  Q_OBJECT
 private slots:
  void appendIsOneUndoableStep() {
    gui::MainWindow w;
    QVERIFY(open(w));
    QTemporaryDir dir;
    QString summary;
    QCOMPARE(runImport(w, writeText(dir, "lib.csv", kCsv), Transfer::Choice{{}, false}, &summary), QString());
    QCOMPARE(toolIds(w), QStringList({"R1", "R2", "R2-2", "E16"}));
    QCOMPARE(summary, QString("2 tools from lib.csv; renamed: R2 → R2-2"));
    w.document()->undoStack()->undo();
    QCOMPARE(toolIds(w), QStringList({"R1", "R2"}));
  }

  void replaceWithASelection() {
    gui::MainWindow w;
    QVERIFY(open(w));
    QTemporaryDir dir;
    QCOMPARE(runImport(w, writeText(dir, "lib.csv", kCsv), Transfer::Choice{{"E16"}, true}), QString());
    QCOMPARE(toolIds(w), QStringList({"E16"}));
  }

  void cancelChangesNothing() {
    gui::MainWindow w;
    QVERIFY(open(w));
    QTemporaryDir dir;
    QCOMPARE(runImport(w, writeText(dir, "lib.csv", kCsv), std::nullopt), QString("cancelled"));
    QCOMPARE(toolIds(w), QStringList({"R1", "R2"}));
    QVERIFY(!w.document()->isDirty());
  }

  // A refused file leaves the project and shows the reason in the editor.
  void refusalIsShown() {
    gui::MainWindow w;
    QVERIFY(open(w));
    QTemporaryDir dir;
    const QString error =
        runImport(w, writeText(dir, "bad.csv", kCsv + "X,2,10,0,,,,x,-3,2,5\n"), Transfer::Choice{{}, false});
    QCOMPARE(error, QString("bad.csv: line 4, column 9 (freq_Hz): '-3' must be in (0, 20000]"));
    QCOMPARE(toolIds(w), QStringList({"R1", "R2"}));
    QVERIFY(test::editorsOf(w)->toolEditor()->errorText().contains("'-3' must be in (0, 20000]"));
  }

  void exportReadsBackAsTheSameTools_data() {
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("csv") << int(app::ToolLibraryFormat::Csv) << "lib.csv";
    QTest::newRow("json") << int(app::ToolLibraryFormat::Json) << "lib.json";
  }
  void exportReadsBackAsTheSameTools() {
    QFETCH(int, format);
    QFETCH(QString, name);
    gui::MainWindow w;
    QVERIFY(open(w));
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    QCOMPARE(transferOf(w)->exportFile(path, app::ToolLibraryFormat(format)), QString());
    const std::vector<app::ToolSpec> before = w.project()->tools;
    QCOMPARE(runImport(w, path, Transfer::Choice{{}, true}), QString());
    QCOMPARE(w.project()->tools, before);
  }
};

MX_REGISTER_TEST(TestToolLibraryTransfer)
#include "test_tool_library_transfer.moc"
