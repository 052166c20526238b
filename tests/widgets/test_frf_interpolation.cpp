// interpolateFrf: exact at the grid lines, linear in Re and Im between them, nothing outside the grid
// or on an empty one.
#include "frf_interpolation.h"
#include "test_registry.h"

using mx::widgets::interpolateFrf;
using C = std::complex<double>;

class TestFrfInterpolation : public QObject {
  Q_OBJECT
 private slots:
  void interpolates_data() {
    QTest::addColumn<double>("f");
    QTest::addColumn<bool>("inside");
    QTest::addColumn<C>("expected");
    QTest::newRow("first line") << 10.0 << true << C(1.0, 0.0);
    QTest::newRow("last line") << 30.0 << true << C(5.0, -4.0);
    QTest::newRow("inner line") << 20.0 << true << C(3.0, 2.0);
    QTest::newRow("quarter") << 12.5 << true << C(1.5, 0.5);
    QTest::newRow("three quarters of the second") << 27.5 << true << C(4.5, -2.5);
    QTest::newRow("below") << 9.999 << false << C();
    QTest::newRow("above") << 30.001 << false << C();
  }
  void interpolates() {
    QFETCH(double, f);
    QFETCH(bool, inside);
    QFETCH(C, expected);
    const std::vector<double> grid{10.0, 20.0, 30.0};
    const std::vector<C> h{C(1.0, 0.0), C(3.0, 2.0), C(5.0, -4.0)};
    const auto value = interpolateFrf(grid, h, f);
    QCOMPARE(value.has_value(), inside);
    if (inside) QVERIFY(std::abs(*value - expected) < 1e-12);
  }

  void emptyGrid() { QVERIFY(!interpolateFrf({}, {}, 1.0).has_value()); }
};

MX_REGISTER_TEST(TestFrfInterpolation)
#include "test_frf_interpolation.moc"
