// ModalDynamics: the modal equations of seed eq. 1 (several modes per axis, empty axis rigid).
#include <cmath>
#include <numbers>

#include "simulation/modal_dynamics.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestModalDynamics : public QObject {
  Q_OBJECT
 private slots:
  void derivativeIsTheModalEquation() {
    MillingSetup s = test::rubioR1();
    s.modes_x.push_back({1500.0, 0.02, 2e7});
    const ModalDynamics d(s);
    QCOMPARE(d.modeCount(), 3);
    QCOMPARE(d.xModeCount(), 2);
    QCOMPARE(d.highestFrequencyHz(), 1500.0);
    const double state[6] = {1e-6, 2e-6, -3e-6, 0.01, -0.02, 0.03};
    double out[6];
    const double fx = 120.0, fy = -40.0;
    d.derivative(state, fx, fy, out);
    const Mode modes[3] = {s.modes_x[0], s.modes_x[1], s.modes_y[0]};
    for (int r = 0; r < 3; ++r) {
      const double w = 2.0 * std::numbers::pi * modes[r].natural_frequency_hz;
      const double f = r < 2 ? fx : fy;
      // q'' = (w^2 / k) F - 2 zeta w q' - w^2 q
      const double expected =
          w * w / modes[r].stiffness_n_per_m * f - 2.0 * modes[r].damping_ratio * w * state[3 + r] - w * w * state[r];
      QCOMPARE(out[r], state[3 + r]);
      QVERIFY(std::abs(out[3 + r] - expected) <= 1e-12 * std::abs(expected));
    }
    double x, y, vx, vy;
    d.axes(state, x, y);
    d.axisVelocities(state, vx, vy);
    QCOMPARE(x, 3e-6);
    QCOMPARE(y, -3e-6);
    QCOMPARE(vx, -0.01);
    QCOMPARE(vy, 0.03);
  }

  // The initial displacement is split like a static deflection: q_r = x0 (1/k_r) / sum(1/k).
  void initialStateIsAStaticDeflection() {
    MillingSetup s = test::rubioR1();
    s.modes_x.push_back({1500.0, 0.02, 3 * 5.59e6});
    const ModalDynamics d(s);
    const std::vector<double> q = d.initialState(4e-6, -1e-6);
    QCOMPARE(q.size(), std::size_t{6});
    QCOMPARE(q[0], 3e-6);
    QCOMPARE(q[1], 1e-6);
    QCOMPARE(q[2], -1e-6);
    for (int i = 3; i < 6; ++i) QCOMPARE(q[static_cast<std::size_t>(i)], 0.0);
  }

  void rigidToolHasNoState() {
    MillingSetup s = test::rubioR1();
    s.modes_x.clear();
    s.modes_y.clear();
    const ModalDynamics d(s);
    QCOMPARE(d.stateSize(), 0);
    QVERIFY(d.initialState(0.0, 0.0).empty());
  }
};

MX_REGISTER_TEST(TestModalDynamics)
#include "test_modal_dynamics.moc"
