// simulateMilling: input validation, the static limit (eta, chip ratio -> 1), free vibration decay at
// zeta * omega_n, the cutting power (Pareto eq. 8; seed note: R1 at q* about 730 W), streaming chunks,
// progress and cancellation.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "model/cutting_force.h"
#include "simulation/simulation.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {

using mx::test::kRubioQStar;

MillingSetup stiffened(MillingSetup s, double factor) {
  for (Mode& m : s.modes_x) m.stiffness_n_per_m *= factor;
  for (Mode& m : s.modes_y) m.stiffness_n_per_m *= factor;
  return s;
}

// Decay rate and damped frequency from the positive peaks of a free vibration: least-squares fit of
// ln(peak) against time (peaks refined by a parabola through three samples).
struct EnvelopeFit {
  double decay_rate = 0.0, damped_hz = 0.0;
  int peaks = 0;
};
EnvelopeFit fitEnvelope(const std::vector<double>& t, const std::vector<double>& x, double floor) {
  std::vector<double> tp, lp;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    if (!(x[i] > x[i - 1] && x[i] >= x[i + 1]) || x[i] < floor) continue;
    const double a = x[i - 1], b = x[i], c = x[i + 1];
    const double d = 0.5 * (a - c) / (a - 2 * b + c);
    tp.push_back(t[i] + d * (t[i + 1] - t[i]));
    lp.push_back(std::log(b - 0.25 * (a - c) * d));
  }
  EnvelopeFit fit;
  fit.peaks = static_cast<int>(tp.size());
  if (tp.size() < 3) return fit;
  double st = 0, sl = 0, stt = 0, stl = 0;
  const double n = static_cast<double>(tp.size());
  for (std::size_t i = 0; i < tp.size(); ++i) {
    st += tp[i];
    sl += lp[i];
    stt += tp[i] * tp[i];
    stl += tp[i] * lp[i];
  }
  fit.decay_rate = -(n * stl - st * sl) / (n * stt - st * st);
  fit.damped_hz = (n - 1) / (tp.back() - tp.front());
  return fit;
}

}  // namespace

