// Grafcet interpreter: the IEC 60848 evolution rules as documented in docs/grafcet.md
// (priority order in conflicts, simultaneous firing of independent transitions, simultaneous
// clearing and activation, search for the stable situation with an iteration limit, level actions of
// the stable situation, impulse actions once per activation), the fast path agreeing with the
// interface, and the SMC I chart of Landers & Ulsoy behaving as the paper describes.
#include <random>

#include "core/invalid_input.h"
#include "grafcet/grafcet_interpreter.h"
#include "test_registry.h"

using namespace mx;

namespace {

using Names = std::vector<std::string>;
using Actions = std::set<std::string>;

GrafcetStep step(int id, const std::string& name, std::vector<std::string> actions = {}, bool initial = false) {
  return {id, name, initial, std::move(actions)};
}
GrafcetTransition transition(int id, std::vector<int> from, std::vector<int> to, const std::string& r,
                             int priority = 1) {
  return {id, std::move(from), std::move(to), r, priority};
}

// SMC I rebuilt from the paper's rules i)-iv), the state descriptions and Table 2 (figure 4 was
// lost): a = operator feed hold activated, b = cutting tool-part contact detected. The feed hold is
// checked first from states 2 and 4 (transitions (2) and (5) have priority 1).
GrafcetChart smc1() {
  GrafcetChart c;
  c.name = "SMC I";
  c.steps = {step(1, "Initialize Modules", {"L*"}, true), step(2, "No Contact and No Chatter", {"A", "B", "I", "J"}),
             step(3, "Reset Modules", {"A", "B", "I", "J", "L*"}),
             step(4, "Contact and No Chatter", {"A", "B", "I", "J", "L"}),
             step(5, "Operator Feed Hold Active", {"A", "B", "C"})};
  c.transitions = {transition(1, {1}, {2}, "true"), transition(2, {2}, {5}, "a", 1), transition(3, {2}, {3}, "b", 2),
                   transition(4, {3}, {4}, "true"), transition(5, {4}, {5}, "a", 1), transition(6, {4}, {2}, "b'", 2),
                   transition(7, {5}, {2}, "a'")};
  return c;
}

}  // namespace

