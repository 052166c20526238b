// Force reference from the tool limits: breakage force or spindle power, whichever binds.
#include <cmath>

#include "control/force_reference.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

class TestForceReference : public QObject {
  Q_OBJECT
 private slots:
  void binding_data() {
    QTest::addColumn<double>("breakage");
    QTest::addColumn<double>("power");
    QTest::addColumn<double>("expected");
    QTest::addColumn<QString>("binding");
    // v = pi * 0.02 m * 715/60 rev/s = 0.74875 m/s; 745.7 W -> 995.9 N
    const double v = 3.14159265358979323846 * 0.02 * 715.0 / 60.0;
    QTest::newRow("power binds") << 1500.0 << 745.7 << 745.7 / v << "power";
    QTest::newRow("breakage binds") << 900.0 << 745.7 << 900.0 * 0.8 << "breakage";
    QTest::newRow("breakage only") << 1500.0 << 0.0 << 1500.0 * 0.8 << "breakage";
    QTest::newRow("power only") << 0.0 << 2000.0 << 2000.0 / v << "power";
  }
  void binding() {
    QFETCH(double, breakage);
    QFETCH(double, power);
    QFETCH(double, expected);
    QFETCH(QString, binding);
    ToolForceLimits l{breakage, 0.8, power, 0.02, 715.0 / 60.0};
    const ForceReference r = forceReferenceFromLimits(l);
    QVERIFY(std::abs(r.force_N - expected) < 1e-9 * expected);
    QCOMPARE(QString::fromStdString(r.binding), binding);
  }
  void invalid() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, forceReferenceFromLimits({0.0, 1.0, 0.0, 0.02, 10.0}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, forceReferenceFromLimits({1000.0, 1.5, 0.0, 0.02, 10.0}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, forceReferenceFromLimits({0.0, 1.0, 500.0, 0.0, 10.0}));
  }
};

MX_REGISTER_TEST(TestForceReference)
#include "test_force_reference.moc"
