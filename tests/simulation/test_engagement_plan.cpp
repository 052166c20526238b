// EngagementPlanner / EngagementTable: which teeth cut during each RK4 step, split at the instants a
// tooth enters or leaves the immersion, with force directions from mx::toothForce.
#include <cmath>
#include <numbers>

#include "model/cutting_force.h"
#include "simulation/engagement_plan.h"
#include "support/fixtures.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kPi;

// Brute force: the teeth inside the immersion at angle theta.
int engagedAt(const MillingSetup& s, double theta) {
  int count = 0;
  for (int j = 0; j < s.teeth; ++j) count += s.immersion.contains(theta + j * s.toothPitchRad()) ? 1 : 0;
  return count;
}
}  // namespace

class TestEngagementPlan : public QObject {
  Q_OBJECT
 private slots:
  void tableMatchesToothForce_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<int>("steps");
    QTest::newRow("R1 full immersion up, m = 92") << 1 << 92;
    QTest::newRow("Insperger half immersion down, m = 37") << 2 << 37;
    QTest::newRow("Insperger 10 % immersion down, m = 40") << 3 << 40;
  }
  void tableMatchesToothForce() {
    QFETCH(int, tool);
    QFETCH(int, steps);
    const MillingSetup s = tool == 1 ? test::rubioR1() : test::insperger(tool == 2 ? 0.5 : 0.1);
    const EngagementTable table(s, steps);
    const double step_angle = s.toothPitchRad() / steps;
    int split_steps = 0;
    for (int n = 0; n < steps; ++n) {
      const StepPlanView plan = table.step(n + 5 * steps);  // periodic in the tooth period
      QVERIFY(!plan.sub_steps.empty());
      double covered = 0.0;
      for (const SubStep& sub : plan.sub_steps) {
        QCOMPARE(sub.begin, covered);
        QVERIFY(sub.length > 0.0);
        covered += sub.length;
        const double mid_theta = (n + sub.begin + 0.5 * sub.length) * step_angle;
        for (int point = 0; point < 3; ++point) {
          const auto teeth = plan.teeth(sub, point);
          QCOMPARE(static_cast<int>(teeth.size()), engagedAt(s, mid_theta));
          for (const ActiveTooth& t : teeth) {
            QVERIFY(std::abs(t.sin_phi * t.sin_phi + t.cos_phi * t.cos_phi - 1.0) < 1e-12);
            const double phi = std::atan2(t.sin_phi, t.cos_phi);
            const ToothForce unit = toothForce(s, 1.0, phi < 0 ? phi + 2 * kPi : phi, 1.0);
            QVERIFY(std::abs(unit.fx_n - t.fx_unit) < 1e-6 * s.tangential_coefficient_pa);
            QVERIFY(std::abs(unit.fy_n - t.fy_unit) < 1e-6 * s.tangential_coefficient_pa);
          }
        }
      }
      QVERIFY(std::abs(covered - 1.0) < 1e-12);
      split_steps += plan.sub_steps.size() > 1 ? 1 : 0;
    }
    // Entry and exit modulo the pitch: at most two steps per tooth period are split.
    QVERIFY(split_steps <= 2);
    if (tool != 1) QVERIFY(split_steps >= 1);  // partial immersion: entry at phi_st = acos(2a/D - 1) inside a step
  }

  // Insperger half immersion down-milling (2 teeth, entry at pi/2): with m = 3 the entry of tooth 0 is
  // half-way through step 1, which becomes two sub-steps; the second starts with the entering tooth.
  void entryInsideAStepSplitsIt() {
    const MillingSetup s = test::insperger(0.5);
    QCOMPARE(s.immersion.entry_rad, kPi / 2);
    const EngagementTable table(s, 3);
    const StepPlanView plan = table.step(1);
    QCOMPARE(plan.sub_steps.size(), std::size_t{2});
    const SubStep& before = plan.sub_steps[0];
    const SubStep& after = plan.sub_steps[1];
    QVERIFY(std::abs(after.begin - 0.5) < 1e-12);
    QCOMPARE(plan.teeth(before, 2).size(), std::size_t{0});  // left limit at the entry: not cutting
    const auto entering = plan.teeth(after, 0);              // right limit: cutting at phi = pi/2
    QCOMPARE(entering.size(), std::size_t{1});
    QCOMPARE(entering[0].sin_phi, 1.0);
  }

  // Entry exactly on a step boundary (m = 2): one-sided values, no split.
  void entryOnAStepBoundaryIsOneSided() {
    const MillingSetup s = test::insperger(0.5);
    const EngagementTable table(s, 2);
    const StepPlanView step0 = table.step(0), step1 = table.step(1);
    QCOMPARE(step0.sub_steps.size(), std::size_t{1});
    QCOMPARE(step1.sub_steps.size(), std::size_t{1});
    QCOMPARE(step0.teeth(step0.sub_steps[0], 2).size(), std::size_t{0});
    QCOMPARE(step1.teeth(step1.sub_steps[0], 0).size(), std::size_t{1});
  }

  // The planner with a non-uniform angle law places the event where theta(f) reaches the entry.
  void plannerFindsEventOfNonlinearAngle() {
    const MillingSetup s = test::insperger(0.5);
    EngagementPlanner planner(s);
    std::vector<SubStep> steps;
    std::vector<ActiveTooth> pool;
    auto theta = [](double f) { return 1.0 + 1.2 * f * f; };  // crosses pi/2 at f = sqrt((pi/2 - 1)/1.2)
    auto fraction = [](double angle) { return std::sqrt((angle - 1.0) / 1.2); };
    planner.plan(theta, fraction, steps, pool);
    QCOMPARE(steps.size(), std::size_t{2});
    QVERIFY(std::abs(steps[1].begin - std::sqrt((kPi / 2 - 1.0) / 1.2)) < 1e-12);
  }
};

MX_REGISTER_TEST(TestEngagementPlan)
#include "test_engagement_plan.moc"
