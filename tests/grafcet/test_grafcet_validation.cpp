// Grafcet chart validation: every error names its element (chart, step or transition, by
// id and position) and field, and the message says what is wrong.
#include "grafcet/grafcet_validation.h"
#include "test_registry.h"

using namespace mx;

namespace {

GrafcetChart valid() {
  GrafcetChart c;
  c.name = "two steps";
  c.steps = {{1, "Idle", true, {"A"}}, {2, "Busy", false, {"B", "R*"}}};
  c.transitions = {{1, {1}, {2}, "go and not stop", 1}, {2, {2}, {1}, "stop'", 1}};
  return c;
}

}  // namespace

Q_DECLARE_METATYPE(mx::GrafcetIssueKind)
Q_DECLARE_METATYPE(mx::GrafcetElement)

class TestGrafcetValidation : public QObject {
  Q_OBJECT
 private slots:
  void validChartHasNoIssue() {
    QVERIFY(validateGrafcetChart(valid()).empty());
    QVERIFY(validateGrafcetChart(valid(), {"go", "stop"}).empty());
  }

  void errorsNameTheirElement_data() {
    QTest::addColumn<int>("variant");
    QTest::addColumn<mx::GrafcetIssueKind>("kind");
    QTest::addColumn<mx::GrafcetElement>("element");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("id");
    QTest::addColumn<QString>("described");
    using K = GrafcetIssueKind;
    using E = GrafcetElement;
    QTest::newRow("unknown signal") << 0 << K::UnknownSignal << E::Transition << 0 << 1
                                    << "transition 1 (receptivity): unknown signal 'go'";
    QTest::newRow("unreachable step")
        << 1 << K::UnreachableStep << E::Step << 2 << 7
        << "step 7: unreachable step 'Orphan': no transition from the initial situation leads to it";
    QTest::newRow("no source") << 2 << K::TransitionWithoutSource << E::Transition << 1 << 2
                               << "transition 2 (from): the transition has no source step";
    QTest::newRow("no target") << 3 << K::TransitionWithoutTarget << E::Transition << 1 << 2
                               << "transition 2 (to): the transition has no target step";
    QTest::newRow("empty initial situation") << 4 << K::EmptyInitialSituation << E::Chart << -1 << 0
                                             << "chart (initial): empty initial situation: no step is marked initial";
    QTest::newRow("duplicate step id") << 5 << K::DuplicateStepId << E::Step << 2 << 1
                                       << "step 1 (id): duplicate step id 1 (also step #1 in the list)";
    QTest::newRow("duplicate transition id")
        << 6 << K::DuplicateTransitionId << E::Transition << 2 << 1
        << "transition 1 (id): duplicate transition id 1 (also transition #1 in the list)";
    QTest::newRow("bad receptivity") << 7 << K::BadReceptivity << E::Transition << 1 << 2
                                     << "transition 2 (receptivity): line 1, column 7: expected ')'";
    QTest::newRow("unknown step") << 8 << K::UnknownStep << E::Transition << 0 << 1
                                  << "transition 1 (to): unknown step 9";
    QTest::newRow("no steps") << 9 << K::NoSteps << E::Chart << -1 << 0 << "chart (steps): the chart has no step";
    QTest::newRow("duplicate step name") << 10 << K::DuplicateStepName << E::Step << 1 << 2
                                         << "step 2 (name): duplicate step name 'Idle' (also step 1)";
    QTest::newRow("empty step name") << 11 << K::EmptyStepName << E::Step << 1 << 2
                                     << "step 2 (name): the step has no name";
    QTest::newRow("bad action")
        << 12 << K::BadAction << E::Step << 1 << 2
        << "step 2 (actions): bad action '*': a name, with a trailing '*' for an impulse action";
  }
  void errorsNameTheirElement() {
    QFETCH(int, variant);
    QFETCH(mx::GrafcetIssueKind, kind);
    QFETCH(mx::GrafcetElement, element);
    QFETCH(int, index);
    QFETCH(int, id);
    QFETCH(QString, described);
    GrafcetChart c = valid();
    std::vector<GrafcetIssue> issues;
    switch (variant) {
      case 0:
        issues = validateGrafcetChart(c, {"stop"});
        break;
      case 1:
        c.steps.push_back({7, "Orphan", false, {}});
        break;
      case 2:
        c.transitions[1].from.clear();
        break;
      case 3:
        c.transitions[1].to.clear();
        break;
      case 4:
        c.steps[0].initial = false;
        break;
      case 5:
        c.steps.push_back({1, "Again", false, {}});
        break;
      case 6:
        c.transitions.push_back({1, {2}, {1}, "true", 1});
        break;
      case 7:
        c.transitions[1].receptivity = "(stop a";
        break;
      case 8:
        c.transitions[0].to = {2, 9};
        break;
      case 9:
        c.steps.clear();
        c.transitions.clear();
        break;
      case 10:
        c.steps[1].name = "Idle";
        break;
      case 11:
        c.steps[1].name.clear();
        break;
      case 12:
        c.steps[1].actions = {"*"};
        break;
    }
    if (variant != 0) issues = validateGrafcetChart(c);
    QVERIFY(!issues.empty());
    const GrafcetIssue& i = issues.front();
    QCOMPARE(i.kind, kind);
    QCOMPARE(i.element, element);
    QCOMPARE(i.index, index);
    QCOMPARE(i.id, id);
    QCOMPARE(QString::fromStdString(i.describe()), described);
    QCOMPARE(issues.size(), std::size_t(1));  // one fault, one error
  }

  void reachabilityNeedsAllSourcesOfASynchronisation() {
    // 1 -> 2; {2, 3} -> 4: 3 is unreachable, and so is 4 (its transition needs 3).
    GrafcetChart c;
    c.steps = {{1, "S1", true, {}}, {2, "S2", false, {}}, {3, "S3", false, {}}, {4, "S4", false, {}}};
    c.transitions = {{1, {1}, {2}, "x", 1}, {2, {2, 3}, {4}, "y", 1}};
    const auto issues = validateGrafcetChart(c);
    QCOMPARE(issues.size(), std::size_t(2));
    QCOMPARE(issues[0].id, 3);
    QCOMPARE(issues[1].id, 4);
    QCOMPARE(issues[1].kind, GrafcetIssueKind::UnreachableStep);
  }

  void allIssuesAreReported() {
    GrafcetChart c = valid();
    c.transitions[0].receptivity = "go and";
    c.transitions[1].to.clear();
    c.steps[1].actions.emplace_back("two words");
    const auto issues = validateGrafcetChart(c, {"go"});
    QStringList described;
    for (const auto& i : issues) described << QString::fromStdString(i.describe());
    QCOMPARE(described,
             (QStringList{"step 2 (actions): bad action 'two words': a name, with a trailing '*' for an impulse action",
                          "transition 1 (receptivity): line 1, column 7: expected a signal, a number or '(', found the "
                          "end of the expression",
                          "transition 2 (to): the transition has no target step",
                          "transition 2 (receptivity): unknown signal 'stop'"}));
  }
};

MX_REGISTER_TEST(TestGrafcetValidation)
#include "test_grafcet_validation.moc"
