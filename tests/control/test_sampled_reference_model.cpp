// The reference model sampled at a changing period (Pareto paper, Rule 4): at a constant T it equals the discrete
// H_m,beta of frohDiscretize driven by the same inputs; at irregular periods (beta = 0, a step held by the ZOH)
// it lands on the continuous step response at every sampling instant; a change of wn keeps F_m and its slope.
#include <cmath>

#include "control/sampled_reference_model.h"
#include "test_registry.h"

using namespace mx;

namespace {

// y(k) of num/den (descending powers, den monic) for the input history u(0..k), zero initial conditions.
double discreteOutput(const DiscreteTransferFunction& h, const std::vector<double>& u, std::vector<double>& y) {
  const std::size_t n = h.den.size() - 1, delay = n - (h.num.size() - 1), k = u.size() - 1;
  double out = 0.0;
  for (std::size_t i = 1; i <= n && i <= k; ++i) out -= h.den[i] * y[k - i];
  for (std::size_t j = 0; j < h.num.size(); ++j)
    if (delay + j <= k) out += h.num[j] * u[k - delay - j];
  y.push_back(out);
  return out;
}

double stepResponse(double xi, double wn, double t) {
  const double wd = wn * std::sqrt(1.0 - xi * xi);
  return 1.0 - std::exp(-xi * wn * t) * (std::cos(wd * t) + xi / std::sqrt(1.0 - xi * xi) * std::sin(wd * t));
}

}  // namespace

class TestSampledReferenceModel : public QObject {
  Q_OBJECT
 private slots:
  void constantPeriodEqualsTheDiscreteModel_data() {
    QTest::addColumn<double>("beta");
    for (double b : {-0.3, 0.0, 0.3, 1.0}) QTest::newRow(qPrintable(QString("beta %1").arg(b))) << b;
  }
  void constantPeriodEqualsTheDiscreteModel() {
    QFETCH(double, beta);
    const double T = 60.0 / 715.0, wn = 2.5 / (4.0 * T);
    const DiscreteTransferFunction h = frohDiscretize(referenceModel(0.75, wn), T, beta);
    SampledReferenceModel m(0.75, wn, beta);
    std::vector<double> u, y;
    for (int k = 0; k < 40; ++k) {
      const double input = k < 20 ? 1200.0 : 600.0;  // a step up, then down
      u.push_back(input);
      const double expected = discreteOutput(h, u, y);
      QVERIFY2(std::abs(m.output() - expected) <= 1e-9 * 1200.0, qPrintable(QString::number(k)));
      m.advance(input, T, wn);
    }
  }

  void irregularPeriodsFollowTheContinuousResponse() {
    const double xi = 0.75, wn = 40.0;
    SampledReferenceModel m(xi, wn, 0.0);
    double t = 0.0;
    for (double T : {0.01, 0.04, 0.04, 0.01, 0.003, 0.04, 0.1, 0.01}) {
      QVERIFY(std::abs(m.output() - 600.0 * stepResponse(xi, wn, t)) <= 1e-9 * 600.0);
      m.advance(600.0, T, wn);
      t += T;
    }
    QVERIFY(std::abs(m.output() - 600.0 * stepResponse(xi, wn, t)) <= 1e-9 * 600.0);
  }

  // After a change of wn the output continues from the same value and slope: over a short period the change of
  // F_m is the old slope times the period to first order.
  void naturalFrequencyChangeKeepsValueAndSlope() {
    const double xi = 0.75, wn = 40.0, T = 0.01;
    SampledReferenceModel a(xi, wn, 0.0), b(xi, wn, 0.0);
    for (int k = 0; k < 3; ++k) {
      a.advance(600.0, T, wn);
      b.advance(600.0, T, wn);
    }
    const double y0 = a.output(), h = 1e-6;
    a.advance(600.0, h, wn);
    b.advance(600.0, h, 10.0);  // 4 times slower from now on
    QVERIFY(std::abs(a.output() - y0) > 1e-3);
    QVERIFY2(std::abs((b.output() - y0) - (a.output() - y0)) < 1e-3 * std::abs(a.output() - y0),
             qPrintable(QString::number(b.output() - a.output())));
  }
};

MX_REGISTER_TEST(TestSampledReferenceModel)
#include "test_sampled_reference_model.moc"
