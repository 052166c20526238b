// Modal fits of synthetic receptances (modal_fit.h): LSCF + LSFD + NLLS with 0 % and 2 % noise, close
// modes, three modes, the given number of modes, peak picking, progress, cancellation, bad settings;
// the fit at poles chosen on the stabilisation diagram.
#include <atomic>

#include "core/invalid_input.h"
#include "modal_fit/modal_fit.h"
#include "modal_fit/modal_pole.h"
#include "support/modal_axis_metatype.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

Q_DECLARE_METATYPE(std::vector<std::complex<double>>)

namespace {

struct Errors {
  double frequency = 0.0, damping = 0.0, stiffness = 0.0;
};

// Largest relative errors over the modes; modes compared in frequency order.
Errors maxErrors(const ModalAxis& fitted, const ModalAxis& truth) {
  Errors e;
  for (std::size_t r = 0; r < truth.size() && r < fitted.size(); ++r) {
    e.frequency = std::max(e.frequency, relativeError(fitted[r].natural_frequency_hz, truth[r].natural_frequency_hz));
    e.damping = std::max(e.damping, relativeError(fitted[r].damping_ratio, truth[r].damping_ratio));
    e.stiffness = std::max(e.stiffness, relativeError(fitted[r].stiffness_n_per_m, truth[r].stiffness_n_per_m));
  }
  return e;
}

// The stable pole of the diagram's highest order nearest each frequency, as a user picks them.
std::vector<std::complex<double>> pickStablePoles(const StabilisationDiagram& diagram,
                                                  const std::vector<double>& near_hz) {
  std::vector<std::complex<double>> picked;
  for (const double f : near_hz) {
    const DiagramPole* best = nullptr;
    for (const DiagramPole& p : diagram.orders.back().poles)
      if (p.stability == PoleStability::Stable &&
          (!best || std::abs(p.frequency_hz - f) < std::abs(best->frequency_hz - f)))
        best = &p;
    if (best) picked.push_back(best->lambda);
  }
  return picked;
}

}  // namespace

class TestModalFit : public QObject {
  Q_OBJECT
 private slots:
  // Tolerances: frequency 0.5 %, damping 10 %, stiffness 5 %; fit error ~0 exact, ~noise level noisy.
  void lscfRecoversModes_data() {
    QTest::addColumn<ModalAxis>("truth");
    QTest::addColumn<double>("noise");
    QTest::addColumn<bool>("uneven");
    const ModalAxis single{{900.0, 0.02, 2e7}};
    const ModalAxis close{{800.0, 0.02, 2e7}, {840.0, 0.02, 2.5e7}};  // 5 % apart
    const ModalAxis three{{350.0, 0.025, 1.5e7}, {1000.0, 0.03, 3e7}, {1650.0, 0.015, 5e7}};
    QTest::newRow("single, exact") << single << 0.0 << false;
    QTest::newRow("single, 2 %") << single << 0.02 << false;
    QTest::newRow("close pair, exact") << close << 0.0 << false;
    QTest::newRow("close pair, 2 %") << close << 0.02 << false;
    QTest::newRow("three, exact") << three << 0.0 << false;
    QTest::newRow("three, 2 %") << three << 0.02 << false;
    QTest::newRow("three, 2 %, uneven grid") << three << 0.02 << true;
  }
  void lscfRecoversModes() {
    QFETCH(ModalAxis, truth);
    QFETCH(double, noise);
    QFETCH(bool, uneven);
    const auto frf = test::syntheticFrf(truth, 0.0, 2000.0, 2001, noise, 11, uneven);
    const auto fit = fitModes(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(100.0, 2000.0));
    QCOMPARE(fit.modes.size(), truth.size());
    const Errors e = maxErrors(fit.modes, truth);
    qInfo("max errors: frequency %.2e, damping %.2e, stiffness %.2e; fit error %.3f %%", e.frequency, e.damping,
          e.stiffness, fit.fit_error_pct);
    QCOMPARE_LE(e.frequency, noise > 0 ? 0.005 : 1e-9);
    QCOMPARE_LE(e.damping, noise > 0 ? 0.10 : 1e-9);
    QCOMPARE_LE(e.stiffness, noise > 0 ? 0.05 : 1e-9);
    // Relative noise of RMS `noise` gives a fit error of about 100 noise % (the model fits the mean).
    if (noise > 0) {
      QCOMPARE_GE(fit.fit_error_pct, 0.8 * 100 * noise);
      QCOMPARE_LE(fit.fit_error_pct, 1.1 * 100 * noise);
    } else {
      QCOMPARE_LE(fit.fit_error_pct, 1e-7);
    }
    QCOMPARE(fit.method, std::string("LSCF + LSFD + NLLS"));
    QCOMPARE(fit.fitted.size(), fit.band_frequency_hz.size());
    QCOMPARE(fit.diagram.orders.size(), std::size_t{19});
  }

