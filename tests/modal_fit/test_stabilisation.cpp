// Stability flags between orders and the stable-pole clusters (stabilisation.h).
#include <numbers>

#include "modal_fit/modal_pole.h"
#include "modal_fit/stabilisation.h"
#include "test_registry.h"

using namespace mx;

namespace {

std::complex<double> pole(double f, double zeta) {
  return poleOf(Mode{f, zeta, 1e7});
}

}  // namespace

class TestStabilisation : public QObject {
  Q_OBJECT
 private slots:
  void physicalPolesOnly() {
    const std::vector<std::complex<double>> lambdas{pole(500, 0.02),
                                                    std::conj(pole(600, 0.02)),
                                                    -std::conj(pole(700, 0.02)),
                                                    pole(50, 0.02),
                                                    pole(800, 0.5),
                                                    {-100.0, 0.0},
                                                    pole(400, 0.01)};
    const auto poles = physicalPoles(lambdas, 100.0, 1000.0, {});
    QCOMPARE(poles.size(), std::size_t{2});  // 400 and 500 Hz, sorted
    QCOMPARE_LE(std::abs(poles[0].frequency_hz - 400.0), 1e-9);
    QCOMPARE_LE(std::abs(poles[1].damping_ratio - 0.02), 1e-12);
  }

  void flags_data() {
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<int>("stability");
    QTest::newRow("same") << 500.0 << 0.02 << int(PoleStability::Stable);
    QTest::newRow("0.9 % f, 4.9 % zeta") << 504.5 << 0.02098 << int(PoleStability::Stable);
    QTest::newRow("0.9 % f, 6 % zeta") << 504.5 << 0.0212 << int(PoleStability::FrequencyStable);
    QTest::newRow("1.1 % f") << 505.5 << 0.02 << int(PoleStability::Unstable);
  }
  void flags() {
    QFETCH(double, f);
    QFETCH(double, zeta);
    QFETCH(int, stability);
    const StabilityCriteria criteria;
    auto previous = physicalPoles({pole(500.0, 0.02), pole(900.0, 0.03)}, 100, 1000, criteria);
    previous[0].stable_orders = 3;
    auto current = physicalPoles({pole(f, zeta)}, 100, 1000, criteria);
    classifyPoles(current, previous, criteria);
    QCOMPARE(int(current[0].stability), stability);
    QCOMPARE(current[0].stable_orders, stability == int(PoleStability::Stable) ? 4 : 1);
    QCOMPARE(current[0].frequency_stable_orders, stability == int(PoleStability::Unstable) ? 1 : 2);
  }

  void clustersOfStablePoles() {
    const StabilityCriteria criteria;
    StabilisationDiagram diagram;
    for (int order = 2; order <= 6; ++order) {
      const double scattered = order % 2 == 0 ? 0.02 : 0.022;  // 10 % jumps: frequency-stable only
      auto poles = physicalPoles(
          {pole(500.0 + order * 0.1, 0.02), pole(525.0, 0.02), pole(700.0, scattered), pole(900.0 - order, 0.1)}, 100,
          1000, criteria);
      if (!diagram.orders.empty()) classifyPoles(poles, diagram.orders.back().poles, criteria);
      diagram.orders.push_back({order, poles});
    }
    // 500.x and 525 Hz (5 % apart) stay two clusters; 700 Hz is frequency-stable over 5 orders (> 3);
    // 900 - order moves by ~0.11 % per order (stable).
    const auto& last = diagram.orders.back().poles;
    QCOMPARE(int(last[2].stability), int(PoleStability::FrequencyStable));
    QCOMPARE(last[2].stable_orders, 1);
    QCOMPARE(last[2].frequency_stable_orders, 5);
    QCOMPARE(last[0].frequency_stable_orders, 5);
    const auto stable = stablePoles(diagram, 3, criteria);
    QCOMPARE(stable.size(), std::size_t{4});
    QCOMPARE_LE(std::abs(poleFrequencyHz(stable[0]) - 500.5), 1e-9);  // median of orders 4..6
    QCOMPARE_LE(std::abs(poleFrequencyHz(stable[1]) - 525.0), 1e-9);
    QCOMPARE_LE(std::abs(poleFrequencyHz(stable[2]) - 700.0), 1e-9);
    QCOMPARE_LE(std::abs(poleDampingRatio(stable[2]) - 0.021), 1e-9);  // median of 0.02, 0.022 (orders 5, 6)
    QCOMPARE_LE(std::abs(poleFrequencyHz(stable[3]) - 895.0), 1e-9);
    QCOMPARE(stablePoles(diagram, 6, criteria).size(), std::size_t{0});
  }
};

MX_REGISTER_TEST(TestStabilisation)
#include "test_stabilisation.moc"
