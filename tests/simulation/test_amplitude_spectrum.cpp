// AmplitudeSpectrum: FFTW r2c, mean removed, Hann window, amplitude-calibrated single-sided spectrum
// and the peak search used for the chatter frequency.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "simulation/amplitude_spectrum.h"
#include "test_registry.h"

using namespace mx;

namespace {
std::vector<double> signal(std::size_t n, double rate, double mean,
                           const std::vector<std::pair<double, double>>& tones) {
  std::vector<double> v(n, mean);
  for (std::size_t i = 0; i < n; ++i)
    for (auto [f, a] : tones) v[i] += a * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / rate);
  return v;
}
}  // namespace

class TestAmplitudeSpectrum : public QObject {
  Q_OBJECT
 private slots:
  void binCentredToneReadsItsAmplitude_data() {
    QTest::addColumn<int>("n");
    QTest::addColumn<double>("bin");
    QTest::addColumn<double>("amplitude");
    QTest::newRow("even n") << 4096 << 100.0 << 3.5;
    QTest::newRow("odd n") << 5521 << 37.0 << 0.25;
    QTest::newRow("low bin") << 1000 << 3.0 << 10.0;
  }
  void binCentredToneReadsItsAmplitude() {
    QFETCH(int, n);
    QFETCH(double, bin);
    QFETCH(double, amplitude);
    const double rate = 10000.0;
    const double f = bin * rate / n;
    const AmplitudeSpectrum s(signal(static_cast<std::size_t>(n), rate, 50.0, {{f, amplitude}}), rate);
    QCOMPARE(s.binHz(), rate / n);
    QCOMPARE(s.bins(), static_cast<std::size_t>(n / 2 + 1));
    QVERIFY(std::abs(s.amplitudeNear(f) - amplitude) < 1e-9 * amplitude);
    QVERIFY(s.amplitude()[0] < 1e-9 * amplitude);  // the mean is removed
    // Hann leakage: only the two neighbouring bins, each at half the amplitude.
    const auto k = static_cast<std::size_t>(bin);
    QVERIFY(std::abs(s.amplitude()[k + 1] - 0.5 * amplitude) < 1e-9 * amplitude);
    QVERIFY(s.amplitude()[k + 3] < 1e-9 * amplitude);
  }

  void peakSearchSkipsExcludedBandsAndInterpolates() {
    const double rate = 20000.0;
    const std::size_t n = 8000;  // 2.5 Hz bins
    // Strong "tooth-passing" tones at 300 and 600 Hz, a weaker off-bin tone at 651.3 Hz.
    const AmplitudeSpectrum s(signal(n, rate, 0.0, {{300.0, 5.0}, {600.0, 2.0}, {651.3, 0.7}}), rate);
    const auto any = s.largestPeak([](double) { return false; });
    QVERIFY(any);
    QVERIFY(std::abs(any->frequency_hz - 300.0) < 1e-6);
    auto harmonic = [](double f) {
      const double h = std::round(f / 300.0);
      return std::abs(f - 300.0 * h) <= 10.0;
    };
    const auto chatter = s.largestPeak(harmonic);
    QVERIFY(chatter);
    QVERIFY2(std::abs(chatter->frequency_hz - 651.3) < 0.1, qPrintable(QString::number(chatter->frequency_hz)));
    QVERIFY(chatter->amplitude > 0.5 && chatter->amplitude < 0.7);  // scalloping of an off-bin tone
    QVERIFY(!s.largestPeak([](double) { return true; }));
  }

  void vectorSumCombinesComponents() {
    const double rate = 1000.0;
    const AmplitudeSpectrum a(signal(500, rate, 0.0, {{100.0, 3.0}}), rate);
    const AmplitudeSpectrum b(signal(500, rate, 0.0, {{100.0, 4.0}}), rate);
    QVERIFY(std::abs(AmplitudeSpectrum::vectorSum(a, b).amplitudeNear(100.0) - 5.0) < 1e-9);
    const AmplitudeSpectrum c(signal(400, rate, 0.0, {{100.0, 4.0}}), rate);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AmplitudeSpectrum::vectorSum(a, c));
  }

  void rejectsInvalidInput() {
    const std::vector<double> three{1.0, 2.0, 3.0}, many(16, 1.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AmplitudeSpectrum(three, 100.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AmplitudeSpectrum(many, 0.0));
  }
};

MX_REGISTER_TEST(TestAmplitudeSpectrum)
#include "test_amplitude_spectrum.moc"
