// The operator rules (Module VII, Rule 18) against a context: which rules fire, the bounds with their
// reasons, advice vs constraint, three-valued conditions, and contradictions naming both rules.
#include "rules/rule_evaluator.h"
#include "rules/rule_parser.h"
#include "test_registry.h"

using namespace mx;

namespace {

RuleSet rules(const QStringList& lines) {
  std::vector<std::string> v;
  for (const QString& s : lines) v.push_back(s.toStdString());
  return parseRulesOrThrow(v);
}

// "tool.teeth=4;material.name=Ti6Al4V": values that parse as numbers are numbers.
RuleContext context(const QString& spec) {
  RuleContext c;
  for (const QString& item : spec.split(';', Qt::SkipEmptyParts)) {
    const QString path = item.section('=', 0, 0);
    const QString value = item.section('=', 1);
    bool isNumber = false;
    const double number = value.toDouble(&isNumber);
    if (isNumber)
      c.set(path.toStdString(), number);
    else
      c.set(path.toStdString(), value.toStdString());
  }
  return c;
}

QList<int> firedLines(const RuleOutcome& o) {
  QList<int> lines;
  for (const RuleRef& r : o.fired) lines << r.line;
  return lines;
}

}  // namespace

class TestRuleEvaluation : public QObject {
  Q_OBJECT

 private slots:
  void issueExamplesFire_data() {
    QTest::addColumn<QString>("context");
    QTest::addColumn<QList<int>>("fired");
    QTest::newRow("small tool, titanium") << "tool.diameter_mm=8;material.name=Ti6Al4V" << QList<int>{1, 2};
    QTest::newRow("small tool, aluminium") << "tool.diameter_mm=9.99;material.name=Aluminium" << QList<int>{1};
    QTest::newRow("boundary is strict") << "tool.diameter_mm=10;material.name=Ti6Al4V" << QList<int>{2};
    QTest::newRow("names are case-sensitive") << "tool.diameter_mm=30;material.name=ti6al4v" << QList<int>{};
  }
  void issueExamplesFire() {
    QFETCH(QString, context);
    QFETCH(QList<int>, fired);
    const RuleSet set = rules(
        {"if tool.diameter_mm < 10 then speed_rpm <= 8000", "if material.name == \"Ti6Al4V\" then weight.c3 >= 0.2"});
    const RuleOutcome o = evaluate(set, ::context(context));
    QCOMPARE(firedLines(o), fired);
    QVERIFY(o.consistent());
    QVERIFY(o.undetermined.empty());
    QCOMPARE(o.admits("speed_rpm", 9000), !fired.contains(1));
    QCOMPARE(o.admits("weight.c3", 0.1), !fired.contains(2));
    QVERIFY(o.admits("speed_rpm", 8000));  // closed bound
    QVERIFY(o.admits("weight.c3", 0.2));
    QVERIFY(o.admits("depth_mm", 123));  // unconstrained
    if (fired.contains(1)) {
      const VariableBounds* b = o.boundsOf("speed_rpm");
      QVERIFY(b != nullptr);
      QCOMPARE(b->upper, 8000.0);
      QVERIFY(std::isinf(b->lower));
      QCOMPARE(b->upperRule->line, 1);
      QCOMPARE(b->reasons.size(), std::size_t(1));
      QCOMPARE(b->reasons[0].rule.text, std::string("if tool.diameter_mm < 10 then speed_rpm <= 8000"));
      QCOMPARE(b->reasons[0].bound.toString(), std::string("speed_rpm <= 8000"));
    } else {
      QVERIFY(o.boundsOf("speed_rpm") == nullptr);
    }
  }

