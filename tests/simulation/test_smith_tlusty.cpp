// Smith-Tlusty spindle speed selection (Pareto paper Rule 16, physical direction):
// N = f_c / (n_t k) rev/s with the integer k >= 1 whose speed is nearest the current one in [min, max].
#include <cmath>
#include <limits>

#include "core/invalid_input.h"
#include "simulation/smith_tlusty.h"
#include "test_registry.h"

using namespace mx;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

class TestSmithTlusty : public QObject {
  Q_OBJECT
 private slots:
  void choosesNearestLobe_data() {
    QTest::addColumn<double>("chatter_hz");
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("current");
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    QTest::addColumn<double>("expected");  // rev/s, < 0: none
    QTest::addColumn<int>("k");
    // f_c / n_t = 200 rev/s: candidates 200, 100, 66.67, 50, ...
    QTest::newRow("already tuned (k = 2)") << 600.0 << 3 << 100.0 << 0.0 << kInf << 100.0 << 2;
    QTest::newRow("nearest is the faster lobe") << 600.0 << 3 << 90.0 << 0.0 << kInf << 100.0 << 2;
    QTest::newRow("nearest is the slower lobe") << 600.0 << 3 << 80.0 << 0.0 << kInf << 200.0 / 3.0 << 3;
    QTest::newRow("tie goes to the higher speed") << 720.0 << 3 << 100.0 << 0.0 << kInf << 120.0 << 2;
    QTest::newRow("above the k = 1 speed") << 600.0 << 3 << 300.0 << 0.0 << kInf << 200.0 << 1;
    QTest::newRow("max excludes k = 1") << 600.0 << 3 << 150.0 << 0.0 << 150.0 << 100.0 << 2;
    QTest::newRow("max exactly on a lobe speed (inclusive)") << 600.0 << 3 << 150.0 << 0.0 << 100.0 << 100.0 << 2;
    QTest::newRow("min limits k (inclusive)") << 600.0 << 3 << 10.0 << 50.0 << kInf << 50.0 << 4;
    QTest::newRow("none between two lobe speeds") << 600.0 << 3 << 150.0 << 101.0 << 199.0 << -1.0 << 0;
    QTest::newRow("slow current speed, large k") << 600.0 << 3 << 0.5 << 0.0 << kInf << 0.5 << 400;
    QTest::newRow("4 teeth, 1000 Hz, 3600 rpm") << 1000.0 << 4 << 60.0 << 0.0 << kInf << 62.5 << 4;
    QTest::newRow("range is a single lobe speed") << 600.0 << 3 << 20.0 << 40.0 << 40.0 << 40.0 << 5;
  }
  void choosesNearestLobe() {
    QFETCH(double, chatter_hz);
    QFETCH(int, teeth);
    QFETCH(double, current);
    QFETCH(double, min);
    QFETCH(double, max);
    QFETCH(double, expected);
    QFETCH(int, k);
    const auto choice = smithTlustyChoice(chatter_hz, teeth, current, min, max);
    const auto speed = smithTlustySpeed(chatter_hz, teeth, current, min, max);
    if (expected < 0.0) {
      QVERIFY(!choice);
      QVERIFY(!speed);
      return;
    }
    QVERIFY(choice && speed);
    QCOMPARE(*speed, choice->rev_per_s);
    QCOMPARE(choice->k, k);
    QVERIFY(std::abs(choice->rev_per_s - expected) <= 1e-12 * expected);
    QVERIFY(choice->rev_per_s >= min && choice->rev_per_s <= max);
    // Rule 16: the tooth-passing frequency times k equals the chatter frequency.
    QVERIFY(std::abs(choice->rev_per_s * teeth * choice->k - chatter_hz) <= 1e-12 * chatter_hz);
  }

  void rejectsInvalidInput_data() {
    QTest::addColumn<double>("chatter_hz");
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("current");
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    QTest::addColumn<QString>("quantity");
    QTest::newRow("zero chatter frequency") << 0.0 << 3 << 100.0 << 0.0 << kInf << "chatter frequency";
    QTest::newRow("NaN chatter frequency") << std::nan("") << 3 << 100.0 << 0.0 << kInf << "chatter frequency";
    QTest::newRow("no teeth") << 600.0 << 0 << 100.0 << 0.0 << kInf << "teeth";
    QTest::newRow("zero current speed") << 600.0 << 3 << 0.0 << 0.0 << kInf << "current speed";
    QTest::newRow("negative minimum") << 600.0 << 3 << 100.0 << -1.0 << kInf << "minimum speed";
    QTest::newRow("maximum below minimum") << 600.0 << 3 << 100.0 << 50.0 << 40.0 << "maximum speed";
  }
  void rejectsInvalidInput() {
    QFETCH(double, chatter_hz);
    QFETCH(int, teeth);
    QFETCH(double, current);
    QFETCH(double, min);
    QFETCH(double, max);
    QFETCH(QString, quantity);
    try {
      smithTlustySpeed(chatter_hz, teeth, current, min, max);
      QFAIL("no InvalidInput thrown");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(quantity), e.what());
    }
  }
};

MX_REGISTER_TEST(TestSmithTlusty)
#include "test_smith_tlusty.moc"