  // Modes below and above the band are taken by the residual terms; the in-band modes stay close.
  void outOfBandModesTakenByResiduals() {
    const ModalAxis truth{{200.0, 0.03, 1e7}, {800.0, 0.02, 2e7}, {1200.0, 0.02, 3e7}, {3000.0, 0.03, 2e7}};
    const auto frf = test::syntheticFrf(truth, 0.0, 4000.0, 4001);
    const auto fit = fitModes(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(500.0, 1500.0));
    QCOMPARE(fit.modes.size(), std::size_t{2});
    const Errors e = maxErrors(fit.modes, {truth[1], truth[2]});
    QCOMPARE_LE(e.frequency, 1e-4);
    QCOMPARE_LE(e.damping, 0.02);
    QCOMPARE_LE(e.stiffness, 0.02);
    QCOMPARE_LE(fit.fit_error_pct, 1.0);
    QCOMPARE_GT(fit.residuals.upper.real(), 0.0);  // the 3000 Hz mode's compliance, ~1/k
  }

  void givenNumberOfModesKeepsTheMostSignificant() {
    const ModalAxis truth{{350.0, 0.025, 1.5e7}, {1000.0, 0.03, 3e7}, {1650.0, 0.015, 5e7}};
    const auto frf = test::syntheticFrf(truth, 0.0, 2000.0, 2001, 0.02, 5);
    auto settings = test::bandSettings(100.0, 2000.0);
    settings.modes = 2;  // peaks 1/(2 zeta k): 1.3e-6, 0.56e-6, 0.67e-6 m/N
    const auto fit = fitModes(frf.frequency_hz, frf.h_m_per_n, settings);
    QCOMPARE(fit.modes.size(), std::size_t{2});
    QCOMPARE_LE(relativeError(fit.modes[0].natural_frequency_hz, 350.0), 0.005);
    QCOMPARE_LE(relativeError(fit.modes[1].natural_frequency_hz, 1650.0), 0.005);
  }

  void withoutRefinementLsfdOnly() {
    const ModalAxis truth{{900.0, 0.02, 2e7}};
    const auto frf = test::syntheticFrf(truth, 0.0, 2000.0, 2001);
    auto settings = test::bandSettings(100.0, 2000.0);
    settings.refine = false;
    const auto fit = fitModes(frf.frequency_hz, frf.h_m_per_n, settings);
    QCOMPARE(fit.method, std::string("LSCF + LSFD"));
    QCOMPARE(fit.modes.size(), std::size_t{1});
    const Errors e = maxErrors(fit.modes, truth);
    QCOMPARE_LE(e.frequency, 1e-3);
    QCOMPARE_LE(e.damping, 0.02);
    QCOMPARE_LE(e.stiffness, 0.02);
  }

  void peakPicking() {
    const ModalAxis truth{{900.0, 0.02, 2e7}};
    const auto frf = test::syntheticFrf(truth, 0.0, 2000.0, 4001, 0.02, 3);
    auto settings = test::bandSettings(300.0, 1500.0);
    settings.method = ModalFitSettings::Method::Peak;
    const auto fit = fitModes(frf.frequency_hz, frf.h_m_per_n, settings);
    QCOMPARE(fit.modes.size(), std::size_t{1});
    const Errors e = maxErrors(fit.modes, truth);
    qInfo("peak picking errors: frequency %.2e, damping %.2e, stiffness %.2e; fit error %.2f %%", e.frequency,
          e.damping, e.stiffness, fit.fit_error_pct);
    QCOMPARE_LE(e.frequency, 0.005);
    QCOMPARE_LE(e.damping, 0.10);
    QCOMPARE_LE(e.stiffness, 0.10);
    QVERIFY(fit.diagram.orders.empty());
    QCOMPARE_LE(fit.fit_error_pct, 20.0);
  }

