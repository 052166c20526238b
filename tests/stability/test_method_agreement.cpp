// Two independent stability methods agree where both are valid: the zeroth-order approximation
// (Rubio et al. 2006 eq. 8-10) and first-order semi-discretization, at full immersion with 3 or
// more teeth, compared at the lobe minima (within 5 %).
#include <algorithm>
#include <cmath>

#include "stability/semi_discretization.h"
#include "stability/zero_order_lobes.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestMethodAgreement : public QObject {
  Q_OBJECT
 private slots:
  void zoaAndSdmAgreeAtLobeMinima_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("from_rpm");
    QTest::addColumn<double>("to_rpm");
    QTest::newRow("Rubio R1, 3 teeth") << 1 << 3000.0 << 12000.0;
    QTest::newRow("Rubio R1, 4 teeth") << 2 << 3000.0 << 12000.0;
    QTest::newRow("Insperger mode, 4 teeth") << 3 << 5000.0 << 20000.0;
  }
  void zoaAndSdmAgreeAtLobeMinima() {
    QFETCH(int, tool);
    QFETCH(double, from_rpm);
    QFETCH(double, to_rpm);
    MillingSetup s = tool == 3 ? test::insperger(1.0) : test::rubioR1();
    if (tool != 1) s.teeth = 4;
    const auto speeds = SpeedGrid{from_rpm / 60.0, to_rpm / 60.0, 25.0 / 60.0}.values();
    const LobeDiagram zoa = computeZoaLobes(s, speeds, {});
    SdmOptions o;
    o.steps_per_period = 40;
    const LobeDiagram sdm = computeSdmLobes(s, speeds, o);
    QVERIFY(!zoa.minima.empty());
    int compared = 0;
    for (const LobeMinimum& m : zoa.minima) {
      // The SDM envelope minimum nearest this ZOA minimum.
      const LobeMinimum* best = nullptr;
      for (const LobeMinimum& q : sdm.minima)
        if (!best ||
            std::abs(q.speed_rev_per_s - m.speed_rev_per_s) < std::abs(best->speed_rev_per_s - m.speed_rev_per_s))
          best = &q;
      QVERIFY(best != nullptr);
      const double rel = std::abs(best->depth_m / m.depth_m - 1.0);
      qInfo("ZOA min %.0f rpm %.4f mm | SDM %.0f rpm %.4f mm | %.2f %%", m.speed_rev_per_s * 60, m.depth_m * 1e3,
            best->speed_rev_per_s * 60, best->depth_m * 1e3, rel * 100);
      QVERIFY2(rel < 0.05, qPrintable(QString("lobe minimum differs by %1 %").arg(rel * 100)));
      ++compared;
    }
    QVERIFY(compared >= 2);
  }
};

MX_REGISTER_TEST(TestMethodAgreement)
#include "test_method_agreement.moc"
