// The seeded disturbance: reproducible, zero mean, the requested spread, held over its period.
#include <cmath>

#include "core/invalid_input.h"
#include "sdnrp/unmodelled_dynamics.h"
#include "test_registry.h"

using namespace mx;

class TestUnmodelledDynamics : public QObject {
  Q_OBJECT
 private slots:
  void statisticsAndHold() {
    UnmodelledDynamics d({true, 7, 3.0, 0.01});
    double sum = 0.0, sum2 = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const double t = k * 0.01;
      const double v = d.at(t);
      QCOMPARE(d.at(t + 0.004), v);  // held within the period
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    QVERIFY(std::abs(mean) < 4.0 * 3.0 / std::sqrt(n));
    QVERIFY(std::abs(sd - 3.0) < 0.1);
  }
  void seeded() {
    UnmodelledDynamics a({true, 11, 2.0, 0.01}), b({true, 11, 2.0, 0.01}), c({true, 12, 2.0, 0.01});
    bool differs = false;
    for (int k = 0; k < 100; ++k) {
      QCOMPARE(a.at(k * 0.01), b.at(k * 0.01));
      differs = differs || c.at(k * 0.01) != a.at(k * 0.01);
    }
    QVERIFY(differs);
    // the sequence does not depend on how often it is sampled
    UnmodelledDynamics coarse({true, 11, 2.0, 0.01}), fine({true, 11, 2.0, 0.01});
    for (int k = 0; k < 1000; ++k) (void)fine.at(k * 0.001);
    QCOMPARE(coarse.at(0.995), fine.at(0.995));
  }
  void disabled() {
    UnmodelledDynamics d({false, 1, 3.0, 0.01});
    QCOMPARE(d.at(0.5), 0.0);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, UnmodelledDynamics({true, 1, -1.0, 0.01}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, UnmodelledDynamics({true, 1, 1.0, 0.0}));
  }
};

MX_REGISTER_TEST(TestUnmodelledDynamics)
#include "test_unmodelled_dynamics.moc"
