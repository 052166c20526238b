// FRFs of known modes (modal_frf.h): the single-mode values at resonance, and the seeded relative noise.
#include "frf/modal_frf.h"
#include "support/frf_quantity_metatype.h"
#include "test_registry.h"

using namespace mx;
using cplx = std::complex<double>;

class TestModalFrf : public QObject {
  Q_OBJECT
 private slots:
  // At f_n a single mode has G = -i / (2 zeta k); mobility and accelerance add factors i w_n and -w_n^2.
  void resonanceValues_data() {
    QTest::addColumn<FrfQuantity>("quantity");
    QTest::addColumn<cplx>("factor");  // of 1 / (2 zeta k)
    const double w = 2.0 * std::numbers::pi * 800.0;
    QTest::newRow("receptance") << FrfQuantity::Receptance << cplx(0.0, -1.0);
    QTest::newRow("mobility") << FrfQuantity::Mobility << cplx(w, 0.0);
    QTest::newRow("accelerance") << FrfQuantity::Accelerance << cplx(0.0, w * w);
  }
  void resonanceValues() {
    QFETCH(FrfQuantity, quantity);
    QFETCH(cplx, factor);
    const ModalAxis mode{{800.0, 0.02, 4e7}};
    const FrfDataset d = modalFrfDataset(mode, quantity, {800.0}, FrfDirection::Y, "T9 y");
    QCOMPARE(d.quantity, quantity);
    QCOMPARE(d.response_direction, FrfDirection::Y);
    QCOMPARE(d.reference_direction, FrfDirection::Y);
    QCOMPARE(d.name, std::string("T9 y"));
    const cplx want = factor / (2.0 * 0.02 * 4e7);
    QCOMPARE_LE(std::abs(d.values.at(0) - want), 1e-12 * std::abs(want));
  }

  // The relative deviation has RMS `noise` (within 3 % over 20 000 lines) and zero mean.
  void noiseHasTheStatedRms() {
    std::vector<cplx> values(20000, cplx(2e-7, -1e-7));
    addRelativeNoise(values, 0.02, 7);
    double sum_sq = 0.0;
    cplx sum = 0.0;
    for (const cplx& v : values) {
      const cplx e = v / cplx(2e-7, -1e-7) - 1.0;
      sum_sq += std::norm(e);
      sum += e;
    }
    const double n = static_cast<double>(values.size());
    QCOMPARE_LE(std::abs(std::sqrt(sum_sq / n) - 0.02), 0.03 * 0.02);
    QCOMPARE_LE(std::abs(sum / n), 4.0 * 0.02 / std::sqrt(n));
  }

  void noiseIsSeeded() {
    std::vector<cplx> a(50, cplx(1.0, 0.0)), b = a, c = a, zero = a;
    addRelativeNoise(a, 0.05, 3);
    addRelativeNoise(b, 0.05, 3);
    addRelativeNoise(c, 0.05, 4);
    addRelativeNoise(zero, 0.0, 3);
    QCOMPARE(a, b);
    QVERIFY(a != c);
    QCOMPARE(zero, std::vector<cplx>(50, cplx(1.0, 0.0)));
  }
};

MX_REGISTER_TEST(TestModalFrf)
#include "test_modal_frf.moc"
