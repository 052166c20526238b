// Where the zeroth-order approximation is valid (zoaValidity): ZOA against semi-discretization for uniform
// tools on both sides of the rule (some tooth always in the cut), and the rule's thresholds.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "stability/semi_discretization.h"
#include "stability/zero_order_lobes.h"
#include "stability/zoa_validity.h"
#include "support/fixtures.h"
#include "support/speed_grids.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kDeg;
using mx::test::minFinite;
using mx::test::rpmGrid;
MillingSetup r1(int teeth, double ratio, MillingDirection dir) {
  MillingSetup s = test::rubioR1();
  s.teeth = teeth;
  s.direction = dir;
  s.radial_depth_m = ratio * s.diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, dir);
  return s;
}
struct Errors {
  double minimum = 0.0;  // |min b_ZOA / min b_SDM - 1| over the speeds
  double median = 0.0;   // median over the speeds of |b_ZOA / b_SDM - 1|
};
Errors zoaAgainstSdm(const MillingSetup& s, const std::vector<double>& speeds) {
  ZoaOptions zo;
  zo.max_depth_m = 1.0;
  SdmOptions so;
  so.max_depth_m = 1.0;
  const LobeDiagram zoa = computeZoaLobes(s, speeds, zo);
  const LobeDiagram sdm = computeSdmLobes(s, speeds, so);
  std::vector<double> rel;
  for (size_t i = 0; i < speeds.size(); ++i)
    if (std::isfinite(zoa.envelope_depth_m[i]) && std::isfinite(sdm.envelope_depth_m[i]))
      rel.push_back(std::abs(zoa.envelope_depth_m[i] / sdm.envelope_depth_m[i] - 1.0));
  std::sort(rel.begin(), rel.end());
  return {std::abs(minFinite(zoa.envelope_depth_m) / minFinite(sdm.envelope_depth_m) - 1.0),
          rel.empty() ? 1.0 : rel[rel.size() / 2]};
}
}  // namespace

class TestZoaValidity : public QObject {
  Q_OBJECT
 private slots:
  // R1's modes, 3000-15000 rpm every 100 rpm. Measured (lowest b_lim %, median %): valid 2 teeth down
  // a/D 1: 1.4, 1.5; 3 teeth down 0.75: 0.6, 4.1; 4 teeth down 0.5: 6.4, 5.0; 4 teeth up 0.5: 0.1, 0.4.
  // Not valid: 2 teeth down 0.75: 19.9, 4.7; 3 teeth down 0.4: 32.3, 7.6; 2 teeth up 0.2: 20.9, 9.9.
  void zoaAgreesWithSdmWhereValid_data() {
    QTest::addColumn<int>("teeth");
    QTest::addColumn<bool>("down");
    QTest::addColumn<double>("ratio");
    QTest::addColumn<bool>("valid");
    QTest::newRow("2 teeth down, slot") << 2 << true << 1.0 << true;
    QTest::newRow("3 teeth down, a/D 0.75") << 3 << true << 0.75 << true;
    QTest::newRow("4 teeth down, a/D 0.5") << 4 << true << 0.5 << true;
    QTest::newRow("4 teeth up, a/D 0.5") << 4 << false << 0.5 << true;
    QTest::newRow("2 teeth down, a/D 0.75") << 2 << true << 0.75 << false;
    QTest::newRow("3 teeth down, a/D 0.4") << 3 << true << 0.4 << false;
    QTest::newRow("2 teeth up, a/D 0.2") << 2 << false << 0.2 << false;
  }
  void zoaAgreesWithSdmWhereValid() {
    QFETCH(int, teeth);
    QFETCH(bool, down);
    QFETCH(double, ratio);
    QFETCH(bool, valid);
    const MillingSetup s = r1(teeth, ratio, down ? MillingDirection::Down : MillingDirection::Up);
    QCOMPARE(zoaValidity(s).accurate, valid);
    const Errors e = zoaAgainstSdm(s, rpmGrid(3000, 15000, 100));
    qInfo("lowest b_lim %.1f %%, median %.1f %%", e.minimum * 100, e.median * 100);
    if (valid) {
      QVERIFY(e.minimum < 0.07);
      QVERIFY(e.median < 0.06);
    } else {
      QVERIFY(std::max(e.minimum, e.median) > 0.15);
    }
  }

  void thresholds() {
    for (auto [teeth, expected] : {std::pair{2, 1.0}, {3, 0.75}, {4, 0.5}, {6, 0.25}}) {
      MillingSetup s = r1(teeth, expected, MillingDirection::Up);
      QCOMPARE_LE(std::abs(zoaValidity(s).min_radial_immersion - expected), 1e-12);
      QVERIFY(zoaValidity(s).accurate);
      QCOMPARE_LE(std::abs(zoaValidity(s).radial_immersion - expected), 1e-12);
      s = r1(teeth, expected * 0.95, MillingDirection::Down);
      QVERIFY(!zoaValidity(s).accurate);
      QVERIFY(zoaValidity(s).reason.find("semi-discretization") != std::string::npos);
    }
    MillingSetup v = r1(4, 0.6, MillingDirection::Up);
    v.pitch_rad = {70 * kDeg, 110 * kDeg, 70 * kDeg, 110 * kDeg};
    QCOMPARE_LE(std::abs(zoaValidity(v).min_radial_immersion - 0.5 * (1.0 - std::cos(110 * kDeg))), 1e-12);
    QVERIFY(!zoaValidity(v).accurate);  // 0.6 < 0.671
    v = r1(4, 1.0, MillingDirection::Up);
    v.pitch_rad = {70 * kDeg, 110 * kDeg, 70 * kDeg, 110 * kDeg};
    QVERIFY(!zoaValidity(v).accurate);  // continuous, but the pitch's lobes need the SDM
    QVERIFY(zoaValidity(v).reason.find("variable pitch") != std::string::npos);
    v = r1(2, 1.0, MillingDirection::Up);
    v.pitch_rad = {170 * kDeg, 190 * kDeg};
    QVERIFY(!zoaValidity(v).accurate);
    QVERIFY(zoaValidity(v).reason.find("190") != std::string::npos);
    v.pitch_rad = {170 * kDeg, 170 * kDeg};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, zoaValidity(v));
  }
};

MX_REGISTER_TEST(TestZoaValidity)
#include "test_zoa_validity.moc"
