// The RAII CVODE wrapper: integrates a known ODE accurately, reports RHS failures and invalid setups
// as exceptions (every SUNDIALS return flag is checked).
#include <cmath>
#include <stdexcept>

#include "simulation/cvode_integrator.h"
#include "test_registry.h"

using namespace mx;

class TestCvodeIntegrator : public QObject {
  Q_OBJECT
 private slots:
  // Damped oscillator q'' + 2 zeta w q' + w^2 q = 0 from q(0) = 1, q'(0) = 0 against the exact solution.
  void dampedOscillator_data() {
    QTest::addColumn<double>("rtol");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("rtol 1e-6") << 1e-6 << 1e-4;
    QTest::newRow("rtol 1e-10") << 1e-10 << 1e-7;
  }
  void dampedOscillator() {
    QFETCH(double, rtol);
    QFETCH(double, tolerance);
    const double w = 2.0 * 3.14159265358979323846 * 600.0, zeta = 0.04;
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    auto rhs = [&](double, const double* y, double* dy) {
      dy[0] = y[1];
      dy[1] = -2.0 * zeta * w * y[1] - w * w * y[0];
    };
    CvodeIntegrator integrator(rhs, 0.0, {1.0, 0.0}, rtol, {rtol * 1e-3, rtol * 1e-3 * w});
    double worst = 0.0;
    for (int k = 1; k <= 200; ++k) {
      const double t = k * 5e-5;
      integrator.advanceTo(t);
      QCOMPARE(integrator.time(), t);
      const double exact = std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
      worst = std::max(worst, std::abs(integrator.state()[0] - exact));
    }
    QVERIFY2(worst < tolerance, qPrintable(QString("max error %1").arg(worst)));
    QVERIFY(integrator.steps() > 10);
  }

  void rhsExceptionPropagates() {
    auto rhs = [](double t, const double* y, double* dy) {
      if (t > 0.5) throw std::domain_error("rhs refuses t > 0.5");
      dy[0] = -y[0];
    };
    CvodeIntegrator integrator(rhs, 0.0, {1.0}, 1e-8, {1e-12});
    integrator.advanceTo(0.4);
    QVERIFY(std::abs(integrator.state()[0] - std::exp(-0.4)) < 1e-6);
    QVERIFY_THROWS_EXCEPTION(std::domain_error, integrator.advanceTo(1.0));
  }

  void invalidSetupThrows() {
    auto rhs = [](double, const double*, double* dy) { dy[0] = 0.0; };
    QVERIFY_THROWS_EXCEPTION(CvodeError, CvodeIntegrator(rhs, 0.0, {}, 1e-8, {}));
    QVERIFY_THROWS_EXCEPTION(CvodeError, CvodeIntegrator(rhs, 0.0, {1.0}, 1e-8, {1e-9, 1e-9}));
    // Negative tolerances are rejected by CVodeSVtolerances (CV_ILL_INPUT).
    try {
      CvodeIntegrator bad(rhs, 0.0, {1.0}, -1.0, {1e-9});
      QFAIL("no CvodeError");
    } catch (const CvodeError& e) {
      QVERIFY2(QString(e.what()).contains("CVodeSVtolerances"), e.what());
    }
  }

  // Too few steps allowed to reach the target: CVode returns CV_TOO_MUCH_WORK, reported as an error.
  void tooMuchWorkThrows() {
    auto rhs = [](double, const double* y, double* dy) {
      dy[0] = y[1];
      dy[1] = -1e8 * y[0];
    };
    CvodeIntegrator integrator(rhs, 0.0, {1.0, 0.0}, 1e-10, {1e-14, 1e-10}, 10);
    try {
      integrator.advanceTo(1.0);
      QFAIL("no CvodeError");
    } catch (const CvodeError& e) {
      QVERIFY2(QString(e.what()).contains("CV_TOO_MUCH_WORK"), e.what());
    }
  }
};

MX_REGISTER_TEST(TestCvodeIntegrator)
#include "test_cvode_integrator.moc"