  void progressAndCancel() {
    const auto frf = test::syntheticFrf({{900.0, 0.02, 2e7}}, 0.0, 2000.0, 2001);
    std::vector<double> reported;
    const JobControl job{nullptr, [&](double x) { reported.push_back(x); }};
    fitModes(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(100.0, 2000.0), job);
    QVERIFY(reported.size() >= 19);
    QVERIFY(std::is_sorted(reported.begin(), reported.end()));
    QCOMPARE(reported.back(), 1.0);
    std::atomic<bool> cancel{true};
    QVERIFY_THROWS_EXCEPTION(
        Cancelled, fitModes(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(100.0, 2000.0), {&cancel, {}}));
  }

  void chosenStablePolesRecoverModes_data() {
    QTest::addColumn<double>("noise");
    QTest::addColumn<bool>("refine");
    QTest::newRow("exact, refined") << 0.0 << true;
    QTest::newRow("2 %, refined") << 0.02 << true;
    QTest::newRow("2 %, LSFD only") << 0.02 << false;
  }
  void chosenStablePolesRecoverModes() {
    QFETCH(double, noise);
    QFETCH(bool, refine);
    const ModalAxis truth{{600.0, 0.03, 1.5e7}, {1400.0, 0.02, 3e7}};
    const auto frf = test::syntheticFrf(truth, 0.0, 2000.0, 2001, noise, 7);
    auto settings = test::bandSettings(100.0, 2000.0);
    const auto diagram = fitModes(frf.frequency_hz, frf.h_m_per_n, settings).diagram;
    const auto poles = pickStablePoles(diagram, {600.0, 1400.0});
    QCOMPARE(poles.size(), std::size_t{2});
    settings.refine = refine;
    settings.modes = 7;  // ignored, as are max_modes and the method
    settings.method = ModalFitSettings::Method::Peak;
    const auto fit = fitModesAtPoles(frf.frequency_hz, frf.h_m_per_n, settings, poles);
    QCOMPARE(fit.modes.size(), std::size_t{2});
    const Errors e = maxErrors(fit.modes, truth);
    QCOMPARE_LE(e.frequency, 0.005);
    QCOMPARE_LE(e.damping, 0.10);
    QCOMPARE_LE(e.stiffness, 0.05);
    QCOMPARE(fit.method, std::string(refine ? "chosen poles + LSFD + NLLS" : "chosen poles + LSFD"));
    QVERIFY(fit.diagram.orders.empty());
    QCOMPARE(fit.fitted.size(), fit.band_frequency_hz.size());
    QCOMPARE_LE(fit.fit_error_pct, noise > 0 ? 1.1 * 100 * noise : 1e-6);
  }

  void chosenPolesRejected_data() {
    QTest::addColumn<std::vector<std::complex<double>>>("poles");
    QTest::addColumn<QString>("message");
    const auto at = [](double f_hz, double zeta) { return poleOf(Mode{f_hz, zeta, 1e7}); };
    QTest::newRow("empty") << std::vector<std::complex<double>>{} << "poles: none given";
    QTest::newRow("above the band") << std::vector{at(900.0, 0.02), at(2500.0, 0.02)} << "pole 2 = ";
    QTest::newRow("below the band") << std::vector{at(50.0, 0.02)} << "(50 Hz)";
    QTest::newRow("lower half-plane") << std::vector{std::conj(at(900.0, 0.02))} << "upper half-plane";
  }
  void chosenPolesRejected() {
    QFETCH(std::vector<std::complex<double>>, poles);
    QFETCH(QString, message);
    const auto frf = test::syntheticFrf({{900.0, 0.02, 2e7}}, 0.0, 2000.0, 2001);
    try {
      fitModesAtPoles(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(100.0, 2000.0), poles);
      QFAIL("no exception");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
  }

  void badSettingsThrow_data() {
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("modes");
    QTest::addColumn<QString>("field");
    QTest::newRow("band outside data") << 100.0 << 3000.0 << 1 << "to_hz = 3000";
    QTest::newRow("from >= to") << 900.0 << 800.0 << 1 << "to_hz = 800";
    QTest::newRow("too few points") << 900.5 << 903.5 << 1 << "points in band = 3";
    QTest::newRow("modes < 1") << 100.0 << 2000.0 << 0 << "modes = 0";
  }
  void badSettingsThrow() {
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, modes);
    QFETCH(QString, field);
    const auto frf = test::syntheticFrf({{900.0, 0.02, 2e7}}, 0.0, 2000.0, 2001);
    auto settings = test::bandSettings(from, to);
    settings.modes = modes;
    try {
      fitModes(frf.frequency_hz, frf.h_m_per_n, settings);
      QFAIL("no exception");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(field), e.what());
    }
  }
};

MX_REGISTER_TEST(TestModalFit)
#include "test_modal_fit.moc"
