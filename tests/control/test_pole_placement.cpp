// Model-following pole placement (eq. 27-29): Diophantine residual (eq. 28) to 1e-9, closed loop = model,
// fallback for unstable zeros, near-common factors, degenerate estimates (no NaN, no division by zero).
#include <cmath>

#include "control/force_plant.h"
#include "control/froh_discretization.h"
#include "control/pole_placement.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {

const double kPeriod715 = 60.0 / 715.0;

DiscreteTransferFunction model(double beta) {
  return frohDiscretize(referenceModel(0.75, 2.5 / (4.0 * kPeriod715)), kPeriod715, beta);
}

// closed loop B T / (A R + B S) evaluated at z
std::complex<double> closedLoop(const Poly& A, const Poly& B, const RstDesign& d, std::complex<double> z) {
  const auto num = polyEval(B, z) * polyEval(d.T, z);
  return num / (polyEval(A, z) * polyEval(d.R, z) + polyEval(B, z) * polyEval(d.S, z));
}

bool allFinite(const Poly& p) {
  for (double c : p)
    if (!std::isfinite(c)) return false;
  return true;
}

}  // namespace

class TestPolePlacement : public QObject {
  Q_OBJECT
 private slots:
  // The true plant of the paper (drive pole at z = 0, zero near 0) for several beta and depths.
  void paperPlantFollowsModel_data() {
    QTest::addColumn<double>("beta");
    QTest::addColumn<double>("depth_mm");
    for (double beta : {-0.5, -0.3, 0.0, 0.3, 1.0})
      for (double b : {2.0, 5.0}) QTest::newRow(qPrintable(QString("beta=%1 b=%2mm").arg(beta).arg(b))) << beta << b;
  }
  void paperPlantFollowsModel() {
    QFETCH(double, beta);
    QFETCH(double, depth_mm);
    CuttingProcess process;
    const DiscreteTransferFunction h =
        frohDiscretize(makeForcePlant(process, depth_mm * 1e-3).stateSpace(), kPeriod715, beta);
    const DiscreteTransferFunction m = model(beta);
    const RstDesign d = designModelFollowing(h.den, h.num, m.den, m.num);
    QVERIFY2(d.ok, d.message.c_str());
    QVERIFY(d.model_zeros_followed);         // all zeros stable for beta > -0.572
    QVERIFY(d.common_factors_removed >= 1);  // the drive zero near 0 against the pole at 0
    QVERIFY2(d.diophantine_residual < 1e-9, qPrintable(QString::number(d.diophantine_residual)));
    QVERIFY(polyDegree(d.S) <= polyDegree(d.R) && polyDegree(d.T) <= polyDegree(d.R));  // causal
    for (double w : {0.0, 0.3, 1.0, 2.0, 3.0}) {
      const std::complex<double> z = std::polar(1.0, w);
      const auto want = polyEval(m.num, z) / polyEval(m.den, z);
      const auto got = closedLoop(d.A_used, d.B_used, d, z);
      QVERIFY2(std::abs(got - want) < 1e-9 * std::max(1.0, std::abs(want)),
               qPrintable(QString("w=%1: %2 vs %3").arg(w).arg(std::abs(got)).arg(std::abs(want))));
    }
  }