class TestGrafcetInterpreter : public QObject {
  Q_OBJECT
 private slots:
  void smc1BehavesAsThePaperDescribes() {
    GrafcetInterpreter g(smc1());
    // Initialisation: state 1 resets L, the situation immediately becomes state 2.
    ScanOutput o = g.scan({{"a", 0}, {"b", 0}});
    QCOMPARE(o.active_steps, Names{"No Contact and No Chatter"});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "I", "J"}));
    QCOMPARE(o.impulse_actions, Names{"L*"});
    QVERIFY(o.stable);
    QCOMPARE(o.iterations, 1);
    // Nothing changes: no impulse again.
    o = g.scan({{"a", 0}, {"b", 0}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{2});
    QVERIFY(o.impulse_actions.empty());
    QCOMPARE(o.iterations, 0);
    // Feed hold requested: 2 -> 5; I and J inactive, C active.
    o = g.scan({{"a", 1}, {"b", 0}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{5});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "C"}));
    // Feed hold released: 5 -> 2.
    o = g.scan({{"a", 0}, {"b", 0}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{2});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "I", "J"}));
    // Contact: 2 -> 3 -> 4 in one scan; L reset once (transient state 3), L implemented in state 4.
    o = g.scan({{"a", 0}, {"b", 1}});
    QCOMPARE(o.active_steps, Names{"Contact and No Chatter"});
    QCOMPARE(o.iterations, 2);
    QCOMPARE(o.impulse_actions, Names{"L*"});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "I", "J", "L"}));
    o = g.scan({{"a", 0}, {"b", 1}});
    QVERIFY(o.impulse_actions.empty());
    QCOMPARE(o.level_actions, (Actions{"A", "B", "I", "J", "L"}));
    // Feed hold during contact: 4 -> 5 even though b holds.
    o = g.scan({{"a", 1}, {"b", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{5});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "C"}));
    // Released while still in contact: 5 -> 2 -> 3 -> 4, L reset again.
    o = g.scan({{"a", 0}, {"b", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{4});
    QCOMPARE(o.iterations, 3);
    QCOMPARE(o.impulse_actions, Names{"L*"});
    // Contact ceases: 4 -> 2.
    o = g.scan({{"a", 0}, {"b", 0}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{2});
    QCOMPARE(o.level_actions, (Actions{"A", "B", "I", "J"}));
    // Feed hold checked first: from state 2 with a and b, 5 (not 3); from 4 with a and b', 5 (not 2).
    o = g.scan({{"a", 1}, {"b", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{5});
    QVERIFY(o.impulse_actions.empty());
    g.scan({{"a", 0}, {"b", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{4});
    g.scan({{"a", 1}, {"b", 0}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{5});
    // Rules i, ii: A and B always, I and J unless state 5 (checked above at every situation).
    g.reset();
    QCOMPARE(g.activeStepIds(), std::vector<int>{1});
    QCOMPARE(g.scan({{"a", 1}}).impulse_actions, Names{"L*"});  // 1 -> 2 -> 5
    QCOMPARE(g.activeStepIds(), std::vector<int>{5});
  }

  void priorityOrderIsRespected_data() {
    QTest::addColumn<int>("p1");
    QTest::addColumn<int>("p2");
    QTest::addColumn<int>("winner");  // target step of the fired transition
    QTest::newRow("t1 better") << 1 << 2 << 2;
    QTest::newRow("t2 better") << 2 << 1 << 3;
    QTest::newRow("tie: lower id") << 5 << 5 << 2;
    QTest::newRow("zero beats one") << 1 << 0 << 3;
  }
  void priorityOrderIsRespected() {
    QFETCH(int, p1);
    QFETCH(int, p2);
    QFETCH(int, winner);
    GrafcetChart c;
    c.steps = {step(1, "S1", {}, true), step(2, "S2"), step(3, "S3")};
    c.transitions = {transition(1, {1}, {2}, "x", p1), transition(2, {1}, {3}, "x", p2),
                     transition(3, {2}, {1}, "false"), transition(4, {3}, {1}, "false")};
    GrafcetInterpreter g(c);
    g.scan({{"x", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{winner});
    // Only the fireable one counts: the better transition false -> the other fires.
    c.transitions[p1 <= p2 ? 0 : 1].receptivity = "x'";
    GrafcetInterpreter h(c);
    h.scan({{"x", 1}});
    QCOMPARE(h.activeStepIds(), std::vector<int>{winner == 2 ? 3 : 2});
  }

  void independentTransitionsFireSimultaneously() {
    // 1 -> {2, 3} (divergence), 2 -> 4 on x, 3 -> 5 on y, {4, 5} -> 6 (synchronisation) on z.
    GrafcetChart c;
    c.steps = {step(1, "S1", {}, true), step(2, "S2"),        step(3, "S3"),
               step(4, "S4", {"P*"}),   step(5, "S5", {"Q"}), step(6, "S6", {"R"})};
    c.transitions = {transition(1, {1}, {2, 3}, "go"), transition(2, {2}, {4}, "x"), transition(3, {3}, {5}, "y"),
                     transition(4, {4, 5}, {6}, "z"), transition(5, {6}, {1}, "false")};
    GrafcetInterpreter g(c);
    ScanOutput o = g.scan({{"go", 1}});
    QCOMPARE(g.activeStepIds(), (std::vector<int>{2, 3}));
    QCOMPARE(o.active_steps, (Names{"S2", "S3"}));
    o = g.scan({{"x", 1}, {"y", 1}, {"z", 0}});
    QCOMPARE(o.iterations, 1);  // both in the same evolution
    QCOMPARE(g.activeStepIds(), (std::vector<int>{4, 5}));
    QCOMPARE(o.impulse_actions, Names{"P*"});
    QCOMPARE(o.level_actions, Actions{"Q"});
    // Synchronisation needs both sources.
    g.reset();
    g.scan({{"go", 1}, {"x", 1}, {"z", 1}});
    QCOMPARE(g.activeStepIds(), (std::vector<int>{3, 4}));
    o = g.scan({{"y", 1}, {"z", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{6});
    QCOMPARE(o.iterations, 2);  // 3 -> 5, then {4, 5} -> 6
    QCOMPARE(o.level_actions, Actions{"R"});
  }

  void conflictsResolvedInPriorityOrderPerSourceStep() {
    // Two initial steps S1, S2. T1 (prio 1) from {1}; T2 (prio 2) from {1, 2}; T3 (prio 3) from {2}.
    // All fireable: T1 fires and claims S1, T2 loses S1 to T1, T3 still fires from S2.
    GrafcetChart c;
    c.steps = {step(1, "S1", {}, true), step(2, "S2", {}, true), step(3, "T1 done"), step(4, "T2 done"),
               step(5, "T3 done")};
    c.transitions = {transition(1, {1}, {3}, "true", 1), transition(2, {1, 2}, {4}, "true", 2),
                     transition(3, {2}, {5}, "true", 3)};
    GrafcetInterpreter g(c);
    const ScanOutput o = g.scan({});
    QCOMPARE(g.activeStepIds(), (std::vector<int>{3, 5}));
    QCOMPARE(o.iterations, 1);
    // With T1 false, T2 (the synchronisation) wins over T3 on S2.
    c.transitions[0].receptivity = "false";
    GrafcetInterpreter h(c);
    h.scan({});
    QCOMPARE(h.activeStepIds(), std::vector<int>{4});
  }

  void clearedAndActivatedStepStaysActive() {
    // Initial S1 and S2; T1: S1 -> S2 and T2: S2 -> S3 fire together: S2 is cleared (T2) and activated
    // (T1), so it stays active; with an iteration limit of 1 we see that situation.
    GrafcetChart c;
    c.steps = {step(1, "S1", {}, true), step(2, "S2", {"P*", "L2"}, true), step(3, "S3")};
    c.transitions = {transition(1, {1}, {2}, "go"), transition(2, {2}, {3}, "go")};
    GrafcetInterpreter g(c, GrafcetSettings{1});
    QCOMPARE(g.scan({}).impulse_actions, Names{"P*"});  // the initial activation
    const ScanOutput o = g.scan({{"go", 1}});
    QCOMPARE(g.activeStepIds(), (std::vector<int>{2, 3}));
    QVERIFY(!o.stable);                  // T2 is still fireable
    QVERIFY(o.impulse_actions.empty());  // S2 stayed active: not a new activation
    // A self-loop re-activates nothing either; it never stabilises.
    GrafcetChart loop;
    loop.steps = {step(1, "S1", {"P*", "Q"}, true)};
    loop.transitions = {transition(1, {1}, {1}, "go")};
    GrafcetInterpreter h(loop, GrafcetSettings{10});
    QCOMPARE(h.scan({}).impulse_actions, Names{"P*"});
    const ScanOutput p = h.scan({{"go", 1}});
    QVERIFY(!p.stable);
    QCOMPARE(p.iterations, 10);
    QVERIFY(p.impulse_actions.empty());
    QCOMPARE(p.level_actions, Actions{"Q"});
  }

  void impulseActionsFireOncePerActivation() {
    GrafcetChart c;
    c.steps = {step(1, "Idle", {}, true), step(2, "Busy", {"R*", "M"})};
    c.transitions = {transition(1, {1}, {2}, "x"), transition(2, {2}, {1}, "y")};
    GrafcetInterpreter g(c);
    QVERIFY(g.scan({}).impulse_actions.empty());  // Idle has no impulse
    QCOMPARE(g.scan({{"x", 1}}).impulse_actions, Names{"R*"});
    for (int k = 0; k < 5; ++k) {
      const ScanOutput o = g.scan({{"x", 1}});
      QVERIFY(o.impulse_actions.empty());
      QCOMPARE(o.level_actions, Actions{"M"});
    }
    QVERIFY(g.scan({{"y", 1}}).impulse_actions.empty());
    QCOMPARE(g.activeStepIds(), std::vector<int>{1});
    QCOMPARE(g.scan({{"x", 1}}).impulse_actions, Names{"R*"});  // a new activation fires again
    // Reset: the initial situation's impulses fire again at the next scan.
    g.reset();
    QCOMPARE(g.scan({{"x", 1}}).impulse_actions, Names{"R*"});
  }

  void neverStabilisingChartIsReported_data() {
    QTest::addColumn<int>("limit");
    QTest::newRow("1") << 1;
    QTest::newRow("default 100") << 100;
    QTest::newRow("100000") << 100000;
  }
  void neverStabilisingChartIsReported() {
    QFETCH(int, limit);
    GrafcetChart c;
    c.steps = {step(1, "Ping", {"P*", "LP"}, true), step(2, "Pong", {"Q*", "LQ"})};
    c.transitions = {transition(1, {1}, {2}, "true"), transition(2, {2}, {1}, "run")};
    GrafcetInterpreter g(c, GrafcetSettings{limit});
    QCOMPARE(g.settings().iteration_limit, limit);
    QElapsedTimer timer;
    timer.start();
    const ScanOutput o = g.scan({{"run", 1}});
    QVERIFY(timer.elapsed() < 2000);
    QVERIFY(!o.stable);
    QCOMPARE(o.iterations, limit);
    // Each impulse at most once per scan, however often its step was activated.
    QCOMPARE(static_cast<int>(o.impulse_actions.size()), 2);
    // The situation reached is kept; its level actions are reported.
    const std::vector<int> expected{limit % 2 == 1 ? 2 : 1};
    QCOMPARE(g.activeStepIds(), expected);
    QCOMPARE(o.level_actions, Actions{limit % 2 == 1 ? "LQ" : "LP"});
    // With the loop open the chart stabilises.
    const ScanOutput p = g.scan({{"run", 0}});
    QVERIFY(p.stable);
    QCOMPARE(g.activeStepIds(), std::vector<int>{2});
  }

  void transientStepsAssertNoLevelAction() {
    GrafcetChart c;
    c.steps = {step(1, "S1", {"A"}, true), step(2, "S2", {"T", "U*"}), step(3, "S3", {"B"})};
    c.transitions = {transition(1, {1}, {2}, "go"), transition(2, {2}, {3}, "true"), transition(3, {3}, {1}, "back")};
    GrafcetInterpreter g(c);
    QCOMPARE(g.scan({}).level_actions, Actions{"A"});
    const ScanOutput o = g.scan({{"go", 1}});
    QCOMPARE(o.iterations, 2);
    QCOMPARE(o.level_actions, Actions{"B"});   // T of the transient S2 is not asserted
    QCOMPARE(o.impulse_actions, Names{"U*"});  // but its impulse fires
    QCOMPARE(o.active_steps, Names{"S3"});
  }

  void fastPathMatchesTheInterface() {
    GrafcetInterpreter byName(smc1()), fast(smc1()), fastDefault(smc1());
    QCOMPARE(fast.signalNames(), (Names{"a", "b"}));
    fast.bindSignals({"unused", "b", "a"});
    QCOMPARE(fast.boundSignals(), (Names{"unused", "b", "a"}));
    std::mt19937 rng(8);
    std::bernoulli_distribution coin(0.3);
    for (int k = 0; k < 500; ++k) {
      const double a = coin(rng) ? 1 : 0, b = coin(rng) ? 1 : 0;
      const ScanOutput x = byName.scan({{"a", a}, {"b", b}});
      const ScanOutput y = fast.scanValues({7.0, b, a});
      const GrafcetSituation& z = fastDefault.evolve({a, b});
      QCOMPARE(y.active_steps, x.active_steps);
      QCOMPARE(y.level_actions, x.level_actions);
      QCOMPARE(y.impulse_actions, x.impulse_actions);
      QCOMPARE(y.iterations, x.iterations);
      std::vector<int> ids;
      for (int s : z.active_steps) ids.push_back(fastDefault.chart().steps[static_cast<std::size_t>(s)].id);
      QCOMPARE(ids, byName.activeStepIds());
      QCOMPARE(static_cast<int>(z.impulse_actions.size()), static_cast<int>(x.impulse_actions.size()));
    }
    QVERIFY_THROWS_EXCEPTION(InvalidInput, fast.bindSignals({"a"}));  // b missing
    QVERIFY_THROWS_EXCEPTION(InvalidInput, fast.evolve({1.0}));       // size mismatch
    QCOMPARE(fast.actionNames(), (Names{"L*", "A", "B", "I", "J", "L", "C"}));
  }

  void invalidChartsAndSettingsAreRefused() {
    GrafcetChart c = smc1();
    c.transitions[2].receptivity = "b and (";
    try {
      GrafcetInterpreter g(c);
      QFAIL("no error");
    } catch (const InvalidInput& e) {
      QVERIFY2(std::string(e.what()).find("transition 3 (receptivity): line 1, column 8") != std::string::npos,
               e.what());
    }
    QVERIFY_THROWS_EXCEPTION(InvalidInput, GrafcetInterpreter(smc1(), GrafcetSettings{0}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, GrafcetInterpreter(GrafcetChart{}));
  }
};

MX_REGISTER_TEST(TestGrafcetInterpreter)
#include "test_grafcet_interpreter.moc"
