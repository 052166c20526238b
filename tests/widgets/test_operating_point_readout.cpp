// The operating-point readout: the lobes' verdict (stable, marginal, unstable, over a limit), the
// simulation of the same point beside it, and a note, when the two disagree, that shows both and says
// the verdict follows the lobes. Marginal points carry no note: there the two may differ.
#include "display_units.h"
#include "operating_point_readout.h"
#include "test_registry.h"

using mx::widgets::OperatingPointReadout;
using mx::widgets::PointReadout;
using mx::widgets::SimulationCheck;

namespace {
PointReadout readout(bool stable, bool marginal) {
  PointReadout r;
  r.tool_id = "R1";
  r.speed_rpm = 3995.0;
  r.depth_mm = 1.007;
  r.blim_mm = 0.943;
  r.valid = true;
  r.stable = stable;
  r.marginal = marginal;
  return r;
}
}  // namespace

class TestOperatingPointReadout : public QObject {
  Q_OBJECT
 private slots:
  void verdictSimulationAndNote_data() {
    QTest::addColumn<bool>("stable");
    QTest::addColumn<bool>("marginal");
    QTest::addColumn<int>("state");
    QTest::addColumn<bool>("chatter");
    QTest::addColumn<QString>("verdict");
    QTest::addColumn<QString>("simulation");
    QTest::addColumn<QString>("note");  // its start; "" for none
    using S = SimulationCheck::State;
    QTest::newRow("stable, agreed") << true << false << int(S::Done) << false << "STABLE"
                                    << "STABLE (\u03b7 = 1.006)"
                                    << "";
    QTest::newRow("unstable, run stable") << false << false << int(S::Done) << false << "UNSTABLE"
                                          << "STABLE (\u03b7 = 1.006)"
                                          << "The lobes say UNSTABLE, the simulation says STABLE (\u03b7 = 1.006). "
                                             "The verdict follows the lobes";
    QTest::newRow("stable, run chatters") << true << false << int(S::Done) << true << "STABLE"
                                          << "CHATTER (\u03b7 = 1.006)"
                                          << "The lobes say STABLE, the simulation says CHATTER";
    QTest::newRow("marginal, run stable") << false << true << int(S::Done) << false << "MARGINAL"
                                          << "STABLE (\u03b7 = 1.006)"
                                          << "";
    QTest::newRow("unstable, running") << false << false << int(S::Running) << false << "UNSTABLE"
                                       << "running..."
                                       << "";
    QTest::newRow("unstable, none") << false << false << int(S::None) << false << "UNSTABLE"
                                    << "not run for this point"
                                    << "";
  }
  void verdictSimulationAndNote() {
    QFETCH(bool, stable);
    QFETCH(bool, marginal);
    QFETCH(int, state);
    QFETCH(bool, chatter);
    QFETCH(QString, verdict);
    QFETCH(QString, simulation);
    QFETCH(QString, note);
    OperatingPointReadout w;
    w.setReadout(readout(stable, marginal));
    w.setSimulation({SimulationCheck::State(state), chatter, 1.006});
    QVERIFY2(w.text("verdict").startsWith(verdict), qPrintable(w.text("verdict")));
    QCOMPARE(w.text("simulation"), simulation);
    if (note.isEmpty())
      QCOMPARE(w.agreementNote(), QString());
    else
      QVERIFY2(w.agreementNote().startsWith(note), qPrintable(w.agreementNote()));
  }

  // A new point without its run: the note goes with the run it was about.
  void aNewPointDropsTheNote() {
    OperatingPointReadout w;
    w.setReadout(readout(false, false));
    w.setSimulation({SimulationCheck::State::Done, false, 1.006});
    QVERIFY(!w.agreementNote().isEmpty());
    w.setSimulation({});
    QCOMPARE(w.agreementNote(), QString());
    QCOMPARE(w.text("simulation"), QString("not run for this point"));
  }

  // Shop units: every value converts and names its unit, and follows a change of the units at once.
  void followsShopUnits() {
    PointReadout r = readout(true, false);
    r.feed_mm_per_tooth = 0.1;
    r.surface_speed_m_min = 376.99;
    r.feed_rate_mm_min = 1598.0;
    r.peak_power_w = 2745.3;
    r.power_limit_w = 7456.99872;
    r.peak_force_n = 812.3;
    r.mrr_mm3_per_s = 3000.0;  // 180 cm³/min
    mx::widgets::DisplayUnits units;
    OperatingPointReadout w;
    w.setUnits(&units);
    w.setReadout(r);
    QCOMPARE(w.text("power"), QString("2745.3 W"));
    QCOMPARE(w.text("mrr"), QString::fromUtf8("180.00 cm³/min"));
    QCOMPARE(w.text("surface_speed"), QString("377.0 m/min"));
    QCOMPARE(w.text("feed_rate"), QString("1598.0 mm/min"));
    units.setShop(mx::widgets::ShopUnits::inch());
    QCOMPARE(w.text("power"), QString("3.682 hp"));
    QCOMPARE(w.text("power_fraction"), QString("36.8 % of 10.000 hp"));
    QCOMPARE(w.text("force"), QString("182.6 lbf"));
    QCOMPARE(w.text("depth"), QString("0.03965 in"));
    QCOMPARE(w.text("feed"), QString("0.00394 in/tooth"));
    QCOMPARE(w.text("surface_speed"), QString("1237 SFM"));
    QCOMPARE(w.text("feed_rate"), QString("62.91 IPM"));
    QCOMPARE(w.text("mrr"), QString::fromUtf8("10.984 in³/min"));
    QCOMPARE(w.text("blim"), QString("0.03713 in"));
  }
};

MX_REGISTER_TEST(TestOperatingPointReadout)
#include "test_operating_point_readout.moc"