  // Eq. 28 with explicit polynomials, including cases that need an observer polynomial Ao.
  void diophantineResidual_data() {
    QTest::addColumn<QVector<double>>("A");
    QTest::addColumn<QVector<double>>("B");
    QTest::addColumn<int>("kept");
    QTest::newRow("2nd order, stable zero") << QVector<double>{1.0, -1.5, 0.7} << QVector<double>{1.0, 0.5} << 0;
    QTest::newRow("2nd order, unstable zero 1.5") << QVector<double>{1.0, -1.5, 0.7} << QVector<double>{1.0, -1.5} << 1;
    QTest::newRow("zero at -1 (theta0 = 0.2)") << QVector<double>{1.0, 0.2, 0.2} << QVector<double>{0.2, 0.2} << 1;
    QTest::newRow("3rd order, complex zeros |z|=1")
        << QVector<double>{1.0, 0.2, 0.2, 0.0} << QVector<double>{0.2, 0.2, 0.2} << 2;
    QTest::newRow("3rd order, one zero -3")
        << QVector<double>{1.0, -1.2, 0.5, 0.0} << QVector<double>{1.0, 2.5, -1.5} << 1;
  }
  void diophantineResidual() {
    QFETCH(QVector<double>, A);
    QFETCH(QVector<double>, B);
    QFETCH(int, kept);
    const Poly a(A.begin(), A.end()), b(B.begin(), B.end());
    const DiscreteTransferFunction m = model(a.size() == 4 ? 0.5 : 0.0);
    const RstDesign d = designModelFollowing(a, b, m.den, m.num);
    QVERIFY2(d.ok, d.message.c_str());
    QCOMPARE(d.zeros_kept, kept);
    QVERIFY2(d.diophantine_residual < 1e-9, qPrintable(QString::number(d.diophantine_residual)));
    // recompute eq. 28 independently
    const Poly lhs = polyAdd(polyMultiply(d.A_used, d.R_prime), polyMultiply(d.B_minus, d.S));
    const Poly rhs = polyMultiply(m.den, d.Ao);
    QVERIFY(polyMaxAbs(polySubtract(lhs, rhs)) < 1e-9 * polyMaxAbs(rhs));
    QVERIFY(polyDegree(d.S) <= polyDegree(d.R) && polyDegree(d.T) <= polyDegree(d.R));
    // closed-loop static gain 1 also in the fallback (B- Bm' / Am)
    const auto g = closedLoop(d.A_used, d.B_used, d, 1.0);
    QVERIFY2(std::abs(g - 1.0) < 1e-9, qPrintable(QString::number(std::abs(g))));
    if (kept > 0) QVERIFY(!d.model_zeros_followed);
  }

  void nearCommonFactorIsRemoved() {
    // A = (z - 0.5)(z - 0.2), B = (z - 0.5 - 1e-4): near cancellation; without removal the Sylvester matrix of
    // A and B- would be nearly singular if the zero were kept.
    const Poly A = polyMultiply({1.0, -0.5}, {1.0, -0.2}), B = {1.0, -0.5001};
    PolePlacementSettings st;
    st.cancel_radius = 0.4;  // would keep the zero 0.5001 in B-
    const DiscreteTransferFunction m = model(0.0);
    const RstDesign d = designModelFollowing(A, B, m.den, m.num, st);
    QVERIFY(d.ok);
    QCOMPARE(d.common_factors_removed, 1);
    QVERIFY(!d.unstable_common_factor);
    QVERIFY(d.diophantine_residual < 1e-9);
    // an unstable near-common pair is flagged
    const Poly A2 = polyMultiply({1.0, -1.3}, {1.0, -0.2}), B2 = {1.0, -1.3001};
    const RstDesign d2 = designModelFollowing(A2, B2, m.den, m.num, st);
    QVERIFY(d2.ok);
    QVERIFY(d2.unstable_common_factor);
  }

  void degenerateEstimatesFailCleanly_data() {
    QTest::addColumn<QVector<double>>("A");
    QTest::addColumn<QVector<double>>("B");
    QTest::newRow("B = 0") << QVector<double>{1.0, 0.2, 0.2} << QVector<double>{0.0, 0.0};
    QTest::newRow("zero at z = 1 kept") << QVector<double>{1.0, 0.2, 0.2} << QVector<double>{1.0, -1.0};
    QTest::newRow("NaN") << QVector<double>{1.0, std::nan(""), 0.2} << QVector<double>{1.0, 0.0};
    QTest::newRow("improper") << QVector<double>{1.0, 0.2} << QVector<double>{1.0, 0.5};
  }
  void degenerateEstimatesFailCleanly() {
    QFETCH(QVector<double>, A);
    QFETCH(QVector<double>, B);
    const DiscreteTransferFunction m = model(0.0);
    const RstDesign d = designModelFollowing(Poly(A.begin(), A.end()), Poly(B.begin(), B.end()), m.den, m.num);
    QVERIFY(!d.ok);
    QVERIFY(!d.message.empty());
    QVERIFY(allFinite(d.R) && allFinite(d.S) && allFinite(d.T));
    QVERIFY(std::isfinite(d.diophantine_residual));
  }

  void invalidSettings() {
    PolePlacementSettings s;
    s.cancel_radius = 1.5;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, designModelFollowing({1.0, 0.5}, {1.0}, {1.0, 0.5}, {0.5}, s));
  }
};

MX_REGISTER_TEST(TestPolePlacement)
#include "test_pole_placement.moc"