  // and/or/not precedence and three-valued logic, as truth tables. Context values: a = tool.teeth,
  // b = tool.Kr, c = material.name; a missing entry is unknown.
  void conditionTruth_data() {
    QTest::addColumn<QString>("condition");
    QTest::addColumn<QString>("context");
    QTest::addColumn<int>("truth");  // 0 false, 1 true, 2 unknown
    const QString orAnd = "tool.teeth == 1 or tool.teeth == 2 and tool.Kr > 0";
    QTest::newRow("or-and: left true") << orAnd << "tool.teeth=1;tool.Kr=-1" << 1;
    QTest::newRow("or-and: right false") << orAnd << "tool.teeth=2;tool.Kr=-1" << 0;
    QTest::newRow("or-and: right true") << orAnd << "tool.teeth=2;tool.Kr=1" << 1;
    const QString grouped = "(tool.teeth == 1 or tool.teeth == 2) and tool.Kr > 0";
    QTest::newRow("grouped: left true, kr false") << grouped << "tool.teeth=1;tool.Kr=-1" << 0;
    QTest::newRow("grouped: both true") << grouped << "tool.teeth=1;tool.Kr=1" << 1;
    const QString notAnd = "not tool.teeth == 1 and tool.Kr > 0";
    QTest::newRow("not-and: (not a) and b") << notAnd << "tool.teeth=2;tool.Kr=1" << 1;
    QTest::newRow("not-and: a true") << notAnd << "tool.teeth=1;tool.Kr=-1" << 0;
    const QString notGroup = "not (tool.teeth == 1 and tool.Kr > 0)";
    QTest::newRow("not-group: a true, b false") << notGroup << "tool.teeth=1;tool.Kr=-1" << 1;
    QTest::newRow("not-group: both true") << notGroup << "tool.teeth=1;tool.Kr=1" << 0;
    QTest::newRow("string !=") << "material.name != \"Ti6Al4V\""
                               << "material.name=Steel" << 1;
    QTest::newRow("all six number operators")
        << "tool.Kr < 2 and tool.Kr <= 1 and tool.Kr > 0 and tool.Kr >= 1 and tool.Kr == 1 and tool.Kr != 2"
        << "tool.Kr=1" << 1;
    QTest::newRow("unknown: missing path") << "tool.teeth == 1"
                                           << "" << 2;
    QTest::newRow("unknown: not unknown") << "not tool.teeth == 1"
                                          << "" << 2;
    QTest::newRow("false and unknown is false") << "tool.Kr > 0 and tool.teeth == 1"
                                                << "tool.Kr=-1" << 0;
    QTest::newRow("true and unknown is unknown") << "tool.Kr > 0 and tool.teeth == 1"
                                                 << "tool.Kr=1" << 2;
    QTest::newRow("true or unknown is true") << "tool.Kr > 0 or tool.teeth == 1"
                                             << "tool.Kr=1" << 1;
    QTest::newRow("false or unknown is unknown") << "tool.Kr > 0 or tool.teeth == 1"
                                                 << "tool.Kr=-1" << 2;
    QTest::newRow("wrong type in context is unknown") << "tool.teeth == 1"
                                                      << "tool.teeth=four" << 2;
  }
  void conditionTruth() {
    QFETCH(QString, condition);
    QFETCH(QString, context);
    QFETCH(int, truth);
    const RuleSet set = rules({"if " + condition + " then depth_mm <= 1"});
    std::vector<std::string> missing;
    const Truth t = evaluateCondition(set.rules.front().condition, ::context(context), &missing);
    QCOMPARE(static_cast<int>(t == Truth::False ? 0 : t == Truth::True ? 1 : 2), truth);
    const RuleOutcome o = evaluate(set, ::context(context));
    QCOMPARE(o.firedLine(1), truth == 1);
    QCOMPARE(o.undetermined.size(), std::size_t(truth == 2 ? 1 : 0));
    if (truth == 2) QCOMPARE(o.undetermined[0].paths, std::vector<std::string>{"tool.teeth"});
  }

