// Receptivity language of the Grafcet interpreter: operators and precedence, the paper's
// postfix complement a', comparisons on numeric signals, parse errors with line and column, the list
// of signals read, and the indexed fast path agreeing with evaluation by name.
#include "grafcet/grafcet_expression.h"
#include "test_registry.h"

using namespace mx;

class TestGrafcetExpression : public QObject {
  Q_OBJECT
 private slots:
  void evaluates_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("expected");
    // signals: a = 1, b = 0, c = 1, x = 2.5, n = -3
    QTest::newRow("true") << "true" << true;
    QTest::newRow("FALSE keyword") << "FALSE" << false;
    QTest::newRow("signal") << "a" << true;
    QTest::newRow("absent signal reads 0") << "zz" << false;
    QTest::newRow("prime") << "a'" << false;
    QTest::newRow("prime of b") << "b'" << true;
    QTest::newRow("double prime") << "a''" << true;
    QTest::newRow("typographic prime") << "b\u2019 and a" << true;
    QTest::newRow("prime of group") << "(a and b)'" << true;
    QTest::newRow("prime binds tighter than and") << "b and a'" << false;
    QTest::newRow("and") << "a and c" << true;
    QTest::newRow("&&") << "a && b" << false;
    QTest::newRow("or") << "b or c" << true;
    QTest::newRow("||") << "b || b" << false;
    QTest::newRow("not") << "not b" << true;
    QTest::newRow("!") << "!a" << false;
    QTest::newRow("and before or") << "a or b and b" << true;  // a or (b and b)
    QTest::newRow("parentheses") << "(a or b) and b" << false;
    QTest::newRow("not binds tighter than and") << "not b and a" << true;
    QTest::newRow("not of comparison") << "not x > 3" << true;
    QTest::newRow("<") << "x < 2.5" << false;
    QTest::newRow("<=") << "x <= 2.5" << true;
    QTest::newRow(">") << "x > 2.4999" << true;
    QTest::newRow(">=") << "x >= 2.5001" << false;
    QTest::newRow("==") << "x == 2.5" << true;
    QTest::newRow("= as ==") << "x = 2.5" << true;
    QTest::newRow("!=") << "x != 2.5" << false;
    QTest::newRow("negative number") << "n < -2.9" << true;
    QTest::newRow("negative equal") << "n == -3" << true;
    QTest::newRow("exponent") << "x > 2.5e-1 and x < 25E-1 + 0" << false;  // "+" is not an operator
    QTest::newRow("number truth") << "0.0" << false;
    QTest::newRow("negative signal is true") << "n" << true;
    QTest::newRow("comparison with signals") << "x > n and a == c" << true;
    QTest::newRow("multi-line") << "a and\n  (b or c)" << true;
  }
  void evaluates() {
    QFETCH(QString, text);
    QFETCH(bool, expected);
    const SignalValues v{{"a", 1}, {"b", 0}, {"c", 1}, {"x", 2.5}, {"n", -3}};
    if (text.contains('+')) {
      QVERIFY_THROWS_EXCEPTION(GrafcetParseError, GrafcetExpression::parse(text.toStdString()));
      return;
    }
    const GrafcetExpression e = GrafcetExpression::parse(text.toStdString());
    QCOMPARE(e.evaluate(v), expected);
    // The indexed path: cells in signalNames() order.
    std::vector<double> cells;
    for (const std::string& s : e.signalNames()) cells.push_back(v.count(s) ? v.at(s) : 0.0);
    QCOMPARE(e.evaluate(cells.data()), expected);
  }

  void nanIsFalse() {
    const GrafcetExpression e = GrafcetExpression::parse("x");
    QCOMPARE(e.evaluate(SignalValues{{"x", std::nan("")}}), false);
    QCOMPARE(GrafcetExpression::parse("x'").evaluate(SignalValues{{"x", std::nan("")}}), true);
    QCOMPARE(GrafcetExpression().evaluate(SignalValues{}), false);  // default: constant false
  }

  void listsSignalsOnceInOrder() {
    const GrafcetExpression e = GrafcetExpression::parse("b and (a' or F_Y > 50) and not b or AND_x");
    QCOMPARE(e.signalNames(), (std::vector<std::string>{"b", "a", "F_Y", "AND_x"}));
    QVERIFY(!e.isConstant());
    QVERIFY(GrafcetExpression::parse("true and 1 > 0").isConstant());
    QCOMPARE(e.text(), std::string("b and (a' or F_Y > 50) and not b or AND_x"));
  }

  void boundSlotsReadGlobalValues() {
    GrafcetExpression e = GrafcetExpression::parse("p and q'");
    e.bindSlots({3, 0});  // p -> slot 3, q -> slot 0
    const double cells[] = {0.0, 1.0, 1.0, 1.0};
    QCOMPARE(e.evaluate(cells), true);
    const double slots2[] = {1.0, 1.0, 1.0, 1.0};
    QCOMPARE(e.evaluate(slots2), false);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, e.bindSlots({1}));
  }

  void deepExpressionsUseTheHeapStack() {
    // A right-leaning chain needs a deep evaluation stack.
    std::string text = "a";
    for (int i = 0; i < 40; ++i) text = std::string("a and (").append(text).append(")");
    const GrafcetExpression e = GrafcetExpression::parse(text);
    QCOMPARE(e.evaluate(SignalValues{{"a", 1}}), true);
    QCOMPARE(e.evaluate(SignalValues{{"a", 0}}), false);
    std::string deep(300, '(');
    deep += "a" + std::string(300, ')');
    try {
      GrafcetExpression::parse(deep);
      QFAIL("no error");
    } catch (const GrafcetParseError& err) {
      QCOMPARE(err.reason(), std::string("expression nested too deeply"));
    }
  }

  void parseErrors_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("what");
    QTest::newRow("missing )") << "(a b" << 1 << 4 << "line 1, column 4: expected ')'";
    QTest::newRow("missing ) at end") << "(a or b" << 1 << 8 << "line 1, column 8: expected ')'";
    QTest::newRow("unmatched )") << "a)" << 1 << 2 << "line 1, column 2: unmatched ')'";
    QTest::newRow("empty") << "" << 1 << 1 << "line 1, column 1: empty receptivity";
    QTest::newRow("blank") << "   " << 1 << 4 << "line 1, column 4: empty receptivity";
    QTest::newRow("dangling and")
        << "a and" << 1 << 6 << "line 1, column 6: expected a signal, a number or '(', found the end of the expression";
    QTest::newRow("two operands") << "a b" << 1 << 3 << "line 1, column 3: expected an operator, found 'b'";
    QTest::newRow("bad character") << "a # b" << 1 << 3 << "line 1, column 3: unexpected character '#'";
    QTest::newRow("single &") << "a & b" << 1 << 3 << "line 1, column 3: unexpected character '&'";
    QTest::newRow("chained comparison") << "1 < x < 3" << 1 << 7
                                        << "line 1, column 7: comparisons cannot be chained; use 'and'";
    QTest::newRow("prime first") << "'a" << 1 << 1 << "line 1, column 1: expected a signal, a number or '(', found '''";
    QTest::newRow("bad number") << "x > 3abc" << 1 << 6 << "line 1, column 6: unexpected 'a' in a number";
    QTest::newRow("second line")
        << "a and\n   (b or" << 2 << 9
        << "line 2, column 9: expected a signal, a number or '(', found the end of the expression";
    QTest::newRow("after typographic prime") << "a\u2019 )" << 1 << 4 << "line 1, column 4: unmatched ')'";
  }
  void parseErrors() {
    QFETCH(QString, text);
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QString, what);
    try {
      GrafcetExpression::parse(text.toStdString());
      QFAIL("no parse error");
    } catch (const GrafcetParseError& e) {
      QCOMPARE(QString::fromStdString(e.what()), what);
      QCOMPARE(e.line(), line);
      QCOMPARE(e.column(), column);
    }
  }
};

MX_REGISTER_TEST(TestGrafcetExpression)
#include "test_grafcet_expression.moc"
