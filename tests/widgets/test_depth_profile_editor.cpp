// DepthProfileEditor: cells are checked at their edge values (length > 0, depth >= 0), an invalid cell
// is refused in place with the row and the reason and shows its previous value, the last step cannot
// be removed, rows are added as copies, and every valid change emits the whole profile once.
#include <QApplication>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>

#include "depth_profile_editor.h"
#include "test_registry.h"

using mx::widgets::DepthProfileEditor;
using mx::widgets::DepthStepView;
using Steps = QVector<DepthStepView>;

namespace {
const Steps kPaper = {{100.0, 1.0}, {80.0, 2.0}, {60.0, 1.5}, {40.0, 0.5}};

void typeCell(DepthProfileEditor& editor, int row, int column, const QString& text) {
  editor.table()->item(row, column)->setText(text);  // as the delegate does on commit
}
}  // namespace

class TestDepthProfileEditor : public QObject {
  Q_OBJECT
 private slots:
  void parseCell_data() {
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("reason");
    QTest::newRow("depth 0 (air cut)") << 1 << "0" << true << 0.0 << "";
    QTest::newRow("depth 2.5") << 1 << " 2.5 " << true << 2.5 << "";
    QTest::newRow("depth -1") << 1 << "-1" << false << 0.0 << "Depth [mm] = -1: must be >= 0";
    QTest::newRow("depth -1e-9") << 1 << "-1e-9" << false << 0.0 << "Depth [mm] = -1e-9: must be >= 0";
    QTest::newRow("depth text") << 1 << "deep" << false << 0.0 << "Depth [mm] = deep: not a number";
    QTest::newRow("depth inf") << 1 << "inf" << false << 0.0 << "Depth [mm] = inf: not a number";
    QTest::newRow("length 1e-6") << 0 << "1e-6" << true << 1e-6 << "";
    QTest::newRow("length 0") << 0 << "0" << false << 0.0 << "Length [mm] = 0: must be > 0";
    QTest::newRow("length -5") << 0 << "-5" << false << 0.0 << "Length [mm] = -5: must be > 0";
    QTest::newRow("length empty") << 0 << "" << false << 0.0 << "Length [mm] = (empty): not a number";
  }
  void parseCell() {
    QFETCH(int, column);
    QFETCH(QString, text);
    QFETCH(bool, valid);
    QFETCH(double, value);
    QFETCH(QString, reason);
    QString why;
    const auto v = DepthProfileEditor::parseCell(static_cast<DepthProfileEditor::Column>(column), text, &why);
    QCOMPARE(v.has_value(), valid);
    if (valid) {
      QCOMPARE(*v, value);
    } else {
      QCOMPARE(why, reason);
    }
  }

  void roundTripWithoutSignal() {
    DepthProfileEditor editor;
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    editor.setSteps(kPaper);
    QCOMPARE(editor.steps(), kPaper);
    QCOMPARE(editor.table()->rowCount(), 4);
    QCOMPARE(editor.table()->horizontalHeaderItem(0)->text(), QString("Length [mm]"));
    QCOMPARE(editor.table()->horizontalHeaderItem(1)->text(), QString("Depth [mm]"));
    QCOMPARE(editor.table()->item(3, 1)->text(), QString("0.5"));
    QCOMPARE(editor.summaryText(), QString("Total length: 280 mm, 3 depth changes"));
    QCOMPARE(spy.count(), 0);
  }

  void validCellEmitsProfile() {
    DepthProfileEditor editor;
    editor.setSteps(kPaper);
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    typeCell(editor, 1, DepthProfileEditor::kDepth, "3");
    QCOMPARE(spy.count(), 1);
    Steps expected = kPaper;
    expected[1].depth_mm = 3.0;
    QCOMPARE(spy.at(0).at(0).value<Steps>(), expected);
    QCOMPARE(editor.steps(), expected);
    typeCell(editor, 1, DepthProfileEditor::kDepth, "3.0");  // same value: no signal
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editor.table()->item(1, 1)->text(), QString("3"));
    QCOMPARE(editor.errorText(), QString());
  }

  void negativeDepthRefused() {
    DepthProfileEditor editor;
    editor.setSteps(kPaper);
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    typeCell(editor, 1, DepthProfileEditor::kDepth, "-1");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.steps(), kPaper);
    QCOMPARE(editor.table()->item(1, 1)->text(), QString("2"));  // the previous value again
    QCOMPARE(editor.errorText(), QString("Row 2: Depth [mm] = -1: must be >= 0"));
    typeCell(editor, 0, DepthProfileEditor::kLength, "0");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.errorText(), QString("Row 1: Length [mm] = 0: must be > 0"));
    typeCell(editor, 0, DepthProfileEditor::kLength, "120");  // a valid edit clears the message
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editor.errorText(), QString());
  }

  void addCopiesTheCurrentStep() {
    DepthProfileEditor editor;
    editor.setSteps(kPaper);
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    editor.table()->setCurrentCell(1, 0);
    editor.addButton()->click();
    QCOMPARE(spy.count(), 1);
    const Steps expected = {{100.0, 1.0}, {80.0, 2.0}, {80.0, 2.0}, {60.0, 1.5}, {40.0, 0.5}};
    QCOMPARE(editor.steps(), expected);
    QCOMPARE(editor.table()->rowCount(), 5);
  }

  void addToEmptyProfile() {
    DepthProfileEditor editor;
    editor.setSteps({});
    QCOMPARE(editor.table()->rowCount(), 0);
    QVERIFY(!editor.removeButton()->isEnabled());
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    editor.addButton()->click();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editor.steps(), Steps({{DepthProfileEditor::kDefaultLengthMm, DepthProfileEditor::kDefaultDepthMm}}));
  }

  void removeSelectedSteps() {
    DepthProfileEditor editor;
    editor.setSteps(kPaper);
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    editor.table()->selectRow(2);
    editor.removeButton()->click();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editor.steps(), Steps({{100.0, 1.0}, {80.0, 2.0}, {40.0, 0.5}}));
  }

  void emptyProfileRefused() {
    DepthProfileEditor editor;
    editor.setSteps({{50.0, 1.0}, {50.0, 2.0}});
    QSignalSpy spy(&editor, &DepthProfileEditor::stepsEdited);
    editor.table()->selectAll();
    editor.removeButton()->click();  // every row: refused
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.steps().size(), 2);
    QCOMPARE(editor.errorText(), QString("Not removed: the profile needs at least one step."));
    editor.table()->clearSelection();
    editor.table()->setCurrentCell(0, 0);
    editor.removeButton()->click();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(editor.steps(), Steps({{50.0, 2.0}}));
    QVERIFY(!editor.removeButton()->isEnabled());  // the last step stays
    editor.removeButton()->click();
    QCOMPARE(editor.steps().size(), 1);
    QCOMPARE(spy.count(), 1);
  }
};

MX_REGISTER_TEST(TestDepthProfileEditor)
#include "test_depth_profile_editor.moc"