  void adviceDoesNotConstrain() {
    const RuleSet set = rules({
        "if tool.teeth >= 4 and operation.milling == \"down\" then feed_mm_per_tooth <= 0.1 advice \"small feed for "
        "many teeth\"",
        "if tool.teeth >= 4 then advise depth_mm <= 2",
        "if material.name == \"Inconel\" then advise \"use coolant\"",
        "if tool.teeth >= 4 then depth_mm <= 3 because \"long flutes\"",
    });
    const RuleOutcome o = evaluate(set, context("tool.teeth=4;operation.milling=down;material.name=Inconel"));
    QCOMPARE(firedLines(o), (QList<int>{1, 2, 3, 4}));
    QCOMPARE(o.advice.size(), std::size_t(3));
    QCOMPARE(o.advice[0].message, std::string("small feed for many teeth"));
    QCOMPARE(o.advice[0].rule.line, 1);
    QCOMPARE(o.advice[1].message, std::string("depth_mm <= 2"));  // generated from the bound
    QCOMPARE(o.advice[2].message, std::string("use coolant"));
    QVERIFY(!o.advice[2].bound.has_value());
    QVERIFY(o.advice[0].followedBy(0.05));
    QVERIFY(!o.advice[0].followedBy(0.2));
    QVERIFY(o.advice[2].followedBy(1e9));
    // Advice never restricts; the constraint does, and carries its reason.
    QVERIFY(o.admits("feed_mm_per_tooth", 0.3));
    QVERIFY(o.boundsOf("feed_mm_per_tooth") == nullptr);
    QVERIFY(o.admits("depth_mm", 2.5));
    QVERIFY(!o.admits("depth_mm", 3.5));
    QCOMPARE(o.boundsOf("depth_mm")->reasons[0].message, std::string("long flutes"));
    QVERIFY(o.consistent());

    // Up-milling: the advice of line 1 does not fire.
    const RuleOutcome up = evaluate(set, context("tool.teeth=4;operation.milling=up;material.name=Steel"));
    QCOMPARE(firedLines(up), (QList<int>{2, 4}));
  }

  void contradictions_data() {
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QString>("context");
    QTest::addColumn<QStringList>("messages");
    const QStringList speed = {"if tool.diameter_mm < 10 then speed_rpm <= 8000",
                               "if material.name == \"Ti6Al4V\" then speed_rpm >= 9000"};
    QTest::newRow("empty interval")
        << speed << "tool.diameter_mm=8;material.name=Ti6Al4V"
        << QStringList{
               "line 1 'speed_rpm <= 8000' contradicts line 2 'speed_rpm >= 9000': no speed_rpm satisfies both"};
    QTest::newRow("only one fires") << speed << "tool.diameter_mm=12;material.name=Ti6Al4V" << QStringList{};
    QTest::newRow("different equalities")
        << QStringList{"weight.c1 == 0.2", "# comment", "weight.c1 == 0.3"} << ""
        << QStringList{"line 1 'weight.c1 == 0.2' contradicts line 3 'weight.c1 == 0.3': no weight.c1 satisfies both"};
    QTest::newRow("equal equalities agree")
        << QStringList{"weight.c1 == 0.2", "weight.c1 == 0.2"} << "" << QStringList{};
    QTest::newRow("equality inside a bound")
        << QStringList{"speed_rpm == 5000", "speed_rpm <= 6000"} << "" << QStringList{};
    QTest::newRow("touching bounds agree")
        << QStringList{"speed_rpm <= 5000", "speed_rpm >= 5000"} << "" << QStringList{};
    QTest::newRow("equality outside a bound")
        << QStringList{"speed_rpm <= 6000", "speed_rpm == 7000"} << ""
        << QStringList{
               "line 1 'speed_rpm <= 6000' contradicts line 2 'speed_rpm == 7000': no speed_rpm satisfies both"};
    QTest::newRow("every conflicting pair")
        << QStringList{"depth_mm >= 3", "depth_mm <= 2", "depth_mm <= 1", "speed_rpm <= 1", "depth_mm >= 0.5"} << ""
        << QStringList{"line 1 'depth_mm >= 3' contradicts line 2 'depth_mm <= 2': no depth_mm satisfies both",
                       "line 1 'depth_mm >= 3' contradicts line 3 'depth_mm <= 1': no depth_mm satisfies both"};
    QTest::newRow("advice does not contradict")
        << QStringList{"speed_rpm <= 8000", "advise speed_rpm >= 9000"} << "" << QStringList{};
  }
  void contradictions() {
    QFETCH(QStringList, lines);
    QFETCH(QString, context);
    QFETCH(QStringList, messages);
    const RuleOutcome o = evaluate(rules(lines), ::context(context));
    QStringList got;
    for (const RuleContradiction& c : o.contradictions) got << QString::fromStdString(c.message);
    QCOMPARE(got, messages);
    QCOMPARE(o.consistent(), messages.isEmpty());
    for (const RuleContradiction& c : o.contradictions) {
      QVERIFY(c.first.line < c.second.line);
      QVERIFY(!o.admits(c.variable, c.firstBound.value));
      QVERIFY(!o.admits(c.variable, c.secondBound.value));
      QVERIFY(o.boundsOf(c.variable)->empty());
    }
  }

