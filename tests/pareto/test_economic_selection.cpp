// The cheapest / fastest point of Q (case study table) against a brute-force pass, and the order of
// the two optima: the minimum-cost point is never faster than the maximum-rate point, and the
// maximum-rate point never cheaper.
#include <limits>

#include "pareto/economic_selection.h"
#include "pareto_fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
MachiningEconomics shop() {
  MachiningEconomics e;
  e.machine_rate_per_s = 90.0 / 3600.0;
  e.tool_cost = 40.0;
  e.tool_change_s = 120.0;
  e.removal_volume_m3 = 200e-6;
  return e;
}
auto all = [](const ParetoPoint&) { return true; };
}  // namespace

class TestEconomicSelection : public QObject {
  Q_OBJECT
 private slots:
  void matchesBruteForce() {
    const ObjectiveTable& t = test::paretoCaseTable();
    for (EconomicObjective o : {EconomicObjective::MinCost, EconomicObjective::MaxRate}) {
      const auto i = cheapestPoint(t, shop(), o, all);
      QVERIFY(i.has_value());
      const double best = economicCost(pointEconomics(shop(), t.points()[*i]), o);
      for (const ParetoPoint& p : t.points()) QVERIFY(economicCost(pointEconomics(shop(), p), o) >= best);
    }
  }

  void costAndRateOptimaAreOrdered() {
    const ObjectiveTable& t = test::paretoCaseTable();
    const PartEconomics cheap =
        pointEconomics(shop(), t.points()[*cheapestPoint(t, shop(), EconomicObjective::MinCost, all)]);
    const PartEconomics fast =
        pointEconomics(shop(), t.points()[*cheapestPoint(t, shop(), EconomicObjective::MaxRate, all)]);
    QVERIFY(cheap.cost_per_part <= fast.cost_per_part);
    QVERIFY(fast.time_per_part_s <= cheap.time_per_part_s);
  }

  void filterAndEmpty() {
    const ObjectiveTable& t = test::paretoCaseTable();
    const double slow = 40.0;  // rev/s
    const auto i = cheapestPoint(t, shop(), EconomicObjective::MinCost,
                                 [&](const ParetoPoint& p) { return p.speed_rev_per_s <= slow; });
    QVERIFY(i && t.points()[*i].speed_rev_per_s <= slow);
    QVERIFY(!cheapestPoint(t, shop(), EconomicObjective::MinCost, [](const ParetoPoint&) { return false; }));
  }
};

MX_REGISTER_TEST(TestEconomicSelection)
#include "test_economic_selection.moc"
