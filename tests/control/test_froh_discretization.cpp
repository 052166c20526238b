// beta-FROH discretization (2006 paper, eq. 24-25): ZOH special case, exactness against CVODE under the
// FROH-shaped input, repeated time constants, pole locations exp(-T/tau).
#include <cmath>
#include <vector>

#include "control/force_plant.h"
#include "control/froh_discretization.h"
#include "core/invalid_input.h"
#include "simulation/cvode_integrator.h"
#include "test_registry.h"

using namespace mx;

namespace {

ForcePlant paperPlant() {
  return makeForcePlant(CuttingProcess{}, 2e-3);  // 2 mm, 715 rpm, 4 teeth, K_c = 1200 N/mm^2
}

StateSpace2 plantOf(double K, double tau_m, double tau_c) {
  ForcePlant p;
  p.gain_N_s_per_m = K;
  p.tau_m_s = tau_m;
  p.tau_c_s = tau_c;
  return p.stateSpace();
}

// y(k) of num/den from zero initial conditions.
std::vector<double> filter(const DiscreteTransferFunction& h, const std::vector<double>& u) {
  const std::size_t n = h.den.size() - 1, m = h.num.size() - 1, delay = n - m;
  std::vector<double> y(u.size(), 0.0);
  for (std::size_t k = 0; k < u.size(); ++k) {
    double v = 0.0;
    for (std::size_t i = 1; i <= n && i <= k; ++i) v -= h.den[i] * y[k - i];
    for (std::size_t j = 0; j <= m; ++j)
      if (k >= delay + j) v += h.num[j] * u[k - delay - j];
    y[k] = v;
  }
  return y;
}

double relDiff(const Poly& a, const Poly& b) {
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(b[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

}  // namespace

class TestFrohDiscretization : public QObject {
  Q_OBJECT
 private slots:
  void zohMatchesPartialFractions_data() {
    QTest::addColumn<double>("K");
    QTest::addColumn<double>("tau_m");
    QTest::addColumn<double>("tau_c");
    QTest::addColumn<double>("T");
    const ForcePlant p = paperPlant();
    QTest::newRow("paper plant, T/tau_m = 839") << p.gain_N_s_per_m << p.tau_m_s << p.tau_c_s << 60.0 / 715.0;
    QTest::newRow("slow drive, tau_m = T/5") << 1000.0 << 0.02 << 0.01 << 0.1;
    QTest::newRow("tau_c > tau_m") << 3.0 << 0.01 << 0.05 << 0.02;
  }
  void zohMatchesPartialFractions() {
    QFETCH(double, K);
    QFETCH(double, tau_m);
    QFETCH(double, tau_c);
    QFETCH(double, T);
    const DiscreteTransferFunction h = frohDiscretize(plantOf(K, tau_m, tau_c), T, 0.0);
    // Independent closed form for distinct poles: H = K[1 - c1 (z-1)/(z-e1) + c2 (z-1)/(z-e2)].
    const double e1 = std::exp(-T / tau_m), e2 = std::exp(-T / tau_c);
    const double c1 = tau_m / (tau_m - tau_c), c2 = tau_c / (tau_m - tau_c);
    const Poly den = polyMultiply({1.0, -e1}, {1.0, -e2});
    Poly num = polyAdd(polyAdd(den, polyScale(polyMultiply({1.0, -1.0}, {1.0, -e2}), -c1)),
                       polyScale(polyMultiply({1.0, -1.0}, {1.0, -e1}), c2));
    num = polyScale(num, K);
    QVERIFY(std::abs(num[0]) < 1e-12 * K);  // relative degree 1
    QCOMPARE(h.num.size(), std::size_t{2});
    QCOMPARE(h.den.size(), std::size_t{3});
    QVERIFY2(relDiff(h.num, {num[1], num[2]}) < 1e-12, qPrintable(QString::number(relDiff(h.num, {num[1], num[2]}))));
    QVERIFY(relDiff(h.den, den) < 1e-14);
  }

  void betaZeroIsZohExactly() {
    const StateSpace2 s = paperPlant().stateSpace();
    const double T = 60.0 / 715.0;
    const DiscreteTransferFunction a = frohDiscretize(s, T, 0.0), b = zohDiscretize(s, T);
    QCOMPARE(a.num, b.num);
    QCOMPARE(a.den, b.den);
    // and beta -> 0 converges to it (the extra z factor cancels): compare at a few points of the unit circle
    const DiscreteTransferFunction c = frohDiscretize(s, T, 1e-12);
    for (double w : {0.1, 1.0, 2.5}) {
      const std::complex<double> z = std::polar(1.0, w);
      const auto ha = polyEval(a.num, z) / polyEval(a.den, z), hc = polyEval(c.num, z) / polyEval(c.den, z);
      QVERIFY(std::abs(ha - hc) < 1e-9 * std::abs(ha));
    }
  }

  void polesAreExpMinusTOverTau() {
    const ForcePlant p = makeForcePlant(CuttingProcess{}, 3e-3);
    const double T = 60.0 / 715.0;
    for (double beta : {-0.3, 0.0, 1.0}) {
      const DiscreteTransferFunction h = frohDiscretize(p.stateSpace(), T, beta);
      const Roots poles = h.poles();
      QCOMPARE(static_cast<int>(poles.size()), beta == 0.0 ? 2 : 3);
      double nearest = 1.0;
      for (const auto& r : poles) nearest = std::min(nearest, std::abs(r - std::exp(-T / p.tau_c_s)));
      QVERIFY2(nearest < 1e-14,
               qPrintable(QString::number(nearest)));  // exp(-T/tau_c) = 3.4e-4: the printed exp(+T/tau) is a sign typo
      QVERIFY(std::abs(h.dcGain() - p.gain_N_s_per_m) < 1e-10 * p.gain_N_s_per_m);  // unit static gain of the hold
    }
  }

  void repeatedTimeConstants_data() {
    QTest::addColumn<double>("relative_gap");
    QTest::newRow("equal") << 0.0;
    QTest::newRow("1e-14") << 1e-14;
    QTest::newRow("1e-9") << 1e-9;
    QTest::newRow("1e-6") << 1e-6;
  }
  void repeatedTimeConstants() {
    QFETCH(double, relative_gap);
    const double T = 0.05, tau = 0.01;
    for (double beta : {-1.0, 0.0, 0.5}) {
      const DiscreteTransferFunction ref = frohDiscretize(plantOf(2.0, tau, tau), T, beta);
      const DiscreteTransferFunction h = frohDiscretize(plantOf(2.0, tau, tau * (1.0 + relative_gap)), T, beta);
      for (double c : h.num) QVERIFY(std::isfinite(c));
      QVERIFY(relDiff(h.num, ref.num) < 10.0 * relative_gap + 1e-13);
      QVERIFY(relDiff(h.den, ref.den) < 10.0 * relative_gap + 1e-13);
    }
  }

  // Integrate the continuous plant with CVODE under u(t) = u_k + beta (u_k - u_{k-1}) (t - kT)/T and compare the
  // samples with the difference equation of H_beta: 1e-8 relative.
  void cvodeReproducesHbeta_data() {
    QTest::addColumn<double>("beta");
    QTest::addColumn<bool>("paper_plant");
    for (double beta : {-1.0, -0.6, -0.3, 0.0, 0.3, 1.0}) {
      QTest::newRow(qPrintable(QString("paper plant, beta=%1").arg(beta))) << beta << true;
      QTest::newRow(qPrintable(QString("slow drive, beta=%1").arg(beta))) << beta << false;
    }
  }
  void cvodeReproducesHbeta() {
    QFETCH(double, beta);
    QFETCH(bool, paper_plant);
    const double T = paper_plant ? 60.0 / 715.0 : 0.1;
    const StateSpace2 s = paper_plant ? paperPlant().stateSpace() : plantOf(1000.0, 0.02, 0.01);
    const DiscreteTransferFunction h = frohDiscretize(s, T, beta);
    std::vector<double> u;
    unsigned lcg = 12345u;
    for (int k = 0; k < 25; ++k) {
      lcg = lcg * 1664525u + 1013904223u;
      u.push_back(0.005 + 0.02 * static_cast<double>(lcg >> 8) / 16777216.0);  // feed 5..25 mm/s
    }
    const std::vector<double> y_tf = filter(h, u);
    std::vector<double> x{0.0, 0.0};
    double ymax = 0.0, err = 0.0;
    for (std::size_t k = 0; k + 1 < u.size(); ++k) {
      const double uk = u[k], up = k > 0 ? u[k - 1] : 0.0, t0 = k * T;
      auto rhs = [&](double t, const double* xs, double* dx) {
        const double in = uk + beta * (uk - up) * (t - t0) / T;
        dx[0] = s.A(0, 0) * xs[0] + s.A(0, 1) * xs[1] + s.B(0) * in;
        dx[1] = s.A(1, 0) * xs[0] + s.A(1, 1) * xs[1] + s.B(1) * in;
      };
      // a fresh integrator per period: the hold output jumps at every sampling instant
      CvodeIntegrator ode(rhs, t0, x, 1e-12, {1e-16, 1e-11}, 1000000, CvodeIntegrator::Method::Bdf);
      ode.advanceTo(t0 + T);
      x = {ode.state()[0], ode.state()[1]};
      const double y = s.C(0) * x[0] + s.C(1) * x[1];
      ymax = std::max(ymax, std::abs(y));
      err = std::max(err, std::abs(y - y_tf[k + 1]));
    }
    QVERIFY2(err <= 1e-8 * ymax, qPrintable(QString("max error %1 of %2").arg(err).arg(ymax)));
  }

  void invalidInputs() {
    const StateSpace2 s = paperPlant().stateSpace();
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frohDiscretize(s, 0.1, 1.5));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frohDiscretize(s, 0.1, -1.0001));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frohDiscretize(s, 0.0, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frohDiscretize(s, std::nan(""), 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, referenceModel(0.0, 1.0));
  }
};

MX_REGISTER_TEST(TestFrohDiscretization)
#include "test_froh_discretization.moc"
