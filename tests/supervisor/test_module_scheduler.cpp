// Multi-rate scheduler: each active module runs at its own period on the simulated time axis, level
// actions switch modules on and off, impulse "X*" resets module X once.
#include <cmath>

#include "core/invalid_input.h"
#include "supervisor/module_scheduler.h"
#include "test_registry.h"

using namespace mx;

namespace {
class Counter : public MachiningModule {
 public:
  Counter(char l, double p, int* resets) : MachiningModule(l, "counter", p), resets_(resets) {}
  void run(MachiningContext&) override {}
  void reset(MachiningContext&) override { ++*resets_; }

 private:
  int* resets_;
};

std::vector<std::unique_ptr<MachiningModule>> counters(int* r) {
  std::vector<std::unique_ptr<MachiningModule>> m;
  m.push_back(std::make_unique<Counter>('A', 0.010, r));
  m.push_back(std::make_unique<Counter>('E', 0.040, r));
  m.push_back(std::make_unique<Counter>('C', 0.0, r));
  return m;
}

void runFor(ModuleScheduler& s, MachiningContext& c, double seconds) {
  const int n = static_cast<int>(std::lround(seconds / 5e-4));
  for (int i = 0; i < n; ++i) {
    s.tick(c);
    c.t_s += 5e-4;
  }
}
}  // namespace

class TestModuleScheduler : public QObject {
  Q_OBJECT
 private slots:
  void periods() {
    int resets = 0;
    ModuleScheduler s(counters(&resets));
    MachiningContext c;
    ScanOutput out;
    out.level_actions = {"A", "E", "C"};
    s.applyScan(out, c);
    runFor(s, c, 1.0);
    QCOMPARE(s.runs('A'), 100LL);   // 10 ms
    QCOMPARE(s.runs('E'), 25LL);    // 40 ms
    QCOMPARE(s.runs('C'), 2000LL);  // every 0.5 ms sample
    QCOMPARE(s.activeLetters(), std::string("ACE"));
  }

  void levelActionsAndImpulses() {
    int resets = 0;
    ModuleScheduler s(counters(&resets));
    MachiningContext c;
    ScanOutput out;
    out.level_actions = {"A"};
    out.impulse_actions = {"E*"};
    s.applyScan(out, c);
    QCOMPARE(resets, 1);
    QCOMPARE(s.resets('E'), 1LL);
    runFor(s, c, 0.2);
    QCOMPARE(s.runs('E'), 0LL);  // reset, not active
    QCOMPARE(s.runs('A'), 20LL);
    out.impulse_actions.clear();
    s.applyScan(out, c);  // the impulse fires once
    QCOMPARE(resets, 1);
    out.level_actions = {};
    s.applyScan(out, c);
    runFor(s, c, 0.2);
    QCOMPARE(s.runs('A'), 20LL);
    QVERIFY(!s.isActive('A'));
    out.impulse_actions = {"Z*", "bogus"};  // unknown modules are ignored
    s.applyScan(out, c);
    QCOMPARE(resets, 1);
  }

  void feedHoldThroughScheduler() {
    ModuleScheduler s(makeStandardModules());
    MachiningContext c;
    c.passes_m = {1e-3};
    ScanOutput run;
    run.level_actions = {"A", "B"};
    s.applyScan(run, c);
    runFor(s, c, 0.05);
    QCOMPARE(c.commanded_feed_m_per_s, 10e-3);
    ScanOutput hold;
    hold.level_actions = {"A", "B", "C"};
    s.applyScan(hold, c);
    runFor(s, c, 0.05);
    QCOMPARE(c.commanded_feed_m_per_s, 0.0);
    s.applyScan(run, c);
    runFor(s, c, 0.05);
    QCOMPARE(c.commanded_feed_m_per_s, 10e-3);
  }

  void duplicateLetters() {
    int r = 0;
    std::vector<std::unique_ptr<MachiningModule>> m;
    m.push_back(std::make_unique<Counter>('A', 0.01, &r));
    m.push_back(std::make_unique<Counter>('A', 0.04, &r));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, ModuleScheduler{std::move(m)});
  }
};

MX_REGISTER_TEST(TestModuleScheduler)
#include "test_module_scheduler.moc"
