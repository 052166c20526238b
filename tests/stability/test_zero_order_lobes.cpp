// Zeroth-order lobes (Rubio et al. 2006 eq. 8-10) against analytic limits and the delta margin.
#include <algorithm>
#include <cmath>

#include "stability/zero_order_lobes.h"
#include "support/fixtures.h"
#include "support/speed_grids.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::rpmGrid;
double minOverLobes(const LobeDiagram& d) {
  double m = LobeDiagram::kNone;
  for (const LobeCurve& c : d.lobes)
    for (double b : c.depth_m) m = std::min(m, b);
  return m;
}
using mx::test::minFinite;
}  // namespace

class TestZeroOrderLobes : public QObject {
  Q_OBJECT
 private slots:
  // Analytic limit: one mode, full immersion: min lobe = 2 pi / (n_t K_t alpha_xx Re G_min), 0.5 %.
  void singleModeMinimumMatchesClosedForm_data() {
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("kr");
    QTest::newRow("insperger 2 teeth") << 2 << 0.011 << 1.0 / 3.0;
    QTest::newRow("3 teeth zeta 3.9%") << 3 << 0.039 << 0.3;
    QTest::newRow("4 teeth zeta 0.5%") << 4 << 0.005 << 0.07;
  }
  void singleModeMinimumMatchesClosedForm() {
    QFETCH(int, teeth);
    QFETCH(double, zeta);
    QFETCH(double, kr);
    MillingSetup s = test::insperger(1.0);
    s.teeth = teeth;
    s.radial_ratio = kr;
    s.modes_x.front().damping_ratio = zeta;
    const double closed = singleModeMinimumDepth(s);
    QVERIFY(closed > 0.0);
    const LobeDiagram d = computeZoaLobes(s, rpmGrid(5000, 25000, 10), {});
    QVERIFY(std::abs(minOverLobes(d) / closed - 1.0) < 0.005);
    // The envelope's refined local minima on a 10 rpm grid agree too.
    double best = LobeDiagram::kNone;
    for (const LobeMinimum& m : d.minima) best = std::min(best, m.depth_m);
    QVERIFY2(std::abs(best / closed - 1.0) < 0.005, qPrintable(QString("%1 vs %2").arg(best).arg(closed)));
  }

  // A mode at the largest double's frequency: the lobe count is capped in floating point, never
  // converted from infinity to int; the answer is the 400-lobe cap, all finite or none.
  void hugeModeFrequencyStaysBounded() {
    MillingSetup s = test::insperger(1.0);
    s.modes_x.front().natural_frequency_hz = 1.797e308;
    const LobeDiagram d = computeZoaLobes(s, rpmGrid(1000, 2000, 100), {});
    QVERIFY(d.lobes.size() <= 400u);
    for (const LobeCurve& c : d.lobes)
      for (double b : c.depth_m) QVERIFY(std::isfinite(b));
  }

  // Insperger benchmark value: full immersion lobe minimum = 2 k zeta (1+zeta) * 2 / (n_t K_t K_r pi).
  void inspergerFullImmersionValue() {
    const MillingSetup s = test::insperger(1.0);
    const double k = s.modes_x.front().stiffness_n_per_m;
    const double expected = 8.0 * k * 0.011 * 1.011 / (2.0 * 6e8 * (1.0 / 3.0));
    QCOMPARE_LE(std::abs(singleModeMinimumDepth(s) / expected - 1.0), 1e-12);
  }

  void deltaZeroIsNominalAndLobesFallWithDelta() {
    const MillingSetup s = test::rubioR1();
    const auto speeds = rpmGrid(3000, 12000, 50);
    ZoaOptions o;
    const LobeDiagram nominal = computeZoaLobes(s, speeds, o);
    double previous = minFinite(nominal.envelope_depth_m);
    for (double delta : {5.0, 20.0, 60.0, 120.0}) {
      o.delta_per_s = delta;
      const LobeDiagram d = computeZoaLobes(s, speeds, o);
      for (size_t i = 0; i < speeds.size(); ++i)
        QVERIFY(d.envelope_depth_m[i] <= nominal.envelope_depth_m[i] * (1.0 + 1e-9));
      const double m = minFinite(d.envelope_depth_m);
      QVERIFY2(m < previous, qPrintable(QString("delta %1: min %2 >= %3").arg(delta).arg(m).arg(previous)));
      previous = m;
    }
  }

  void deltaAtOrAboveDecayRateIsRefused_data() {
    QTest::addColumn<double>("delta");
    const MillingSetup s = test::rubioR1();
    const double limit = smallestDecayRate(s.modes_x, s.modes_y);
    QTest::newRow("at limit") << limit;
    QTest::newRow("above") << limit * 2.0;
    QTest::newRow("negative") << -1.0;
  }
  void deltaAtOrAboveDecayRateIsRefused() {
    QFETCH(double, delta);
    ZoaOptions o;
    o.delta_per_s = delta;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, computeZoaLobes(test::rubioR1(), rpmGrid(3000, 6000, 100), o));
  }

  void rigidToolHasNoLobes() {
    MillingSetup s = test::rubioR1();
    s.modes_x.clear();
    s.modes_y.clear();
    const LobeDiagram d = computeZoaLobes(s, rpmGrid(3000, 6000, 100), {});
    for (double b : d.envelope_depth_m) QVERIFY(std::isinf(b));
  }

  // R1 lobe minima lie near 4790, 7760 and 20460 rpm (shared/notes/seed-reading.md).
  void rubioR1MinimaSpeeds() {
    const LobeDiagram d = computeZoaLobes(test::rubioR1(), rpmGrid(3000, 25000, 10), {});
    for (double expected : {4790.0, 7760.0, 20460.0}) {
      bool found = false;
      for (const LobeMinimum& m : d.minima) found = found || std::abs(m.speed_rev_per_s * 60.0 - expected) < 60.0;
      QVERIFY2(found, qPrintable(QString("no minimum near %1 rpm").arg(expected)));
    }
  }
};

MX_REGISTER_TEST(TestZeroOrderLobes)
#include "test_zero_order_lobes.moc"
