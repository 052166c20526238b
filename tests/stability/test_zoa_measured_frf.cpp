// ZOA on a measured receptance FRF (Rubio et al. 2006 eq. 8-10 with G(i omega) interpolated between
// lines): agreement with the modal ZOA on a fine frequency grid, mixed axes, and the refused options.
#include <algorithm>
#include <cmath>

#include "stability/lobe_computation.h"
#include "stability/zero_order_lobes.h"
#include "support/fixtures.h"
#include "support/speed_grids.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::rpmGrid;

// The modal reference: 40 000 uniform chatter frequencies plus the dense bands around the modes.
LobeDiagram fineModalLobes(const MillingSetup& s, const std::vector<double>& speeds) {
  ZoaOptions o;
  o.frequency_samples = 40000;
  return computeZoaLobes(s, speeds, o);
}

LobeDiagram measuredLobes(const MillingSetup& s, const std::vector<double>& speeds) {
  ZoaOptions o;
  o.dynamics = DynamicsSource::Measured;
  return computeZoaLobes(s, speeds, o);
}

// Largest |b / b_ref - 1| over the speeds; +inf when one envelope is capped where the other is not.
double worstRelativeError(const LobeDiagram& d, const LobeDiagram& ref) {
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.envelope_depth_m.size(); ++i) {
    const double b = d.envelope_depth_m[i], b_ref = ref.envelope_depth_m[i];
    if (std::isinf(b) && std::isinf(b_ref)) continue;
    worst = std::max(worst, std::abs(b / b_ref - 1.0));
  }
  return worst;
}

MillingSetup withMeasuredAxes(MillingSetup s, bool x, bool y) {
  if (x) s.measured_x = test::sampledAxis(s.modes_x, 0.0, 4000.0, 1.0);
  if (y && !s.modes_y.empty()) s.measured_y = test::sampledAxis(s.modes_y, 0.0, 4000.0, 1.0);
  return s;
}
}  // namespace

