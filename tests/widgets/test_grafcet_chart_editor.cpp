// GrafcetChartEditor: add and remove steps and transitions through the buttons, edit cells,
// show the validator's issues inline (list, tinted rows, click selects the element) and emit
// chartEdited only for an edit with no issue.
#include <QApplication>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
GrafcetChartData smallChart() {
  GrafcetChartData c;
  c.name = QStringLiteral("SMC I");
  c.steps = {{1, "Initialize modules", true, {"L*"}}, {2, "No contact", false, {"A", "B", "I", "J"}}};
  c.transitions = {{1, {1}, {2}, "1", 1}, {2, {2}, {1}, "b", 1}};
  return c;
}

// The main window's validator, in miniature: a transition needs a source and a target that exist.
QList<ChartIssue> validator(const GrafcetChartData& c) {
  QList<ChartIssue> issues;
  auto exists = [&](int id) {
    return std::any_of(c.steps.begin(), c.steps.end(), [id](const auto& s) { return s.id == id; });
  };
  for (const GrafcetTransitionView& t : c.transitions) {
    const QString element = QStringLiteral("transition %1").arg(t.id);
    if (t.to.isEmpty()) issues << ChartIssue{element, -1, t.id, QStringLiteral("no target step")};
    if (t.from.isEmpty()) issues << ChartIssue{element, -1, t.id, QStringLiteral("no source step")};
    for (int s : t.to + t.from)
      if (!exists(s)) issues << ChartIssue{element, -1, t.id, QStringLiteral("unknown step %1").arg(s)};
  }
  return issues;
}
}  // namespace

class TestGrafcetChartEditor : public QObject {
  Q_OBJECT
 private slots:
  void setChartRoundTripsWithoutSignal() {
    GrafcetChartEditor editor;
    editor.setValidator(validator);
    QSignalSpy spy(&editor, &GrafcetChartEditor::chartEdited);
    editor.setChart(smallChart());
    QCOMPARE(editor.chart(), smallChart());
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.stepTable()->rowCount(), 2);
    QCOMPARE(editor.transitionTable()->rowCount(), 2);
    QCOMPARE(editor.stepTable()->item(1, GrafcetChartEditor::StepActions)->text(), QStringLiteral("A, B, I, J"));
    QCOMPARE(editor.stepTable()->item(0, GrafcetChartEditor::StepInitial)->checkState(), Qt::Checked);
    QVERIFY(editor.issues().isEmpty());
    QCOMPARE(editor.chartView()->chart(), smallChart());
  }

  void addStepAndTransitionThenFixTheIssue() {
    GrafcetChartEditor editor;
    editor.setValidator(validator);
    editor.setChart(smallChart());
    QSignalSpy spy(&editor, &GrafcetChartEditor::chartEdited);
    QTest::mouseClick(editor.addStepButton(), Qt::LeftButton);
    QCOMPARE(editor.chart().steps.size(), 2 + 1);
    QCOMPARE(editor.chart().steps.back().id, 3);
    QVERIFY(!editor.chart().steps.back().initial);
    QCOMPARE(spy.count(), 1);  // a lone step is valid for this validator
    // A transition from the selected step (3) without a target: flagged, not emitted.
    QCOMPARE(editor.stepTable()->currentRow(), 2);
    QTest::mouseClick(editor.addTransitionButton(), Qt::LeftButton);
    QCOMPARE(editor.chart().transitions.size(), 3);
    QCOMPARE(editor.chart().transitions.back().from, QList<int>{3});
    QCOMPARE(editor.issues().size(), 1);
    QCOMPARE(editor.issues().front().transition_id, 3);
    QCOMPARE(editor.issueList()->count(), 1);
    QVERIFY(editor.issueList()->item(0)->text().contains(QStringLiteral("transition 3: no target step")));
    QCOMPARE(spy.count(), 1);
    // Clicking the issue selects the transition's row and highlights it in the drawing.
    emit editor.issueList()->itemClicked(editor.issueList()->item(0));
    QCOMPARE(editor.transitionTable()->currentRow(), 2);
    QCOMPARE(editor.chartView()->selectedTransition(), 3);
    // Typing the target fixes it: the edit is emitted.
    editor.transitionTable()->item(2, GrafcetChartEditor::TransitionTo)->setText(QStringLiteral("2"));
    QVERIFY(editor.issues().isEmpty());
    QCOMPARE(editor.issueList()->count(), 0);
    QCOMPARE(spy.count(), 2);
    const GrafcetChartData last = spy.last().at(0).value<GrafcetChartData>();
    QCOMPARE(last.transitions.back().to, QList<int>{2});
  }

  void editCellsAndFormatErrors() {
    GrafcetChartEditor editor;
    editor.setValidator(validator);
    editor.setChart(smallChart());
    QSignalSpy spy(&editor, &GrafcetChartEditor::chartEdited);
    editor.stepTable()->item(1, GrafcetChartEditor::StepName)->setText(QStringLiteral("Contact"));
    editor.stepTable()->item(1, GrafcetChartEditor::StepActions)->setText(QStringLiteral("A B L*"));
    QCOMPARE(spy.count(), 2);
    QCOMPARE(editor.chart().steps[1].name, QStringLiteral("Contact"));
    QCOMPARE(editor.chart().steps[1].actions, (QStringList{"A", "B", "L*"}));
    editor.stepTable()->item(1, GrafcetChartEditor::StepInitial)->setCheckState(Qt::Checked);
    QVERIFY(editor.chart().steps[1].initial);
    QCOMPARE(spy.count(), 3);
    editor.transitionTable()->item(1, GrafcetChartEditor::TransitionReceptivity)->setText(QStringLiteral("not b"));
    QCOMPARE(editor.chart().transitions[1].receptivity, QStringLiteral("not b"));
    QCOMPARE(spy.count(), 4);
    // Format errors are issues too, naming the element.
    editor.stepTable()->item(1, GrafcetChartEditor::StepActions)->setText(QStringLiteral("A, 9x"));
    QCOMPARE(editor.issues().size(), 1);
    QCOMPARE(editor.issues().front().step_id, 2);
    QCOMPARE(spy.count(), 4);
    editor.transitionTable()->item(0, GrafcetChartEditor::TransitionTo)->setText(QStringLiteral("7"));
    QCOMPARE(editor.issues().size(), 2);  // the action and the unknown step 7
    QCOMPARE(editor.issues().back().message, QStringLiteral("unknown step 7"));
  }

  void removeStepAndTransition() {
    GrafcetChartEditor editor;
    editor.setValidator(validator);
    editor.setChart(smallChart());
    QSignalSpy spy(&editor, &GrafcetChartEditor::chartEdited);
    editor.transitionTable()->setCurrentCell(1, 0);
    QTest::mouseClick(editor.removeTransitionButton(), Qt::LeftButton);
    QCOMPARE(editor.chart().transitions.size(), 1);
    QCOMPARE(editor.chart().transitions.front().id, 1);
    QCOMPARE(spy.count(), 1);
    // Removing step 2 leaves transition 1 without a target: an issue, no signal.
    editor.stepTable()->setCurrentCell(1, 0);
    QTest::mouseClick(editor.removeStepButton(), Qt::LeftButton);
    QCOMPARE(editor.chart().steps.size(), 1);
    QVERIFY(editor.chart().transitions.front().to.isEmpty());
    QCOMPARE(editor.issues().size(), 1);
    QCOMPARE(editor.issues().front().element, QStringLiteral("transition 1"));
    QCOMPARE(spy.count(), 1);
  }
};

MX_REGISTER_TEST(TestGrafcetChartEditor)
#include "test_grafcet_chart_editor.moc"