  void tightestBoundsAndTheirRules() {
    const RuleOutcome o = evaluate(
        rules({"speed_rpm <= 9000", "speed_rpm >= 1000", "speed_rpm <= 8000", "speed_rpm >= 500"}), RuleContext{});
    const VariableBounds* b = o.boundsOf("speed_rpm");
    QCOMPARE(b->lower, 1000.0);
    QCOMPARE(b->upper, 8000.0);
    QCOMPARE(b->lowerRule->line, 2);
    QCOMPARE(b->upperRule->line, 3);
    QCOMPARE(b->reasons.size(), std::size_t(4));
    QVERIFY(o.admits("speed_rpm", 1000));
    QVERIFY(!o.admits("speed_rpm", 999.9));
    QVERIFY(!o.admits("speed_rpm", std::nan("")));
  }

  void violationsOfAPoint() {
    const RuleOutcome o =
        evaluate(rules({"speed_rpm <= 8000", "depth_mm <= 2", "feed_mm_per_tooth >= 0.05", "advise depth_mm <= 1"}),
                 RuleContext{});
    const auto v = o.violations({{"speed_rpm", 9000}, {"depth_mm", 1.5}, {"feed_mm_per_tooth", 0.01}});
    QCOMPARE(v.size(), std::size_t(2));
    QCOMPARE(v[0].rule.line, 1);
    QCOMPARE(v[1].rule.line, 3);
    QVERIFY(o.violations({{"speed_rpm", 8000}}).empty());
  }

  void staticContradictions_data() {
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QStringList>("messages");
    QTest::newRow("unconditional pair")
        << QStringList{"speed_rpm <= 8000", "speed_rpm >= 9000"}
        << QStringList{
               "line 1 'speed_rpm <= 8000' contradicts line 2 'speed_rpm >= 9000': both are unconditional, "
               "so they contradict for every context"};
    QTest::newRow("unconditional against conditional")
        << QStringList{"if tool.teeth > 2 then depth_mm >= 3", "depth_mm <= 2"}
        << QStringList{
               "line 1 'depth_mm >= 3' contradicts line 2 'depth_mm <= 2': they contradict whenever line 1 fires"};
    QTest::newRow("same condition, written differently")
        << QStringList{"if (tool.teeth > 2) and tool.Kr < 1 then depth_mm >= 3",
                       "if tool.teeth > 2 and (tool.Kr < 1) then depth_mm <= 2"}
        << QStringList{
               "line 1 'depth_mm >= 3' contradicts line 2 'depth_mm <= 2': they have the same condition, so "
               "they contradict whenever they fire"};
    QTest::newRow("different conditions")
        << QStringList{"if tool.teeth > 2 then depth_mm >= 3", "if tool.teeth <= 2 then depth_mm <= 2"}
        << QStringList{};
    QTest::newRow("compatible bounds") << QStringList{"speed_rpm <= 8000", "speed_rpm >= 7000"} << QStringList{};
    QTest::newRow("advice is not checked")
        << QStringList{"speed_rpm <= 8000", "advise speed_rpm >= 9000"} << QStringList{};
  }
  void staticContradictions() {
    QFETCH(QStringList, lines);
    QFETCH(QStringList, messages);
    QStringList got;
    for (const RuleContradiction& c : mx::staticContradictions(rules(lines))) got << QString::fromStdString(c.message);
    QCOMPARE(got, messages);
  }
};

MX_REGISTER_TEST(TestRuleEvaluation)
#include "test_rule_evaluation.moc"
