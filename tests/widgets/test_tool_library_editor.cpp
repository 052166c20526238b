// The tool-library editor: in-place edits through the real models and delegates, refusal of invalid
// values (nothing emitted, old value kept, reason shown at once under the cell), undo through a real
// ProjectDocument, selection kept across refreshes, and inch display.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalSpy>
#include <QUndoStack>
#include <numbers>

#include "display_units.h"
#include "document/project_document.h"
#include "input_feedback.h"
#include "range_delegate.h"
#include "support/project_files.h"
#include "support/settle_events.h"
#include "test_registry.h"
#include "tool_library_editor.h"

using mx::app::Project;
using mx::widgets::ModeTableModel;
using mx::widgets::ToolLibraryEditor;
using mx::widgets::ToolTableModel;
using ModeAxis = ModeTableModel::Axis;

namespace {

using mx::test::kRubio;

// The editor wired to a document exactly as the main window does it.
void wire(ToolLibraryEditor& editor, mx::app::ProjectDocument& doc) {
  QObject::connect(&editor, &ToolLibraryEditor::editRequested, &doc,
                   [&doc](const Project& edited, const QString& text) { doc.applyEdit(edited, text); });
  QObject::connect(&doc, &mx::app::ProjectDocument::changed, &editor, [&] { editor.setProject(doc.project()); });
  editor.setProject(doc.project());
}

using mx::test::settle;

// Types `text` into the spin box editor of `index`, as a user who selected the cell.
QAbstractSpinBox* typeKeys(QTableView* view, const QModelIndex& index, const QString& text) {
  view->setCurrentIndex(index);
  view->edit(index);
  auto* box = view->viewport()->findChild<QAbstractSpinBox*>();
  if (!box) return nullptr;
  box->selectAll();
  QTest::keyClicks(box, text);
  return box;
}

// The same, then Return.
void typeInto(QTableView* view, const QModelIndex& index, const QString& text) {
  QAbstractSpinBox* box = typeKeys(view, index, text);
  QVERIFY(box);
  QTest::keyClick(box, Qt::Key_Return);
  settle();
}

// The input note of the editor's window, "" when none is shown.
QString noteText(const QWidget* editor) {
  const QLabel* note = mx::widgets::inputNote(editor);
  return note && note->isVisible() ? note->text() : QString();
}

// The note is right under or above the cell and overlaps it horizontally.
bool noteIsAtTheCell(const QTableView* view, const QModelIndex& index) {
  const QLabel* note = mx::widgets::inputNote(view);
  const QRect rect = view->visualRect(index);
  const QRect cell(view->viewport()->mapToGlobal(rect.topLeft()), rect.size());
  const QRect shown(note->mapToGlobal(QPoint(0, 0)), note->size());
  const bool adjacent = shown.top() == cell.bottom() + 1 || shown.bottom() + 1 == cell.top();
  return adjacent && shown.left() <= cell.right() && shown.right() >= cell.left();
}

bool labelShows(const ToolLibraryEditor& editor, const QString& text) {
  for (const QLabel* label : editor.findChildren<QLabel*>()) {
    if (!label->isHidden() && label->text().contains(text)) return true;
  }
  return false;
}

}  // namespace

class TestToolLibraryEditor : public QObject {
  Q_OBJECT
 private slots:
  void showsTheTools() {
    ToolLibraryEditor editor;
    QSignalSpy selected(&editor, &ToolLibraryEditor::toolSelected);
    editor.setProject(mx::app::loadProject(kRubio));
    ToolTableModel* m = editor.toolModel();
    QCOMPARE(m->rowCount(), 2);
    QCOMPARE(m->headerData(ToolTableModel::Diameter, Qt::Horizontal).toString(), QString("D [mm]"));
    QCOMPARE(m->index(1, ToolTableModel::Id).data().toString(), QString("R2"));
    QCOMPARE(m->index(1, ToolTableModel::Diameter).data().toString(), QString("12.7"));
    QCOMPARE(m->index(1, ToolTableModel::Kr).data().toString(), QString("0.07"));
    QCOMPARE(m->index(1, ToolTableModel::Kt).data().toString(), QString());  // the material's
    QVERIFY(m->index(1, ToolTableModel::Kt).data(Qt::ToolTipRole).toString().contains("600"));
    QCOMPARE(m->index(0, ToolTableModel::ModesX).data().toString(), QString("1"));
    QCOMPARE(editor.currentToolId(), QString("R1"));
    QCOMPARE(selected.count(), 1);
    QVERIFY(editor.selectTool("R2"));
    QCOMPARE(selected.last().at(0).toString(), QString("R2"));
    QCOMPARE(editor.modeModel(ModeAxis::X)->index(0, ModeTableModel::Frequency).data(Qt::EditRole).toDouble(), 900.03);
    QCOMPARE(editor.modeModel(ModeAxis::Y)->index(0, ModeTableModel::Stiffness).data(Qt::EditRole).toDouble(), 0.971);
  }

