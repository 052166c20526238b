// Mobility and accelerance to receptance: against the modal receptance they were made from, and the
// f = 0 points that cannot be converted.
#include "frf/receptance_conversion.h"
#include "support/frf_quantity_metatype.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;

class TestReceptanceConversion : public QObject {
  Q_OBJECT
 private slots:
  void matchesTheModalReceptance_data() {
    QTest::addColumn<FrfQuantity>("quantity");
    QTest::newRow("receptance") << FrfQuantity::Receptance;
    QTest::newRow("mobility") << FrfQuantity::Mobility;
    QTest::newRow("accelerance") << FrfQuantity::Accelerance;
  }
  void matchesTheModalReceptance() {
    QFETCH(FrfQuantity, quantity);
    const auto f = test::evenFrequencies(1.0, 7.5, 400);
    const auto r = toReceptance(test::modalFrf(test::kTwoModes, quantity, f, FrfDirection::Y));
    QCOMPARE(r.direction, FrfDirection::Y);
    QCOMPARE(r.reference_direction, FrfDirection::Y);
    QCOMPARE(r.frequency_hz, f);
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto want = receptance(test::kTwoModes, {0.0, 2.0 * std::numbers::pi * f[i]});
      QCOMPARE_LE(std::abs(r.h_m_per_n[i] - want), 1e-12 * std::abs(want));
    }
  }

  // Hand values: mobility 1 (m/s)/N at 1/(2 pi) Hz is -i m/N; accelerance 1 at the same frequency is -1.
  void handValues() {
    FrfDataset d;
    d.frequency_hz = {1.0 / (2.0 * std::numbers::pi)};
    d.values = {{1.0, 0.0}};
    d.quantity = FrfQuantity::Mobility;
    QCOMPARE_LE(std::abs(toReceptance(d).h_m_per_n.at(0) - std::complex<double>(0.0, -1.0)), 1e-15);
    d.quantity = FrfQuantity::Accelerance;
    QCOMPARE_LE(std::abs(toReceptance(d).h_m_per_n.at(0) - std::complex<double>(-1.0, 0.0)), 1e-15);
  }

  void zeroFrequency_data() {
    QTest::addColumn<FrfQuantity>("quantity");
    QTest::addColumn<int>("points");
    QTest::newRow("receptance keeps f = 0") << FrfQuantity::Receptance << 3;
    QTest::newRow("mobility drops f = 0") << FrfQuantity::Mobility << 2;
    QTest::newRow("accelerance drops f = 0") << FrfQuantity::Accelerance << 2;
  }
  void zeroFrequency() {
    QFETCH(FrfQuantity, quantity);
    QFETCH(int, points);
    const auto r = toReceptance(test::modalFrf(test::kTwoModes, quantity, {0.0, 10.0, 20.0}));
    QCOMPARE(static_cast<int>(r.frequency_hz.size()), points);
    QCOMPARE(static_cast<int>(r.h_m_per_n.size()), points);
    QCOMPARE(r.frequency_hz.front(), points == 3 ? 0.0 : 10.0);
    for (const auto& h : r.h_m_per_n) QVERIFY(std::isfinite(h.real()) && std::isfinite(h.imag()));
    if (points == 3) QCOMPARE_LE(std::abs(r.h_m_per_n[0].real() - (1 / 5e6 + 1 / 2e7)), 1e-18);  // G(0) = sum 1/k
  }

  // fromReceptance is the inverse of toReceptance (f > 0), to rounding.
  void fromReceptanceRoundTrips_data() { matchesTheModalReceptance_data(); }
  void fromReceptanceRoundTrips() {
    QFETCH(FrfQuantity, quantity);
    const auto f = test::evenFrequencies(2.0, 11.0, 300);
    const Receptance r = toReceptance(test::modalFrf(test::kTwoModes, FrfQuantity::Receptance, f, FrfDirection::Y));
    const FrfDataset d = fromReceptance(r, quantity, "T9 y");
    QCOMPARE(d.quantity, quantity);
    QCOMPARE(d.response_direction, FrfDirection::Y);
    QCOMPARE(d.name, std::string("T9 y"));
    const Receptance back = toReceptance(d);
    QCOMPARE(back.frequency_hz, f);
    for (std::size_t i = 0; i < f.size(); ++i)
      QCOMPARE_LE(std::abs(back.h_m_per_n[i] - r.h_m_per_n[i]), 1e-13 * std::abs(r.h_m_per_n[i]));
  }

  void crossFrfKeepsBothDirections() {
    auto d = test::modalFrf(test::kTwoModes, FrfQuantity::Receptance, {10.0});
    d.response_direction = FrfDirection::X;
    d.reference_direction = FrfDirection::Z;
    const auto r = toReceptance(d);
    QCOMPARE(r.direction, FrfDirection::X);
    QCOMPARE(r.reference_direction, FrfDirection::Z);
  }
};

MX_REGISTER_TEST(TestReceptanceConversion)
#include "test_receptance_conversion.moc"
