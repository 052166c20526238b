// t_s, M_p, R12h, R1ch and the Rule 6 test from one simulation (stable and chattering cuts of R1).
#include <cmath>

#include "expert/response_metrics.h"
#include "simulation/milling_simulation.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
ResponseMetrics run(double rpm, double depth_mm, double feed_mm) {
  const MillingSetup r1 = test::rubioR1();
  const OperatingPoint p{rpm / 60.0, depth_mm * 1e-3, feed_mm * 1e-3};
  SimulationOptions o;  // 60 revolutions, last 20 evaluated, every step recorded
  return responseMetrics(r1, p, simulateMilling(r1, p, o), o.evaluated_revolutions);
}
}  // namespace

class TestResponseMetrics : public QObject {
  Q_OBJECT
 private slots:
  // q* of the example: stable, settles within a few tooth periods, no malfunction.
  void stablePoint() {
    const ResponseMetrics m = run(5800.0, 0.5048, 0.27);
    qInfo("stable: t_s = %.4f s, M_p = %.4f, R12h = %.4f, R1ch = %.2e", m.settling_time_s, m.overshoot, m.r12h, m.r1ch);
    QVERIFY(!m.chatter);
    QVERIFY(!m.malfunction());
    QVERIFY(m.settling_time_s <= 2.0 / 290.0);  // within two tooth periods (0 here: within 5 % from the first)
    QVERIFY(m.overshoot >= 0.0 && m.overshoot < 0.05);
    QVERIFY(m.r12h > 0.0 && m.r12h < 2.0);
    QVERIFY(m.r1ch < 0.05);  // the non-harmonic content of a stable cut is a decayed transient
  }

  // Above the lobe minimum near 4786 rpm: chatter, the chatter peak dominates the harmonics.
  void chatteringPoint() {
    const ResponseMetrics m = run(4800.0, 1.5, 0.1);
    qInfo("chatter: t_s = %.4f s, M_p = %.4f, R12h = %.4f, R1ch = %.2e", m.settling_time_s, m.overshoot, m.r12h,
          m.r1ch);
    QVERIFY(m.chatter);
    QVERIFY(m.malfunction());
    QVERIFY(m.r1ch > 1.0);
    QVERIFY(m.settling_time_s > 0.5);  // never settles within the 0.75 s run
    QVERIFY(run(5800.0, 0.3, 0.1).r1ch < m.r1ch);
  }
};

MX_REGISTER_TEST(TestResponseMetrics)
#include "test_response_metrics.moc"
