// Gilbert's machining economics: cost and time per part by hand, and the analytic optimum: with the
// Taylor tool life T = K V^a (a = -3.02, the Pareto paper's exponent) and MRR proportional to V, the
// cheapest speed has T = (-a - 1)(t_ct + C_t / M) and the fastest T = (-a - 1) t_ct.
#include <cmath>
#include <limits>

#include "core/invalid_input.h"
#include "pareto/machining_economics.h"
#include "test_registry.h"

using namespace mx;

namespace {
MachiningEconomics shopEconomics() {
  MachiningEconomics e;
  e.machine_rate_per_s = 90.0 / 3600.0;  // 90 per hour
  e.tool_cost = 40.0;
  e.tool_change_s = 2.0 * 60.0;
  e.removal_volume_m3 = 200e-6;  // 200 cm^3
  return e;
}

// Speed V [m/min] -> (MRR [m^3/s], tool life [s]) at a fixed depth and feed.
constexpr double kA = -3.02;
double mrrAt(double v) {
  return 1e-7 * v;
}
double lifeAt(double v) {
  return 60.0 * 1.53e7 * std::pow(v, kA);
}

double argminOverSpeed(const MachiningEconomics& e, EconomicObjective o) {
  double best_v = 0.0, best = std::numeric_limits<double>::infinity();
  for (double v = 20.0; v <= 2000.0; v += 0.01) {
    const double c = economicCost(partEconomics(e, mrrAt(v), lifeAt(v)), o);
    if (c < best) {
      best = c;
      best_v = v;
    }
  }
  return best_v;
}
}  // namespace

class TestMachiningEconomics : public QObject {
  Q_OBJECT
 private slots:
  void byHand() {
    // 200 cm^3 at 2 cm^3/s: 100 s; tool life 50 s: 2 changes of 120 s and 2 tools of 40.
    const PartEconomics p = partEconomics(shopEconomics(), 2e-6, 50.0);
    QCOMPARE(p.machining_time_s, 100.0);
    QCOMPARE(p.tool_changes, 2.0);
    QCOMPARE(p.time_per_part_s, 340.0);
    QCOMPARE_LE(std::abs(p.cost_per_part - (340.0 * 90.0 / 3600.0 + 80.0)), 1e-12);
    QVERIFY(std::isinf(partEconomics(shopEconomics(), 0.0, 50.0).cost_per_part));
  }

  void gilbertOptimum_data() {
    QTest::addColumn<int>("objective");
    QTest::newRow("minimum cost") << int(EconomicObjective::MinCost);
    QTest::newRow("maximum rate") << int(EconomicObjective::MaxRate);
  }
  void gilbertOptimum() {
    QFETCH(int, objective);
    const auto o = static_cast<EconomicObjective>(objective);
    const MachiningEconomics e = shopEconomics();
    const double expected =
        o == EconomicObjective::MinCost ? 2.02 * (120.0 + 40.0 / e.machine_rate_per_s) : 2.02 * 120.0;
    QCOMPARE_LE(std::abs(*gilbertToolLife(e, kA, o) - expected), 1e-9);
    // The brute-force optimum over a 0.01 m/min sweep has Gilbert's tool life within 0.1 %.
    const double life = lifeAt(argminOverSpeed(e, o));
    QCOMPARE_LE(std::abs(life / expected - 1.0), 1e-3);
  }

  void noInteriorOptimum() {
    QVERIFY(!gilbertToolLife(shopEconomics(), -1.0, EconomicObjective::MinCost));
    MachiningEconomics free_machine = shopEconomics();
    free_machine.machine_rate_per_s = 0.0;
    QVERIFY(!gilbertToolLife(free_machine, kA, EconomicObjective::MinCost));
  }

  void validation() {
    MachiningEconomics e = shopEconomics();
    e.removal_volume_m3 = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, e.validate());
    e = shopEconomics();
    e.tool_cost = -1.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, e.validate());
    e = shopEconomics();
    e.machine_rate_per_s = e.tool_cost = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, e.validate());
  }
};

MX_REGISTER_TEST(TestMachiningEconomics)
#include "test_machining_economics.moc"
