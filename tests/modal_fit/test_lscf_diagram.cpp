// The LSCF stabilisation diagram on exact data: the true poles are stable from the order after their
// first appearance (within 1 % in frequency and 5 % in damping of the truth) on (lscf_diagram.h); progress and
// cancellation.
#include <atomic>

#include "core/cancellation.h"
#include "modal_fit/frf_band.h"
#include "modal_fit/lscf_diagram.h"
#include "support/modal_axis_metatype.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

namespace {

const DiagramPole* poleNear(const DiagramOrder& order, const Mode& mode) {
  for (const auto& pole : order.poles)
    if (relativeError(pole.frequency_hz, mode.natural_frequency_hz) < 0.01 &&
        relativeError(pole.damping_ratio, mode.damping_ratio) < 0.05)
      return &pole;
  return nullptr;
}

}  // namespace

class TestLscfDiagram : public QObject {
  Q_OBJECT
 private slots:
  void truePolesStableOnExactData_data() {
    QTest::addColumn<ModalAxis>("truth");
    QTest::newRow("one mode") << ModalAxis{{900.0, 0.02, 2e7}};
    QTest::newRow("three modes") << ModalAxis{{400.0, 0.02, 1e7}, {1000.0, 0.03, 2e7}, {1600.0, 0.015, 4e7}};
  }
  void truePolesStableOnExactData() {
    QFETCH(ModalAxis, truth);
    const auto frf = test::syntheticFrf(truth, 100.0, 2000.0, 1901);
    const auto diagram = lscfDiagram(selectBand(frf.frequency_hz, frf.h_m_per_n, 100.0, 2000.0), 20);
    QCOMPARE(diagram.orders.size(), std::size_t{19});
    QCOMPARE(diagram.orders.front().order, 2);
    for (const Mode& mode : truth) {
      std::size_t first = 0;
      while (first < diagram.orders.size() && !poleNear(diagram.orders[first], mode)) ++first;
      QVERIFY2(first + 1 < diagram.orders.size(), "the true pole appears");
      QCOMPARE_LE(diagram.orders[first].order, 2 * static_cast<int>(truth.size()) + 2);
      for (std::size_t i = first + 1; i < diagram.orders.size(); ++i) {
        const DiagramPole* pole = poleNear(diagram.orders[i], mode);
        QVERIFY(pole != nullptr);
        QCOMPARE(int(pole->stability), int(PoleStability::Stable));
        QCOMPARE_GE(pole->stable_orders, static_cast<int>(i - first) + 1);
      }
    }
  }

  void progressAndCancel() {
    const auto frf = test::syntheticFrf({{900.0, 0.02, 2e7}}, 100.0, 2000.0, 400);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 100.0, 2000.0);
    std::vector<double> reported;
    const JobControl job{nullptr, [&](double x) { reported.push_back(x); }};
    lscfDiagram(band, 10, {}, job);
    QCOMPARE(reported.size(), std::size_t{9});
    QCOMPARE(reported.back(), 1.0);
    QVERIFY(std::is_sorted(reported.begin(), reported.end()));
    std::atomic<bool> cancel{true};
    QVERIFY_THROWS_EXCEPTION(Cancelled, lscfDiagram(band, 10, {}, JobControl{&cancel, {}}));
  }
};

MX_REGISTER_TEST(TestLscfDiagram)
#include "test_lscf_diagram.moc"
