// Rule 4: one spindle period, k periods while N and b stay constant.
#include "core/invalid_input.h"
#include "pareto/sampling_time.h"
#include "test_registry.h"

using namespace mx;

class TestSamplingTime : public QObject {
  Q_OBJECT
 private slots:
  void period_data() {
    QTest::addColumn<double>("rpm");
    QTest::addColumn<bool>("steady");
    QTest::addColumn<int>("k");
    QTest::addColumn<double>("expected");
    QTest::newRow("715 rpm (2006 example)") << 715.0 << false << 4 << 60.0 / 715.0;
    QTest::newRow("steady, k = 4") << 715.0 << true << 4 << 4.0 * 60.0 / 715.0;
    QTest::newRow("steady, k = 1") << 2010.0 << true << 1 << 60.0 / 2010.0;
  }
  void period() {
    QFETCH(double, rpm);
    QFETCH(bool, steady);
    QFETCH(int, k);
    QFETCH(double, expected);
    QVERIFY(std::abs(samplingTime(rpm / 60.0, steady, k) - expected) < 1e-15);
  }
  void selector() {
    SamplingTimeSelector s({3, 1e-9});
    QCOMPARE(s.update(30.0, 1e-3), 1.0 / 30.0);  // first sample: transient
    QCOMPARE(s.update(30.0, 1e-3), 3.0 / 30.0);  // N, b unchanged: steady
    QVERIFY(s.steady());
    QCOMPARE(s.update(30.0, 2e-3), 1.0 / 30.0);  // depth changed
    QCOMPARE(s.update(40.0, 2e-3), 1.0 / 40.0);  // speed changed
    QCOMPARE(s.update(40.0, 2e-3), 3.0 / 40.0);
  }
  void invalid() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, samplingTime(0.0, false, 1));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, samplingTime(10.0, true, 0));
  }
};

MX_REGISTER_TEST(TestSamplingTime)
#include "test_sampling_time.moc"
