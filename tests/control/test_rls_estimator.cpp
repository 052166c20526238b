// RLS (2006 paper, eq. 26): recovery of known parameters under PRBS excitation, forgetting, covariance resets.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

#include "control/rls_estimator.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {

// Maximal-length 7-bit LFSR: a PRBS of period 127 in {-1, +1}.
struct Prbs {
  unsigned state = 0x5Au;
  double next() {
    const unsigned bit = ((state >> 6) ^ (state >> 5)) & 1u;
    state = ((state << 1) | bit) & 0x7Fu;
    return (state & 1u) ? 1.0 : -1.0;
  }
};

// y(k) = -a1 y(k-1) - a2 y(k-2) + b0 u(k-1) + b1 u(k-2) [+ b2 u(k-3)]: the paper's regressor layout.
Eigen::VectorXd regressor(const std::vector<double>& y, const std::vector<double>& u, std::size_t k, int nb) {
  auto get = [](const std::vector<double>& v, std::size_t at, std::size_t lag) {
    return at >= lag ? v[at - lag] : 0.0;
  };
  Eigen::VectorXd phi(2 + nb);
  phi(0) = -get(y, k, 1);
  phi(1) = -get(y, k, 2);
  for (int j = 0; j < nb; ++j) phi(2 + j) = get(u, k, static_cast<std::size_t>(j) + 1);
  return phi;
}

Eigen::VectorXd identify(const Eigen::VectorXd& truth, const RlsSettings& s, int samples, int* resets = nullptr,
                         const Eigen::VectorXd* switch_to = nullptr, int switch_at = -1) {
  const int nb = static_cast<int>(truth.size()) - 2;
  RlsEstimator rls(static_cast<int>(truth.size()), s);
  Prbs prbs;
  std::vector<double> y, u;
  Eigen::VectorXd theta = truth;
  for (int k = 0; k < samples; ++k) {
    if (k == switch_at && switch_to) theta = *switch_to;
    u.push_back(prbs.next());
    y.push_back(0.0);
    const Eigen::VectorXd phi = regressor(y, u, static_cast<std::size_t>(k), nb);
    y.back() = phi.dot(theta);
    rls.update(phi, y.back(), 1.0);
  }
  if (resets) *resets = rls.resets();
  return rls.theta();
}

}  // namespace

class TestRlsEstimator : public QObject {
  Q_OBJECT
 private slots:
  void recoversKnownParameters_data() {
    QTest::addColumn<double>("lambda");
    QTest::addColumn<int>("reset");
    QTest::addColumn<int>("nb");
    QTest::newRow("beta != 0 layout (5 params), lambda = 1") << 1.0 << int(CovarianceReset::None) << 3;
    QTest::newRow("beta = 0 layout (4 params), lambda = 1") << 1.0 << int(CovarianceReset::None) << 2;
    QTest::newRow("lambda = 0.98") << 0.98 << int(CovarianceReset::None) << 3;
    QTest::newRow("5 % error reset") << 1.0 << int(CovarianceReset::ErrorFraction) << 3;
    QTest::newRow("trace reset") << 0.95 << int(CovarianceReset::Trace) << 3;
  }
  void recoversKnownParameters() {
    QFETCH(double, lambda);
    QFETCH(int, reset);
    QFETCH(int, nb);
    Eigen::VectorXd truth(2 + nb);
    if (nb == 3)
      truth << -1.2, 0.5, 1.0, 0.5, 0.2;  // poles 0.6 +- 0.37i, zeros inside the unit circle
    else
      truth << -1.2, 0.5, 1.0, 0.5;
    RlsSettings s;
    s.forgetting_factor = lambda;
    s.reset = static_cast<CovarianceReset>(reset);
    s.trace_min = 1e-3;
    s.trace_max = 1e12;
    const Eigen::VectorXd est = identify(truth, s, 400);
    const double err = (est - truth).cwiseAbs().maxCoeff();
    QVERIFY2(err < 1e-6, qPrintable(QString("max parameter error %1").arg(err)));
  }

  // A sudden 50 % gain change (like a depth step) is tracked after a 5 % reset.
  void tracksParameterJumpWithReset() {
    Eigen::VectorXd a(5), b(5);
    a << -1.2, 0.5, 1.0, 0.5, 0.2;
    b << -1.2, 0.5, 1.5, 0.75, 0.3;
    RlsSettings s;  // lambda = 1: without the reset P would be ~1/k and the new values would be reached slowly
    int resets = 0;
    const Eigen::VectorXd est = identify(a, s, 500, &resets, &b, 250);
    QVERIFY((est - b).cwiseAbs().maxCoeff() < 1e-6);
    QVERIFY(resets >= 1);
    RlsSettings none = s;
    none.reset = CovarianceReset::None;
    const Eigen::VectorXd slow = identify(a, none, 500, nullptr, &b, 250);
    QVERIFY((slow - b).cwiseAbs().maxCoeff() > 1e-3);  // the reset is what makes it fast
  }

  void initialValues() {
    RlsEstimator r(4, RlsSettings{});
    QCOMPARE(r.theta(), Eigen::VectorXd::Constant(4, 0.2));
    QCOMPARE(r.covariance(), Eigen::MatrixXd::Identity(4, 4) * 1e5);
  }

  void nonFiniteDataLeavesEstimateUntouched() {
    RlsEstimator r(2, RlsSettings{});
    Eigen::VectorXd phi(2);
    phi << std::nan(""), 1.0;
    r.update(phi, 1.0, 1.0);
    QVERIFY(r.theta().allFinite());
    QCOMPARE(r.theta(), Eigen::VectorXd::Constant(2, 0.2));
  }

  void invalidSettings_data() {
    QTest::addColumn<double>("lambda");
    QTest::addColumn<double>("p0");
    QTest::newRow("lambda 0") << 0.0 << 1e5;
    QTest::newRow("lambda > 1") << 1.01 << 1e5;
    QTest::newRow("P0 0") << 1.0 << 0.0;
    QTest::newRow("P0 inf") << 1.0 << std::numeric_limits<double>::infinity();
  }
  void invalidSettings() {
    QFETCH(double, lambda);
    QFETCH(double, p0);
    RlsSettings s;
    s.forgetting_factor = lambda;
    s.initial_covariance = p0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, RlsEstimator(3, s));
  }
};

MX_REGISTER_TEST(TestRlsEstimator)
#include "test_rls_estimator.moc"
