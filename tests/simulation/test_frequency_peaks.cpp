// Rule 17 peak identification: a synthetic spectrum with a tooth-passing harmonic, a spindle (run-out)
// line and a non-harmonic chatter line, computed with the engine's own amplitude spectrum, is read
// back with the right frequencies (within one bin), kinds and harmonic numbers.
#include <cmath>
#include <numbers>

#include "core/invalid_input.h"
#include "simulation/amplitude_spectrum.h"
#include "simulation/frequency_peaks.h"
#include "test_registry.h"

using namespace mx;

class TestFrequencyPeaks : public QObject {
  Q_OBJECT
 private slots:
  void identifiesSyntheticLines_data() {
    QTest::addColumn<double>("spindle_hz");
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("chatter_hz");
    QTest::newRow("4000 rpm, 3 teeth, 613 Hz") << 4000.0 / 60.0 << 3 << 613.0;
    QTest::newRow("10000 rpm, 2 teeth, 1270 Hz") << 10000.0 / 60.0 << 2 << 1270.0;
  }
  void identifiesSyntheticLines() {
    QFETCH(double, spindle_hz);
    QFETCH(int, teeth);
    QFETCH(double, chatter_hz);
    const double fs = 20000.0;
    const std::size_t n = 1 << 14;
    std::vector<double> x(n);
    const double tooth = spindle_hz * teeth, pi2 = 2.0 * std::numbers::pi;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / fs;
      x[i] = 100.0 * std::sin(pi2 * tooth * t) + 30.0 * std::sin(pi2 * 2.0 * tooth * t) +
             10.0 * std::sin(pi2 * spindle_hz * t) + 50.0 * std::sin(pi2 * chatter_hz * t);
    }
    const AmplitudeSpectrum s(x, fs);
    std::vector<double> f(s.bins());
    for (std::size_t k = 0; k < f.size(); ++k) f[k] = s.frequencyOfBin(k);
    const auto peaks = identifyPeaks(f, s.amplitude(), spindle_hz, teeth);
    QVERIFY(peaks.size() >= 4);
    const double bin = s.binHz();
    QCOMPARE(peaks[0].kind, PeakKind::ToothPassing);
    QCOMPARE(peaks[0].harmonic, 1);
    QCOMPARE_LE(std::abs(peaks[0].frequency_hz - tooth), bin);
    QCOMPARE(peaks[1].kind, PeakKind::NonHarmonic);
    QCOMPARE_LE(std::abs(peaks[1].frequency_hz - chatter_hz), bin);
    QCOMPARE(peaks[2].kind, PeakKind::ToothPassing);
    QCOMPARE(peaks[2].harmonic, 2);
    QCOMPARE(peaks[3].kind, PeakKind::Spindle);
    QCOMPARE(peaks[3].harmonic, 1);
    QCOMPARE_LE(std::abs(peaks[3].amplitude / peaks[0].amplitude - 0.1), 0.03);  // Hann scalloping
  }
  void invalidInputs() {
    const std::vector<double> f{0, 1, 2}, a{0, 1, 0};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, identifyPeaks(f, a, 0.0, 2));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, identifyPeaks(f, a, 10.0, 0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, identifyPeaks(f, std::vector<double>{0, 1}, 10.0, 2));
    QVERIFY(identifyPeaks(std::vector<double>{}, std::vector<double>{}, 10.0, 2).empty());
  }
};

MX_REGISTER_TEST(TestFrequencyPeaks)
#include "test_frequency_peaks.moc"
