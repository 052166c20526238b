// A measured receptance FRF: linear interpolation between lines, zero outside, and its validation.
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "core/invalid_input.h"
#include "model/measured_receptance.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;
using cplx = std::complex<double>;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
using mx::test::kNaN;

MeasuredAxis threeLines() {
  return {{0.0, 100.0, 250.0}, {{1e-6, 0.0}, {2e-6, -4e-6}, {-1e-6, 8e-6}}};
}
}  // namespace

class TestMeasuredReceptance : public QObject {
  Q_OBJECT
 private slots:
  void exactAtTheLines() {
    const MeasuredAxis a = threeLines();
    for (std::size_t i = 0; i < a.frequency_hz.size(); ++i)
      QCOMPARE_LE(std::abs(a.at(kTwoPi * a.frequency_hz[i]) - a.h_m_per_n[i]), 1e-12 * std::abs(a.h_m_per_n[i]));
  }

  // Real and imaginary parts linear in f: H(100 + t 150) = H_1 + t (H_2 - H_1).
  void linearBetweenLines_data() {
    QTest::addColumn<double>("t");
    QTest::newRow("quarter") << 0.25;
    QTest::newRow("half") << 0.5;
    QTest::newRow("0.9") << 0.9;
  }
  void linearBetweenLines() {
    QFETCH(double, t);
    const MeasuredAxis a = threeLines();
    const cplx expected = a.h_m_per_n[1] + t * (a.h_m_per_n[2] - a.h_m_per_n[1]);
    QCOMPARE_LE(std::abs(a.at(kTwoPi * (100.0 + 150.0 * t)) - expected), 1e-12 * std::abs(expected));
    const cplx first = a.at(kTwoPi * 50.0);  // between 0 and 100 Hz
    QCOMPARE_LE(std::abs(first - cplx{1.5e-6, -2e-6}), 1e-18);
  }

  void zeroOutsideTheMeasuredBand_data() {
    QTest::addColumn<double>("f_hz");
    QTest::newRow("above") << 250.001;
    QTest::newRow("far above") << 1e5;
    QTest::newRow("negative") << -1.0;
  }
  void zeroOutsideTheMeasuredBand() {
    QFETCH(double, f_hz);
    QCOMPARE(threeLines().at(kTwoPi * f_hz), cplx(0.0, 0.0));
    const MeasuredAxis from_10{{10.0, 20.0}, {{1.0, 1.0}, {2.0, 2.0}}};
    QCOMPARE(from_10.at(kTwoPi * 9.99), cplx(0.0, 0.0));  // below the first line
  }

  void validAxisPasses() {
    threeLines().validate("frf_x");
    const MeasuredAxis no_zero{{5.0, 6.0}, {{1.0, 0.0}, {0.0, 1.0}}};
    no_zero.validate("frf_x");
  }

  // Each row breaks one rule; the message names the axis, the index or value, and the rule.
  void validateNamesFieldIndexAndRule_data() {
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("expected");
    QTest::newRow("sizes") << 0 << "frf_x: frequency_hz has 3 lines and h_m_per_n 2: the sizes must be equal";
    QTest::newRow("one line") << 1 << "frf_x: 1 lines: a measured FRF needs >= 2 lines";
    QTest::newRow("negative") << 2 << "frf_x: frequency_hz[0] = -5 Hz: must be >= 0";
    QTest::newRow("repeated") << 3
                              << "frf_x: frequency_hz[2] = 100 Hz: must be strictly increasing (frequency_hz[1] = "
                                 "100 Hz)";
    QTest::newRow("decreasing") << 4
                                << "frf_x: frequency_hz[1] = 50 Hz: must be strictly increasing (frequency_hz[0] = "
                                   "60 Hz)";
    QTest::newRow("nan frequency") << 5 << "frf_x: frequency_hz[1] = nan Hz: must be finite";
    QTest::newRow("inf frequency") << 6 << "frf_x: frequency_hz[2] = inf Hz: must be finite";
    QTest::newRow("nan h") << 7 << "frf_x: h_m_per_n[1] = (nan, 0) m/N: must be finite";
    QTest::newRow("inf h") << 8 << "frf_x: h_m_per_n[0] = (0, -inf) m/N: must be finite";
  }
  void validateNamesFieldIndexAndRule() {
    QFETCH(int, row);
    QFETCH(QString, expected);
    const double inf = std::numeric_limits<double>::infinity();
    MeasuredAxis a = threeLines();
    switch (row) {
      case 0:
        a.h_m_per_n.pop_back();
        break;
      case 1:
        a = {{10.0}, {{1.0, 0.0}}};
        break;
      case 2:
        a.frequency_hz[0] = -5.0;
        break;
      case 3:
        a.frequency_hz[2] = 100.0;
        break;
      case 4:
        a.frequency_hz = {60.0, 50.0, 250.0};
        break;
      case 5:
        a.frequency_hz[1] = kNaN;
        break;
      case 6:
        a.frequency_hz[2] = inf;
        break;
      case 7:
        a.h_m_per_n[1] = {kNaN, 0.0};
        break;
      case 8:
        a.h_m_per_n[0] = {0.0, -inf};
        break;
      default:
        QFAIL("unknown row");
    }
    try {
      a.validate("frf_x");
      QFAIL("validate accepted an invalid FRF");
    } catch (const InvalidInput& e) {
      QCOMPARE(QString::fromUtf8(e.what()), expected);
    }
  }
};

MX_REGISTER_TEST(TestMeasuredReceptance)
#include "test_measured_receptance.moc"
