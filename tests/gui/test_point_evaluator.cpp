// The lobe chart's power line and readout against the available spindle power P_av(N): with a torque
// T_max the depth limit P_av(N) / (k N s_t) is the constant 2 pi T_max / (k s_t) below the corner speed
// (constant torque) and falls as P_max / (k N s_t) above it. R1 (2006 example), k = pi D K_t = 5.655e7.
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "model/cutting_force.h"
#include "point_evaluator.h"
#include "stability/lobe_computation.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::gui;

namespace {
std::shared_ptr<const LobeSnapshot> rubioSnapshot(const std::vector<double>& speeds_rev_per_s) {
  auto s = std::make_shared<LobeSnapshot>();
  ToolLobes t;
  t.setup = test::rubioR1();
  t.margined = computeLobes(t.setup, speeds_rev_per_s, LobeSettings{});
  t.nominal = t.margined;
  s->tools.push_back(t);
  return s;
}
}  // namespace

class TestPointEvaluator : public QObject {
  Q_OBJECT
 private slots:
  // P_max 745.3 W, 1 N·m: corner 745.3 / (2 pi) rev/s = 7117 rpm. At s_t = 0.1 mm the line is
  // 2 pi / (k 1e-4) = 1.111 mm at 3000 and 6000 rpm, and 745.3 / (k N 1e-4) = 0.988 mm at 8000 rpm.
  void powerLineFollowsTheTorque() {
    const std::vector<double> speeds{3000.0 / 60.0, 6000.0 / 60.0, 8000.0 / 60.0};
    SpindlePowerCurve spindle;
    spindle.max_power_w = 745.3;
    spindle.max_torque_nm = 1.0;
    const PointEvaluator e(rubioSnapshot(speeds), spindle);
    const QVector<double> line = e.powerLimitMm(0, 0.1);
    QCOMPARE(line.size(), 3);
    const double k = peakPerDepthFeed(test::rubioR1(), 1e-3, 1e-4).power_w_per_rev_per_s;
    QCOMPARE_LE(std::abs(k / 5.655e7 - 1.0), 1e-3);
    QCOMPARE_LE(std::abs(line[0] - 2.0 * std::numbers::pi / (k * 1e-4) * 1e3), 1e-9);
    QCOMPARE_LE(std::abs(line[0] - 1.111), 0.002);
    QCOMPARE_LE(std::abs(line[1] - line[0]), 1e-12);
    QCOMPARE_LE(std::abs(line[2] - 745.3 / (k * speeds[2] * 1e-4) * 1e3), 1e-9);
    QCOMPARE_LE(std::abs(line[2] - 0.988), 0.002);
    // The readout's limit is P_av at the point's speed: 2 pi 50 1 = 314.16 W at 3000 rpm.
    const widgets::PointReadout r = e.evaluate(0, 3000.0, 0.5, 0.1);
    QCOMPARE_LE(std::abs(r.power_limit_w - 100.0 * std::numbers::pi), 1e-9);
    QCOMPARE_LE(std::abs(r.powerFraction() - r.peak_power_w / (100.0 * std::numbers::pi)), 1e-12);
  }

  void noMachineNoLine() {
    const PointEvaluator e(rubioSnapshot({3000.0 / 60.0, 6000.0 / 60.0}), SpindlePowerCurve{});
    QVERIFY(e.powerLimitMm(0, 0.1).isEmpty());
    QCOMPARE(e.evaluate(0, 3000.0, 0.5, 0.1).power_limit_w, 0.0);
  }

  // The readout's force: K_t sqrt(1 + K_r^2) b s_t for R1 slotting (626.4 N/mm^2 * 0.5 mm * 0.1 mm =
  // 31.32 N) against F_allow; no limit (+inf or no entry) reads as 0 and passes.
  void forceAgainstTheToolLimit() {
    PointEvaluator e(rubioSnapshot({3000.0 / 60.0, 6000.0 / 60.0}), SpindlePowerCurve{});
    widgets::PointReadout r = e.evaluate(0, 3000.0, 0.5, 0.1);
    QCOMPARE_LE(std::abs(r.peak_force_n - 600.0 * std::sqrt(1.09) * 0.5 * 0.1), 1e-6);
    QCOMPARE(r.force_limit_n, 0.0);
    QVERIFY(r.forceOk());
    e.setForceLimits({30.0});
    r = e.evaluate(0, 3000.0, 0.5, 0.1);
    QCOMPARE(r.force_limit_n, 30.0);
    QVERIFY(!r.forceOk());
    QCOMPARE_LE(std::abs(r.forceFraction() - r.peak_force_n / 30.0), 1e-12);
    e.setForceLimits({std::numeric_limits<double>::infinity()});
    QCOMPARE(e.evaluate(0, 3000.0, 0.5, 0.1).force_limit_n, 0.0);
  }
};

MX_REGISTER_TEST(TestPointEvaluator)
#include "test_point_evaluator.moc"
