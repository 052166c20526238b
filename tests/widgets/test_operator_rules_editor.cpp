// The operator-rules editor: a bad line shows the parser's own "line L, column C: message" and is
// marked red; rulesChanged() only for rules that parse; fired rules are marked green; the debounced
// check runs by itself after an edit.
#include <QApplication>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTextBlock>

#include "operator_rules_editor.h"
#include "rules/rule_parser.h"
#include "test_registry.h"

using mx::widgets::OperatorRulesEditor;

namespace {

const QString kGood1 = "if material.name == \"Ti6Al4V\" then weight.c3 >= 0.2";
const QString kBad2 = "if tool.diameter_mm < then speed_rpm <= 8000";
const QString kGood2 = "if tool.diameter_mm < 10 then speed_rpm <= 8000";
const QString kGood3 = "if machine.max_spindle_rpm <= 12000 then speed_rpm <= 11000 because \"margin\"";

// The background colours of the extra selections covering block `line` (1-based).
QList<QColor> lineColours(const OperatorRulesEditor& editor, int line) {
  QList<QColor> out;
  for (const QTextEdit::ExtraSelection& s : editor.textEdit()->extraSelections())
    if (s.cursor.blockNumber() == line - 1 && s.format.hasProperty(QTextFormat::BackgroundBrush))
      out << s.format.background().color();
  return out;
}

bool isRed(const QColor& c) {
  return c.red() > 200 && c.green() < 220 && c.blue() < 220;
}
bool isGreen(const QColor& c) {
  return c.green() > 200 && c.red() < c.green() && c.blue() < c.green();
}

}  // namespace

class TestOperatorRulesEditor : public QObject {
  Q_OBJECT
 private slots:
  void badLineShowsTheParserMessageAndIsMarked() {
    OperatorRulesEditor editor;
    QSignalSpy spy(&editor, &OperatorRulesEditor::rulesChanged);
    editor.textEdit()->setPlainText(QStringList{kGood1, kBad2, kGood3}.join('\n'));
    QVERIFY(!editor.check());
    // The message is the parser's, verbatim.
    const mx::RuleParseResult direct =
        mx::parseRules({kGood1.toStdString(), kBad2.toStdString(), kGood3.toStdString()});
    QCOMPARE(direct.errors.size(), std::size_t{1});
    const QString expected = QString::fromStdString(direct.errors.front().toString());
    QCOMPARE(expected, QStringLiteral("line 2, column 23: expected a number after 'tool.diameter_mm <', got 'then'"));
    QCOMPARE(editor.errorMessages(), QStringList{expected});
    QCOMPARE(editor.errorList()->item(0)->text(), expected);
    QVERIFY(editor.errorList()->isVisibleTo(&editor));
    QCOMPARE(editor.errorLines(), QList<int>{2});
    const QList<QColor> marks = lineColours(editor, 2);
    QVERIFY(!marks.isEmpty() && isRed(marks.last()));
    QVERIFY(lineColours(editor, 1).isEmpty());
    QVERIFY(lineColours(editor, 3).isEmpty());
    QCOMPARE(spy.count(), 0);

    // Fixing line 2 emits the lines.
    QTextCursor c(editor.textEdit()->document()->findBlockByNumber(1));
    c.select(QTextCursor::LineUnderCursor);
    c.insertText(kGood2);
    QVERIFY(editor.check());
    QCOMPARE(spy.count(), 1);
    const QStringList expectedLines{kGood1, kGood2, kGood3};
    QCOMPARE(spy.at(0).at(0).toStringList(), expectedLines);
    QCOMPARE(editor.rules(), expectedLines);
    QVERIFY(editor.errorLines().isEmpty());
    QVERIFY(!editor.errorList()->isVisibleTo(&editor));
    QVERIFY(lineColours(editor, 2).isEmpty());
    // Checking again without a change: no second signal.
    QVERIFY(editor.check());
    QCOMPARE(spy.count(), 1);
  }

  void debouncedCheckRunsAfterAnEdit() {
    OperatorRulesEditor editor;
    editor.setRules({kGood1});
    QSignalSpy spy(&editor, &OperatorRulesEditor::rulesChanged);
    editor.textEdit()->appendPlainText(kBad2);
    QVERIFY(editor.errorLines().isEmpty());  // not yet: debounced
    QTRY_COMPARE_WITH_TIMEOUT(editor.errorLines(), QList<int>{2}, 2000);
    QCOMPARE(spy.count(), 0);
    QTextCursor c(editor.textEdit()->document()->findBlockByNumber(1));
    c.select(QTextCursor::LineUnderCursor);
    c.insertText(kGood2);
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 1, 2000);
    QCOMPARE(spy.at(0).at(0).toStringList(), (QStringList{kGood1, kGood2}));
  }

  void setRulesIsSilentAndFiredRulesAreGreen() {
    OperatorRulesEditor editor;
    QSignalSpy spy(&editor, &OperatorRulesEditor::rulesChanged);
    editor.setRules({kGood1, "# a comment", kGood2, kGood3});
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.rules(), (QStringList{kGood1, "# a comment", kGood2, kGood3}));
    QVERIFY(editor.check());
    QCOMPARE(spy.count(), 0);
    editor.setFiredRules({1, 4});
    QCOMPARE(lineColours(editor, 1).size(), 1);
    QVERIFY(isGreen(lineColours(editor, 1).first()));
    QVERIFY(isGreen(lineColours(editor, 4).first()));
    QVERIFY(lineColours(editor, 3).isEmpty());
    editor.setFiredRules({});
    QVERIFY(lineColours(editor, 1).isEmpty());
    QVERIFY(!editor.textEdit()->toolTip().isEmpty() && !editor.errorList()->toolTip().isEmpty());
  }
};

MX_REGISTER_TEST(TestOperatorRulesEditor)
#include "test_operator_rules_editor.moc"