class TestMillingSimulation : public QObject {
  Q_OBJECT
 private slots:
  // A (nearly) rigid tool cuts the static chip: eta and the chip ratio tend to 1 and the peak force
  // to the static one of evaluateCut. The window here includes the start of the cut (revolution 2).
  void staticLimit_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("depth_mm");
    QTest::newRow("R1, tiny depth 1e-4 mm") << 1 << 1e-4;
    QTest::newRow("R1 with 1e6 x stiffer modes, q*") << 2 << 0.4924;
    QTest::newRow("rigid tool (no modes), q*") << 3 << 0.4924;
    QTest::newRow("Insperger half immersion, stiff, 0.5 mm") << 4 << 0.5;
  }
  void staticLimit() {
    QFETCH(int, tool);
    QFETCH(double, depth_mm);
    MillingSetup s = tool == 4 ? stiffened(test::insperger(0.5), 1e6) : test::rubioR1();
    if (tool == 2) s = stiffened(s, 1e6);
    if (tool == 3) s.modes_x.clear(), s.modes_y.clear();
    const OperatingPoint point{kRubioQStar.spindle_rev_per_s, depth_mm * 1e-3, kRubioQStar.feed_per_tooth_m};
    SimulationOptions options;
    options.revolutions = 2;
    options.evaluated_revolutions = 1;
    const ChatterIndicators ind = simulateMilling(s, point, options).indicators;
    QVERIFY2(std::abs(ind.eta - 1.0) < 0.01, qPrintable(QString::number(ind.eta)));
    QVERIFY2(std::abs(ind.chip_ratio - 1.0) < 0.01, qPrintable(QString::number(ind.chip_ratio)));
    QVERIFY(!ind.chatter);
    const CutPerformance rigid = evaluateCut(s, point);
    QVERIFY(std::abs(ind.peak_force_n / rigid.peak_force_n - 1.0) < 0.01);
    QVERIFY(std::abs(ind.peak_power_w / rigid.peak_power_w - 1.0) < 0.01);
  }

  // The same window at the real R1 sees the regenerative transient: eta > 1 (the indicator responds).
  void transientRaisesEta() {
    SimulationOptions options;
    options.revolutions = 2;
    options.evaluated_revolutions = 1;
    const ChatterIndicators ind = simulateMilling(test::rubioR1(), kRubioQStar, options).indicators;
    QVERIFY(ind.eta > 1.001 && ind.eta < 1.3);
  }

  // b = 0: the tool released from x0 rings down at zeta * omega_n with omega_d = omega_n sqrt(1 - zeta^2).
  void freeVibrationDecay_data() {
    QTest::addColumn<int>("axis");
    QTest::addColumn<double>("frequency_hz");
    QTest::addColumn<double>("zeta");
    QTest::newRow("R1 x mode (603 Hz, 3.9 %)") << 0 << 603.0 << 0.039;
    QTest::newRow("R1 y mode (666 Hz, 3.5 %)") << 1 << 666.0 << 0.035;
    QTest::newRow("light damping (1200 Hz, 1 %)") << 0 << 1200.0 << 0.01;
    QTest::newRow("heavy damping (400 Hz, 20 %)") << 1 << 400.0 << 0.2;
  }
  void freeVibrationDecay() {
    QFETCH(int, axis);
    QFETCH(double, frequency_hz);
    QFETCH(double, zeta);
    MillingSetup s = test::rubioR1();
    const Mode mode{frequency_hz, zeta, 5e6};
    (axis == 0 ? s.modes_x : s.modes_y) = {mode};
    SimulationOptions options;
    options.revolutions = 11;
    options.evaluated_revolutions = 1;
    (axis == 0 ? options.initial_x_m : options.initial_y_m) = 1e-5;
    const SimulationResult r = simulateMilling(s, {100.0, 0.0, 1e-4}, options);
    const EnvelopeFit fit = fitEnvelope(r.trace.time_s, axis == 0 ? r.trace.x_m : r.trace.y_m, 1e-5 * 1e-6);
    const double expected = mode.decayRate();
    qInfo("%d peaks: decay %.3f 1/s (zeta w = %.3f), f_d %.3f Hz", fit.peaks, fit.decay_rate, expected, fit.damped_hz);
    QVERIFY(fit.peaks >= 8);
    QVERIFY(std::abs(fit.decay_rate / expected - 1.0) < 0.02);
    QVERIFY(std::abs(fit.damped_hz / (frequency_hz * std::sqrt(1.0 - zeta * zeta)) - 1.0) < 0.005);
    QCOMPARE(r.indicators.peak_force_n, 0.0);
    QCOMPARE(r.indicators.eta, 1.0);
  }

  // Pareto eq. 8: P = pi D N sum F_t. Static peak at q* is 732.6 W (seed note: about 730 W, under 745.3 W).
  void peakPowerAtQStar_data() {
    QTest::addColumn<double>("stiffness_factor");
    QTest::newRow("R1 x 1e4 stiffness (tiny vibration)") << 1e4;
    QTest::newRow("R1 (stable: steady state cuts the static chip)") << 1.0;
  }
  void peakPowerAtQStar() {
    QFETCH(double, stiffness_factor);
    const MillingSetup s = stiffened(test::rubioR1(), stiffness_factor);
    const CutPerformance rigid = evaluateCut(s, kRubioQStar);
    QVERIFY(std::abs(rigid.peak_power_w - 732.6) < 0.001 * 732.6);
    const ChatterIndicators ind = simulateMilling(s, kRubioQStar, {}).indicators;
    qInfo("simulated peak power %.3f W, evaluateCut %.3f W", ind.peak_power_w, rigid.peak_power_w);
    QVERIFY(std::abs(ind.peak_power_w / rigid.peak_power_w - 1.0) < 0.01);
  }

  void chunksAndProgress() {
    SimulationOptions options;
    options.revolutions = 6;
    options.evaluated_revolutions = 2;
    options.record_every = 5;
    std::vector<int> revolutions;
    std::vector<double> streamed_force;
    std::size_t expected_first = 0;
    bool contiguous = true;
    options.on_chunk = [&](const SimulationChunk& c) {
      revolutions.push_back(c.revolution);
      contiguous = contiguous && c.first_index == expected_first && c.revolutions == 6 &&
                   c.time_s.size() == c.force_n.size() && c.x_m.size() == c.power_w.size();
      expected_first += c.time_s.size();
      streamed_force.insert(streamed_force.end(), c.force_n.begin(), c.force_n.end());
    };
    std::vector<double> progress;
    JobControl control;
    control.progress = [&](double f) { progress.push_back(f); };
    const SimulationResult r = simulateMilling(test::rubioR1(), kRubioQStar, options, control);
    QCOMPARE(revolutions, (std::vector<int>{1, 2, 3, 4, 5, 6}));
    QVERIFY(contiguous);
    QCOMPARE(streamed_force, r.trace.force_n);
    QCOMPARE(progress.size(), std::size_t{6});
    QVERIFY(std::is_sorted(progress.begin(), progress.end()));
    QCOMPARE(progress.back(), 1.0);
  }

  void cancellation() {
    std::atomic<bool> cancel{false};
    int progress_calls = 0, chunks = 0;
    JobControl control;
    control.cancel = &cancel;
    control.progress = [&](double f) {
      ++progress_calls;
      if (f >= 0.25) cancel = true;
    };
    SimulationOptions options;
    options.on_chunk = [&](const SimulationChunk&) { ++chunks; };
    QVERIFY_THROWS_EXCEPTION(Cancelled, simulateMilling(test::rubioR1(), kRubioQStar, options, control));
    QCOMPARE(progress_calls, 15);  // polled once per revolution: stops at the start of revolution 16 of 60
    QCOMPARE(chunks, 15);
    progress_calls = 0;
    QVERIFY_THROWS_EXCEPTION(Cancelled, simulateMilling(test::rubioR1(), kRubioQStar, options, control));
    QCOMPARE(progress_calls, 0);
  }

  void rejectsInvalidInput_data() {
    QTest::addColumn<int>("field");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("quantity");
    QTest::addColumn<QString>("shown");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("zero speed") << 0 << 0.0 << "spindle speed"
                                << "= 0 ";
    QTest::newRow("NaN speed") << 0 << nan << "spindle speed"
                               << "= nan ";
    QTest::newRow("negative depth") << 1 << -1e-4 << "axial depth"
                                    << "= -0.0001 ";
    QTest::newRow("zero feed") << 2 << 0.0 << "feed per tooth"
                               << "= 0 ";
    QTest::newRow("revolutions = evaluated") << 3 << 20.0 << "revolutions"
                                             << "= 20 ";
    QTest::newRow("no evaluated revolution") << 4 << 0.0 << "evaluated revolutions"
                                             << "= 0 ";
    QTest::newRow("|a| = 1") << 5 << 1.0 << "amplitude ratio"
                             << "= 1 ";
    QTest::newRow("a = -1.5") << 5 << -1.5 << "amplitude ratio"
                              << "= -1.5 ";
    QTest::newRow("negative SSV frequency") << 6 << -2.0 << "speed variation frequency"
                                            << "= -2 ";
    QTest::newRow("3 steps per tooth period") << 7 << 3.0 << "steps per tooth period"
                                              << "= 3 ";
    QTest::newRow("record_every 0") << 8 << 0.0 << "record_every"
                                    << "= 0 ";
    QTest::newRow("0 regenerative passes") << 9 << 0.0 << "regenerative passes"
                                           << "= 0 ";
    QTest::newRow("9 regenerative passes") << 9 << 9.0 << "regenerative passes"
                                           << "= 9 ";
    QTest::newRow("negative divergence limit") << 10 << -1.0 << "divergence limit"
                                               << "= -1 ";
    QTest::newRow("initial y on a rigid axis") << 11 << 1e-6 << "initial y displacement"
                                               << "= 1e-06 ";
    QTest::newRow("zero teeth") << 12 << 0.0 << "teeth"
                                << "= 0 ";
    QTest::newRow("zero diameter") << 13 << 0.0 << "diameter"
                                   << "= 0 ";
    QTest::newRow("damping ratio 1") << 14 << 1.0 << "modes_x[0] damping ratio"
                                     << "= 1 ";
    QTest::newRow("zero modal stiffness") << 15 << 0.0 << "modes_x[0] stiffness"
                                          << "= 0 ";
    // 3 rpm: m = 40 * 922 Hz * 10 s = 368800 steps per tooth period, 4.4e7 steps over 60 revolutions.
    QTest::newRow("too many steps at 3 rpm") << 0 << 0.05 << "total integration steps"
                                             << "= 4.4256e+07 ";
  }
  void rejectsInvalidInput() {
    QFETCH(int, field);
    QFETCH(double, value);
    QFETCH(QString, quantity);
    QFETCH(QString, shown);
    MillingSetup s = test::insperger(0.5);  // y axis rigid
    OperatingPoint p{100.0, 1e-4, 1e-4};
    SimulationOptions o;
    switch (field) {
      case 0:
        p.spindle_rev_per_s = value;
        break;
      case 1:
        p.axial_depth_m = value;
        break;
      case 2:
        p.feed_per_tooth_m = value;
        break;
      case 3:
        o.revolutions = static_cast<int>(value);
        break;
      case 4:
        o.evaluated_revolutions = static_cast<int>(value);
        break;
      case 5:
        o.ssv.amplitude_ratio = value;
        break;
      case 6:
        o.ssv.frequency_hz = value;
        break;
      case 7:
        o.steps_per_tooth_period = static_cast<int>(value);
        break;
      case 8:
        o.record_every = static_cast<int>(value);
        break;
      case 9:
        o.regenerative_passes = static_cast<int>(value);
        break;
      case 10:
        o.divergence_limit_m = value;
        break;
      case 11:
        o.initial_y_m = value;
        break;
      case 12:
        s.teeth = static_cast<int>(value);
        break;
      case 13:
        s.diameter_m = value;
        break;
      case 14:
        s.modes_x[0].damping_ratio = value;
        break;
      case 15:
        s.modes_x[0].stiffness_n_per_m = value;
        break;
    }
    try {
      simulateMilling(s, p, o);
      QFAIL("no InvalidInput thrown");
    } catch (const InvalidInput& e) {
      const QString message = e.what();
      QVERIFY2(message.contains(quantity) && message.contains(shown) && message.contains("allowed range"),
               qPrintable(message));
    }
  }
};

MX_REGISTER_TEST(TestMillingSimulation)
#include "test_milling_simulation.moc"