  // An axis with a tap test names its file; one without says only its direction.
  void showsTheTapTests() {
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(MX_PROJECTS_DIR "/tap-test-example.mxproj"));
    QCOMPARE(editor.currentToolId(), QString("T9"));
    QVERIFY(labelShows(editor, "x direction, tap test taps/T9-x.uff, dataset 0"));
    QVERIFY(labelShows(editor, "y direction, tap test taps/T9-y.uff, dataset 0"));
    editor.setProject(mx::app::loadProject(kRubio));
    QVERIFY(!labelShows(editor, "tap test"));
  }

  void invalidStiffnessIsRefused_data() {
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<QString>("message");
    QTest::newRow("zero") << QVariant(0.0) << "tools[0].modes_x[0].stiffness_N_per_um = 0: must be in [0.001, 1e+06]";
    QTest::newRow("negative") << QVariant(-5.0)
                              << "tools[0].modes_x[0].stiffness_N_per_um = -5: must be in [0.001, 1e+06]";
    QTest::newRow("text") << QVariant("soft") << "tools[0].modes_x[0].stiffness_N_per_um = 'soft': not a number";
  }
  void invalidStiffnessIsRefused() {
    QFETCH(QVariant, value);
    QFETCH(QString, message);
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    ModeTableModel* modes = editor.modeModel(ModeAxis::X);
    const QModelIndex k = modes->index(0, ModeTableModel::Stiffness);
    QVERIFY(!modes->setData(k, value, Qt::EditRole));
    QCOMPARE(spy.count(), 0);
    QCOMPARE(k.data(Qt::EditRole).toDouble(), 5.59);
    QCOMPARE(editor.errorText(), message);
    QVERIFY(labelShows(editor, message));
  }

  void typedStiffnessGoesThroughTheDelegate() {
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    QTableView* view = editor.modeView(ModeAxis::X);
    const QModelIndex k = editor.modeModel(ModeAxis::X)->index(0, ModeTableModel::Stiffness);
    typeInto(view, k, "0");  // below the box's minimum, the rule's 0.001
    QCOMPARE(spy.count(), 0);
    QCOMPARE(k.data(Qt::EditRole).toDouble(), 5.59);
    QVERIFY(noteText(view).contains("\"0\" is below the minimum"));

    typeInto(view, k, "7.25");
    QCOMPARE(spy.count(), 1);
    const Project edited = spy.at(0).at(0).value<Project>();
    QCOMPARE(edited.tools[0].modes_x[0].stiffness_N_per_um, 7.25);
    QCOMPARE(edited.tools[0].modes_y[0].stiffness_N_per_um, 5.715);
    QCOMPARE(editor.errorText(), QString());  // a good edit clears the message
  }

  // Typing what a cell's box cannot take is answered at once under the cell; ending the edit there
  // keeps the old value and the note.
  void badInputIsAnsweredAtTheCell_data() {
    QTest::addColumn<bool>("toolTable");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("message");
    QTest::addColumn<QString>("kept");
    const QString stiffness = "Stiffness k [N/µm] must be between 0.001 and 1000000; ";
    const QString teeth = "Teeth must be a whole number from 1 to 100; ";
    const int k = ModeTableModel::Stiffness;
    const int z = ToolTableModel::Teeth;
    QTest::newRow("stiffness -5") << false << k << "-5" << stiffness + "\"-5\" is below the minimum."
                                  << "5.59";
    QTest::newRow("stiffness too large") << false << k << "1000001" << stiffness + "\"1000001\" is above the maximum."
                                         << "5.59";
    QTest::newRow("teeth abc") << true << z << "abc" << teeth + "\"abc\" is not a number."
                               << "3";
    QTest::newRow("teeth 101") << true << z << "101" << teeth + "\"101\" is above the maximum."
                               << "3";
    QTest::newRow("diameter -1") << true << int(ToolTableModel::Diameter) << "-1"
                                 << "Diameter D [mm] must be between 0 and 1000; \"-1\" is below the minimum."
                                 << "30 mm";
    QTest::newRow("teeth 2.5") << true << z << "2.5" << teeth + "\"2.5\" is not a whole number."
                               << "3";
  }
  void badInputIsAnsweredAtTheCell() {
    QFETCH(bool, toolTable);
    QFETCH(int, column);
    QFETCH(QString, typed);
    QFETCH(QString, message);
    QFETCH(QString, kept);
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    editor.resize(900, 700);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    QTableView* view = toolTable ? editor.toolView() : editor.modeView(ModeAxis::X);
    QAbstractItemModel* model = view->model();
    const QModelIndex cell = model->index(0, column);
    const QVariant before = cell.data(Qt::EditRole);

    QAbstractSpinBox* box = typeKeys(view, cell, typed);
    QVERIFY(box);
    QCOMPARE(noteText(view), message);  // at once, before the edit ends
    QVERIFY(noteIsAtTheCell(view, cell));

    QTest::keyClick(box, Qt::Key_Return);
    settle();
    QCOMPARE(spy.count(), 0);
    QCOMPARE(cell.data(Qt::EditRole), before);
    QCOMPARE(noteText(view), message + " The value stays " + kept + ".");
    QVERIFY(noteIsAtTheCell(view, cell));
  }

  // A value the box takes but the project's rules refuse: the rule's message under the cell.
  void documentRefusalIsShownAtTheCell_data() {
    QTest::addColumn<bool>("toolTable");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message");
    QTest::newRow("diameter 0") << true << int(ToolTableModel::Diameter)
                                << "tools[0].diameter_mm = 0: must be in (0, 1000]";
    QTest::newRow("frequency 0") << false << int(ModeTableModel::Frequency)
                                 << "tools[0].modes_x[0].freq_Hz = 0: must be in (0, 20000]";
  }
  void documentRefusalIsShownAtTheCell() {
    QFETCH(bool, toolTable);
    QFETCH(int, column);
    QFETCH(QString, message);
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    editor.resize(900, 700);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    QTableView* view = toolTable ? editor.toolView() : editor.modeView(ModeAxis::X);
    const QModelIndex cell = view->model()->index(0, column);
    const QVariant before = cell.data(Qt::EditRole);
    typeInto(view, cell, "0");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(cell.data(Qt::EditRole), before);
    QCOMPARE(editor.errorText(), message);
    QCOMPARE(noteText(view), message + ". The cell keeps its value.");
    QVERIFY(noteIsAtTheCell(view, cell));
  }

  void validStiffnessEmitsTheNewValue() {
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    editor.selectTool("R2");
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    ModeTableModel* modes = editor.modeModel(ModeAxis::Y);
    QVERIFY(modes->setData(modes->index(0, ModeTableModel::Stiffness), 1.25, Qt::EditRole));
    QCOMPARE(spy.count(), 1);
    const Project edited = spy.at(0).at(0).value<Project>();
    QCOMPARE(edited.tools[1].modes_y[0].stiffness_N_per_um, 1.25);
    QVERIFY(spy.at(0).at(1).toString().contains("stiffness_N_per_um"));
  }

  void undoRestoresTheOldValue() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    ToolLibraryEditor editor;
    wire(editor, doc);
    editor.selectTool("R2");
    ModeTableModel* modes = editor.modeModel(ModeAxis::X);
    const QModelIndex k = modes->index(0, ModeTableModel::Stiffness);
    QVERIFY(modes->setData(k, 2.5, Qt::EditRole));
    QCOMPARE(doc.project().tools[1].modes_x[0].stiffness_N_per_um, 2.5);
    QCOMPARE(k.data(Qt::EditRole).toDouble(), 2.5);
    doc.undoStack()->undo();
    QCOMPARE(doc.project().tools[1].modes_x[0].stiffness_N_per_um, 0.879);
    QCOMPARE(modes->index(0, ModeTableModel::Stiffness).data(Qt::EditRole).toDouble(), 0.879);
    QCOMPARE(editor.currentToolId(), QString("R2"));  // the selection survives the refresh
    doc.undoStack()->redo();
    QCOMPARE(modes->index(0, ModeTableModel::Stiffness).data(Qt::EditRole).toDouble(), 2.5);
  }

  void addDuplicateRemoveAreUndoable() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    ToolLibraryEditor editor;
    wire(editor, doc);
    QSignalSpy selected(&editor, &ToolLibraryEditor::toolSelected);
    editor.addTool();
    QCOMPARE(selected.count(), 1);  // straight to the new tool, no transient "" on the model reset
    QCOMPARE(selected.at(0).at(0).toString(), QString("T1"));
    QCOMPARE(doc.project().tools.size(), std::size_t{3});
    QCOMPARE(doc.project().tools[2].id, QString("T1"));
    QCOMPARE(editor.currentToolId(), QString("T1"));
    editor.selectTool("R1");
    editor.duplicateTool();
    QCOMPARE(doc.project().tools[1].id, QString("R1-copy"));
    QCOMPARE(doc.project().tools[1].modes_y[0].freq_Hz, 666.0);
    QCOMPARE(editor.currentToolId(), QString("R1-copy"));
    editor.removeTool();
    QCOMPARE(doc.project().tools.size(), std::size_t{3});
    QCOMPARE(editor.currentToolId(), QString("R2"));
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(editor.toolModel()->rowCount(), 2);
    QVERIFY(!editor.currentToolId().isEmpty());
  }

  void modesAreAddedAndRemoved() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    ToolLibraryEditor editor;
    wire(editor, doc);
    ModeTableModel* x = editor.modeModel(ModeAxis::X);
    QVERIFY(x->addMode());
    QCOMPARE(doc.project().tools[0].modes_x.size(), std::size_t{2});
    QCOMPARE(x->rowCount(), 2);
    QVERIFY(x->removeMode(0));
    QCOMPARE(doc.project().tools[0].modes_x.size(), std::size_t{1});
    QVERIFY(editor.modeModel(ModeAxis::Y)->removeMode(0));
    QVERIFY(doc.project().tools[0].modes_y.empty());  // a rigid axis is allowed
  }

  void invalidToolEditsAreRefused_data() {
    QTest::addColumn<int>("column");
    QTest::addColumn<QVariant>("value");
    QTest::addColumn<QString>("message");
    QTest::newRow("diameter") << int(ToolTableModel::Diameter) << QVariant(0.0)
                              << "tools[0].diameter_mm = 0: must be in (0, 1000]";
    QTest::newRow("teeth") << int(ToolTableModel::Teeth) << QVariant(0)
                           << "tools[0].teeth = 0: must be an integer in [1, 100]";
    QTest::newRow("teeth above 100") << int(ToolTableModel::Teeth) << QVariant(101)
                                     << "tools[0].teeth = 101: must be an integer in [1, 100]";
    QTest::newRow("helix") << int(ToolTableModel::Helix) << QVariant(90.0)
                           << "tools[0].helix_deg = 90: must be in (-90, 90)";
    QTest::newRow("duplicate id") << int(ToolTableModel::Id) << QVariant("R2")
                                  << "tools[1].id = \"R2\": duplicate of tools[0].id";
    QTest::newRow("radial depth > D") << int(ToolTableModel::RadialDepth) << QVariant(31.0)
                                      << "tools[0].radial_depth_mm = 31: must be in (0, 30]";
    QTest::newRow("max force zero") << int(ToolTableModel::MaxForce) << QVariant(0.0)
                                    << "tools[0].max_force_N = 0: must be in (0, 1e+07]";
    QTest::newRow("edge force negative") << int(ToolTableModel::Kte) << QVariant(-0.5)
                                         << "tools[0].Kte_N_mm = -0.5: must be in [0, 10000]";
    QTest::newRow("radial edge force above 1e4")
        << int(ToolTableModel::Kre) << QVariant(10000.01) << "tools[0].Kre_N_mm = 10000.01: must be in [0, 10000]";
    QTest::newRow("axial coefficient above 1e5")
        << int(ToolTableModel::Ka) << QVariant(100001.0) << "tools[0].Ka_N_mm2 = 100001: must be in [0, 1e+05]";
    QTest::newRow("axial edge force negative")
        << int(ToolTableModel::Kae) << QVariant(-1.0) << "tools[0].Kae_N_mm = -1: must be in [0, 10000]";
    // R1: 3 teeth, D = 30 mm (|runout| < 7500 um)
    QTest::newRow("pitch wrong length")
        << int(ToolTableModel::Pitch) << QVariant("170; 190")
        << "tools[0].pitch_deg = [170, 190]: must have one value per tooth (teeth = 3), got 2";
    QTest::newRow("pitch zero") << int(ToolTableModel::Pitch) << QVariant("0; 180; 180")
                                << "tools[0].pitch_deg[0] = 0: must be in (0, 360)";
    QTest::newRow("pitch negative") << int(ToolTableModel::Pitch) << QVariant("200; -20; 180")
                                    << "tools[0].pitch_deg[1] = -20: must be in (0, 360)";
    QTest::newRow("pitch sum 1e-5 off")
        << int(ToolTableModel::Pitch) << QVariant("120; 120; 120.00001")
        << "tools[0].pitch_deg = [120, 120, 120.00001]: must sum to 360 within 1e-06, sums to 360.00001";
    QTest::newRow("pitch not a number")
        << int(ToolTableModel::Pitch) << QVariant("120; x; 120")
        << "tools[0].pitch_deg = '120; x; 120': value 2 ('x') is not a number (one number per tooth, separated by ';'";
    QTest::newRow("pitch comma-separated")
        << int(ToolTableModel::Pitch) << QVariant("120,120,120")
        << "tools[0].pitch_deg = '120,120,120': value 1 ('120,120,120') is not a number";
    QTest::newRow("runout too large") << int(ToolTableModel::Runout) << QVariant("0; 7500; 0")
                                      << "tools[0].runout_um[1] = 7500: must be in (-7500, 7500)";
    QTest::newRow("runout wrong length") << int(ToolTableModel::Runout) << QVariant("5")
                                         << "tools[0].runout_um = [5]: must have one value per tooth (teeth = 3)";
  }
  void invalidToolEditsAreRefused() {
    QFETCH(int, column);
    QFETCH(QVariant, value);
    QFETCH(QString, message);
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    const QModelIndex cell = editor.toolModel()->index(0, column);
    const QVariant before = cell.data(Qt::EditRole);
    QVERIFY(!editor.toolModel()->setData(cell, value, Qt::EditRole));
    QCOMPARE(spy.count(), 0);
    QCOMPARE(cell.data(Qt::EditRole), before);
    QVERIFY2(editor.errorText().startsWith(message), qPrintable(editor.errorText()));
    QVERIFY(labelShows(editor, message));
  }

  // Pitch and runout: ';'-separated lists in deg and um, "uniform" / "none" (or an empty cell) for
  // none; each edit is one undo step; teeth cannot change under a pitch list of another length.
  void pitchAndRunoutAreUndoableEdits() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    ToolLibraryEditor editor;
    wire(editor, doc);
    ToolTableModel* m = editor.toolModel();
    QCOMPARE(m->headerData(ToolTableModel::Pitch, Qt::Horizontal).toString(), QString("pitch [°]"));
    QCOMPARE(m->headerData(ToolTableModel::Runout, Qt::Horizontal).toString(), QString("runout [µm]"));
    const QModelIndex pitch = m->index(0, ToolTableModel::Pitch);
    const QModelIndex runout = m->index(0, ToolTableModel::Runout);
    QCOMPARE(pitch.data().toString(), QString("uniform"));
    QCOMPARE(runout.data().toString(), QString("none"));
    QVERIFY(m->setData(pitch, "100;130 ; 130"));
    QCOMPARE(*doc.project().tools[0].pitch_deg, (std::vector<double>{100, 130, 130}));
    QCOMPARE(pitch.data().toString(), QString("100; 130; 130"));
    QCOMPARE(editor.toolPicture()->cutter()->toothAngleRad(1), 100.0 * std::numbers::pi / 180.0);
    QVERIFY(m->setData(runout, "0; 8; -5"));
    QCOMPARE(*doc.project().tools[0].runout_um, (std::vector<double>{0, 8, -5}));

    QVERIFY(!m->setData(m->index(0, ToolTableModel::Teeth), 4));
    QVERIFY2(editor.errorText().startsWith("tools[0].pitch_deg = [100, 130, 130]: must have one value per tooth "
                                           "(teeth = 4), got 3"),
             qPrintable(editor.errorText()));
    QCOMPARE(doc.project().tools[0].teeth, 3);

    const int steps = doc.undoStack()->index();
    QVERIFY(m->setData(pitch, ""));  // "" is "uniform" as well
    QVERIFY(!doc.project().tools[0].pitch_deg);
    QVERIFY(m->setData(runout, "None"));
    QVERIFY(!doc.project().tools[0].runout_um);
    QVERIFY(m->setData(pitch, "uniform"));  // no change: no undo step
    QCOMPARE(doc.undoStack()->index(), steps + 2);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(*doc.project().tools[0].pitch_deg, (std::vector<double>{100, 130, 130}));
    QCOMPARE(m->index(0, ToolTableModel::Runout).data().toString(), QString("0; 8; -5"));
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QVERIFY(!doc.project().tools[0].pitch_deg && !doc.project().tools[0].runout_um);
    QCOMPARE(m->index(0, ToolTableModel::Pitch).data().toString(), QString("uniform"));
  }

  void optionalOverridesAreSetAndCleared() {
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(kRubio));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    ToolTableModel* m = editor.toolModel();
    QVERIFY(m->setData(m->index(0, ToolTableModel::Kt), 700.0));
    QCOMPARE(*spy.at(0).at(0).value<Project>().tools[0].Kt_N_mm2, 700.0);
    QVERIFY(m->setData(m->index(0, ToolTableModel::Kr), QVariant()));  // back to the material's
    QVERIFY(!spy.at(1).at(0).value<Project>().tools[0].Kr);
    QVERIFY(m->setData(m->index(1, ToolTableModel::Id), "R2b"));
    QCOMPARE(spy.at(2).at(0).value<Project>().tools[1].id, QString("R2b"));
    // F_allow (Rule 3): set in N, cleared back to "none" (the project has no breakage limit).
    QCOMPARE(m->headerData(ToolTableModel::MaxForce, Qt::Horizontal).toString(), QString("F_allow [N]"));
    QVERIFY(m->index(0, ToolTableModel::MaxForce).data(Qt::ToolTipRole).toString().contains("empty = no limit"));
    QVERIFY(m->setData(m->index(0, ToolTableModel::MaxForce), 450.0));
    QCOMPARE(*spy.at(3).at(0).value<Project>().tools[0].max_force_N, 450.0);
    editor.setProject(spy.at(3).at(0).value<Project>());
    QCOMPARE(m->index(0, ToolTableModel::MaxForce).data().toString(), QString("450"));
    QVERIFY(m->setData(m->index(0, ToolTableModel::MaxForce), QVariant()));
    QVERIFY(!spy.at(4).at(0).value<Project>().tools[0].max_force_N);
  }

  // K_te, K_re, K_a, K_ae: per-tool overrides of the material's edge and axial coefficients, each edit one
  // undo step; the edge values of their ranges are accepted, and an empty cell is the material's again.
  void edgeAndAxialOverrides_data() {
    QTest::addColumn<int>("column");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("header");
    QTest::newRow("K_te zero") << int(ToolTableModel::Kte) << 0.0 << "K_te [N/mm]";
    QTest::newRow("K_te at 1e4") << int(ToolTableModel::Kte) << 1e4 << "K_te [N/mm]";
    QTest::newRow("K_re") << int(ToolTableModel::Kre) << 26.6 << "K_re [N/mm]";
    QTest::newRow("K_a at 1e5") << int(ToolTableModel::Ka) << 1e5 << "K_a [N/mm²]";
    QTest::newRow("K_ae") << int(ToolTableModel::Kae) << 0.7 << "K_ae [N/mm]";
  }
  void edgeAndAxialOverrides() {
    QFETCH(int, column);
    QFETCH(double, value);
    QFETCH(QString, header);
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    ToolLibraryEditor editor;
    wire(editor, doc);
    ToolTableModel* m = editor.toolModel();
    QCOMPARE(m->headerData(column, Qt::Horizontal).toString(), header);
    const QModelIndex cell = m->index(0, column);
    QCOMPARE(cell.data().toString(), QString());  // the material's
    QVERIFY(cell.data(Qt::ToolTipRole).toString().contains("empty = the material's 0"));
    QCOMPARE(cell.data(mx::widgets::RangeDelegate::SpecialTextRole).toString(), QString("material's"));
    QVERIFY(cell.data(mx::widgets::RangeDelegate::MinimumRole).toDouble() < 0.0);  // 0 is a value
    const int steps = doc.undoStack()->index();
    QVERIFY(m->setData(cell, value));
    QCOMPARE(doc.undoStack()->index(), steps + 1);
    QCOMPARE(cell.data(Qt::EditRole).toDouble(), value);
    const mx::app::ToolSpec& t = doc.project().tools[0];
    const std::optional<double> stored = column == ToolTableModel::Kte   ? t.Kte_N_mm
                                         : column == ToolTableModel::Kre ? t.Kre_N_mm
                                         : column == ToolTableModel::Ka  ? t.Ka_N_mm2
                                                                         : t.Kae_N_mm;
    QCOMPARE(stored, std::optional<double>(value));
    QVERIFY(m->setData(cell, QVariant()));
    QVERIFY(!cell.data(Qt::EditRole).isValid());
    doc.undoStack()->undo();
    QCOMPARE(cell.data(Qt::EditRole).toDouble(), value);
  }

  void inchUnits() {
    mx::widgets::DisplayUnits units;
    ToolLibraryEditor editor;
    editor.setUnits(&units);
    editor.setProject(mx::app::loadProject(kRubio));
    units.setLength(mx::widgets::DisplayUnits::Length::Inch);
    ToolTableModel* m = editor.toolModel();
    const QModelIndex d = m->index(0, ToolTableModel::Diameter);
    QCOMPARE(m->headerData(ToolTableModel::Diameter, Qt::Horizontal).toString(), QString("D [in]"));
    QCOMPARE(d.data().toString(), QString("1.1811"));
    QVERIFY(qAbs(d.data(Qt::EditRole).toDouble() - 30.0 / 25.4) < 1e-12);
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    QVERIFY(m->setData(d, 1.0));
    QCOMPARE(spy.at(0).at(0).value<Project>().tools[0].diameter_mm, 25.4);

    // Through the delegate: the spin box shows inches, typing 1 stores 25.4 mm.
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QTableView* view = editor.toolView();
    const QModelIndex d2 = m->index(1, ToolTableModel::Diameter);
    view->edit(d2);
    auto* box = view->viewport()->findChild<QDoubleSpinBox*>();
    QVERIFY(box);
    QCOMPARE(box->suffix(), QString(" in"));
    QCOMPARE(box->value(), 0.5);  // 12.7 mm
    box->selectAll();
    QTest::keyClicks(box, "1");
    QTest::keyClick(box, Qt::Key_Return);
    settle();
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.at(1).at(0).value<Project>().tools[1].diameter_mm, 25.4);
  }

  void openingAndClosingAnEditorChangesNothing() {
    ToolLibraryEditor editor;
    editor.setProject(mx::app::loadProject(MX_PROJECTS_DIR "/benchmark-insperger-1dof.mxproj"));
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QSignalSpy spy(&editor, &ToolLibraryEditor::editRequested);
    QTableView* view = editor.modeView(ModeAxis::X);
    const QModelIndex k = editor.modeModel(ModeAxis::X)->index(0, ModeTableModel::Stiffness);
    view->edit(k);
    auto* box = view->viewport()->findChild<QDoubleSpinBox*>();
    QVERIFY(box);
    QTest::keyClick(box, Qt::Key_Return);  // 1.3400496480507487 shown as 1.3400: not an edit
    settle();
    QVERIFY(!view->viewport()->findChild<QDoubleSpinBox*>());  // the editor was committed and closed
    QCOMPARE(spy.count(), 0);
  }
};

MX_REGISTER_TEST(TestToolLibraryEditor)
#include "test_tool_library_editor.moc"