class TestZoaMeasuredFrf : public QObject {
  Q_OBJECT
 private slots:
  // FRFs sampled from the modes at 1 Hz lines (0-4000 Hz), the modes then removed: the measured ZOA
  // envelope agrees with the fine modal one within 1 % at every speed.
  void measuredEnvelopeMatchesFineModal_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("from_rpm");
    QTest::addColumn<double>("to_rpm");
    QTest::newRow("R1, 2 modes") << 0 << 3000.0 << 25000.0;
    QTest::newRow("R2, 2 modes") << 1 << 5000.0 << 40000.0;
    QTest::newRow("Insperger, half immersion") << 2 << 5000.0 << 25000.0;
  }
  void measuredEnvelopeMatchesFineModal() {
    QFETCH(int, tool);
    QFETCH(double, from_rpm);
    QFETCH(double, to_rpm);
    const MillingSetup modal = tool == 0 ? test::rubioR1() : tool == 1 ? test::rubioR2() : test::insperger(0.5);
    MillingSetup measured = withMeasuredAxes(modal, true, true);
    measured.modes_x.clear();
    measured.modes_y.clear();
    const auto speeds = rpmGrid(from_rpm, to_rpm, 10.0);
    const LobeDiagram ref = fineModalLobes(modal, speeds);
    const LobeDiagram d = measuredLobes(measured, speeds);
    QVERIFY(std::any_of(ref.envelope_depth_m.begin(), ref.envelope_depth_m.end(),
                        [](double b) { return std::isfinite(b); }));
    const double worst = worstRelativeError(d, ref);
    qInfo("%s: worst envelope difference %.4f %% over %zu speeds", QTest::currentDataTag(), 100.0 * worst,
          speeds.size());
    QVERIFY2(worst < 0.01, qPrintable(QString("worst %1 %").arg(100.0 * worst)));
  }

  // Measured x with modal y: agrees with the all-modal reference as well.
  void mixedAxesMatchFineModal() {
    const MillingSetup modal = test::rubioR1();
    MillingSetup mixed = withMeasuredAxes(modal, true, false);
    mixed.modes_x.clear();
    const auto speeds = rpmGrid(3000.0, 25000.0, 10.0);
    const double worst = worstRelativeError(measuredLobes(mixed, speeds), fineModalLobes(modal, speeds));
    qInfo("mixed axes (measured x, modal y): worst envelope difference %.4f %%", 100.0 * worst);
    QVERIFY2(worst < 0.01, qPrintable(QString("worst %1 %").arg(100.0 * worst)));
  }

  // Invariant: with dynamics = Modal the measured FRFs are ignored (here FRFs of other, stiffer modes,
  // and one that is invalid): the diagram is the same to the bit.
  void modalIgnoresMeasuredAxes() {
    const MillingSetup s = test::rubioR1();
    MillingSetup with_frf = s;
    with_frf.measured_x = test::sampledAxis({{700.0, 0.05, 2e7}}, 0.0, 2000.0, 1.0);
    with_frf.measured_y = MeasuredAxis{{10.0, 5.0}, {{1.0, 0.0}, {1.0, 0.0}}};  // not increasing
    const auto speeds = rpmGrid(3000.0, 12000.0, 50.0);
    const LobeDiagram a = computeZoaLobes(s, speeds, {});
    const LobeDiagram b = computeZoaLobes(with_frf, speeds, {});
    QCOMPARE(b.envelope_depth_m, a.envelope_depth_m);
    QCOMPARE(b.envelope_chatter_hz, a.envelope_chatter_hz);
    // Measured without any measured axis falls back to the modes on both axes: the same diagram.
    QCOMPARE(measuredLobes(s, speeds).envelope_depth_m, a.envelope_depth_m);
  }

  void measuredAxisOverridesItsModes() {
    // An axis with both: the measured FRF (here of a mode twice as stiff) is used, not the modes.
    const MillingSetup modal = test::insperger(0.5);
    MillingSetup stiff = modal;
    stiff.modes_x.front().stiffness_n_per_m *= 2.0;
    MillingSetup both = modal;
    both.measured_x = test::sampledAxis(stiff.modes_x, 0.0, 4000.0, 1.0);
    const auto speeds = rpmGrid(5000.0, 25000.0, 10.0);
    const double worst = worstRelativeError(measuredLobes(both, speeds), fineModalLobes(stiff, speeds));
    QVERIFY2(worst < 0.01, qPrintable(QString("worst %1 %").arg(100.0 * worst)));
  }

  void rigidToolHasNoLobes() {
    MillingSetup s = test::rubioR1();
    s.modes_x.clear();
    s.modes_y.clear();
    for (double b : measuredLobes(s, rpmGrid(3000, 6000, 100)).envelope_depth_m) QVERIFY(std::isinf(b));
  }

  void deltaWithMeasuredIsRefused() {
    const MillingSetup s = withMeasuredAxes(test::rubioR1(), true, true);
    ZoaOptions o;
    o.dynamics = DynamicsSource::Measured;
    o.delta_per_s = 5.0;
    try {
      computeZoaLobes(s, rpmGrid(3000, 6000, 100), o);
      QFAIL("delta > 0 accepted with a measured FRF");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains("G(i omega) only") && QString(e.what()).contains("delta must be 0"),
               e.what());
    }
    o.delta_per_s = 0.0;
    QVERIFY(!computeZoaLobes(s, rpmGrid(3000, 6000, 100), o).lobes.empty());
  }

  void invalidMeasuredAxisIsNamed() {
    MillingSetup s = test::rubioR1();
    s.measured_y = MeasuredAxis{{0.0, 10.0, 10.0}, {{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}}};
    ZoaOptions o;
    o.dynamics = DynamicsSource::Measured;
    try {
      computeZoaLobes(s, rpmGrid(3000, 6000, 100), o);
      QFAIL("an invalid measured FRF was accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).startsWith("measured_y: frequency_hz[2]"), e.what());
    }
  }

  // computeLobes passes the source to the ZOA and refuses it for semi-discretization.
  void lobeSettingsPassDynamics() {
    MillingSetup s = withMeasuredAxes(test::rubioR1(), true, true);
    s.modes_x.clear();
    s.modes_y.clear();
    const auto speeds = rpmGrid(3000.0, 12000.0, 50.0);
    LobeSettings settings;
    settings.dynamics = DynamicsSource::Measured;
    QCOMPARE(computeLobes(s, speeds, settings).envelope_depth_m, measuredLobes(s, speeds).envelope_depth_m);
    settings.method = StabilityMethod::SemiDiscretization;
    try {
      computeLobes(s, speeds, settings);
      QFAIL("semi-discretization accepted a measured FRF");
    } catch (const InvalidInput& e) {
      QCOMPARE(QString(e.what()), QString("semi-discretization needs a state-space model: use fitted modes"));
    }
  }
};

MX_REGISTER_TEST(TestZoaMeasuredFrf)
#include "test_zoa_measured_frf.moc"
