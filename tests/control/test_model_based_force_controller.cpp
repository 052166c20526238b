// Model-based force control (Landers & Ulsoy SMC I): F = 0.76 d^0.65 f^0.63 kN, inverted for the feed,
// limited by the feed drive (36 mm/s) and the feed per tooth (0.6 mm/tooth).
#include <cmath>

#include "control/model_based_force_controller.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {
ModelBasedForceSettings landers(double f_ref) {
  ModelBasedForceSettings s;
  s.reference_force_N = f_ref;
  return s;
}
}  // namespace

class TestModelBasedForceController : public QObject {
  Q_OBJECT
 private slots:
  void forceModel() {
    const ModelBasedForceController c(landers(500.0));
    // 0.76 kN * 1^0.65 * 0.1^0.63 = 760 * 10^-0.63 = 178.16139 N
    QVERIFY(std::abs(c.force(1e-3, 0.1e-3) - 178.161390) < 1e-5);
    // 2 mm: 2^0.65 = 1.569168
    QVERIFY(std::abs(c.force(2e-3, 0.1e-3) / c.force(1e-3, 0.1e-3) - 1.5691681) < 1e-6);
    QCOMPARE(c.force(0.0, 0.1e-3), 0.0);
    QCOMPARE(c.force(1e-3, 0.0), 0.0);
  }
  void exactInversion_data() {
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("force_N");
    QTest::newRow("1 mm, 300 N") << 1.0 << 300.0;
    QTest::newRow("2 mm, 500 N") << 2.0 << 500.0;
    QTest::newRow("0.05 mm, 50 N") << 0.05 << 50.0;
    QTest::newRow("5 mm, 1200 N") << 5.0 << 1200.0;
  }
  void exactInversion() {
    QFETCH(double, depth_mm);
    QFETCH(double, force_N);
    const ModelBasedForceController c(landers(force_N));
    const double f = c.feedPerToothForForce(depth_mm * 1e-3, force_N);
    QVERIFY(std::abs(c.force(depth_mm * 1e-3, f) / force_N - 1.0) < 1e-13);
    // closed form: f = (F / (760 d^0.65))^(1/0.63) mm
    const double expected_mm = std::pow(force_N / (760.0 * std::pow(depth_mm, 0.65)), 1.0 / 0.63);
    QVERIFY(std::abs(f * 1e3 / expected_mm - 1.0) < 1e-13);
  }
  void forceLimitedFeed() {
    // 2 mm deep, 1500 rpm, 4 teeth, F_ref 300 N: f = (300/(760*2^0.65))^(1/0.63) mm = 0.111849 mm/tooth
    const ModelBasedForceController c(landers(300.0));
    const auto d = c.feed(2e-3, 25.0);
    QCOMPARE(d.limit, FeedLimit::Force);
    QVERIFY(std::abs(d.predicted_force_N - 300.0) < 1e-9);
    QVERIFY(std::abs(d.feed_per_tooth_m * 1e3 - 0.1118490) < 1e-6);
    QVERIFY(std::abs(d.feed_rate_m_per_s - d.feed_per_tooth_m * 100.0) < 1e-15);
  }
  void limitsRespected() {
    const ModelBasedForceController c(landers(1000.0));
    // 1500 rpm: the drive allows 36 mm/s / (4 * 25 rev/s) = 0.36 mm/tooth < 0.6 -> drive limit
    const auto drive = c.feed(0.5e-3, 25.0);
    QCOMPARE(drive.limit, FeedLimit::FeedDrive);
    QVERIFY(std::abs(drive.feed_rate_m_per_s - 36e-3) < 1e-15);
    QVERIFY(drive.predicted_force_N < 1000.0);
    // 600 rpm: the drive would allow 0.9 mm/tooth, the tooth limit 0.6 mm/tooth wins
    const auto tooth = c.feed(0.5e-3, 10.0);
    QCOMPARE(tooth.limit, FeedLimit::FeedPerTooth);
    QVERIFY(std::abs(tooth.feed_per_tooth_m - 0.6e-3) < 1e-18);
    QVERIFY(std::abs(tooth.feed_rate_m_per_s - 24e-3) < 1e-15);
    // a sweep: never above either maximum, and on the force where neither binds
    for (double depth = 0.1e-3; depth < 6e-3; depth += 0.1e-3)
      for (double n : {5.0, 10.0, 25.0, 50.0}) {
        const auto d = c.feed(depth, n);
        QVERIFY(d.feed_rate_m_per_s <= 36e-3 * (1 + 1e-12));
        QVERIFY(d.feed_per_tooth_m <= 0.6e-3 * (1 + 1e-12));
        QVERIFY(d.predicted_force_N <= 1000.0 * (1 + 1e-12));
        if (d.limit == FeedLimit::Force) QVERIFY(std::abs(d.predicted_force_N - 1000.0) < 1e-8);
      }
  }
  void depthToZero() {
    const ModelBasedForceController c(landers(300.0));
    for (double d : {0.0, -1e-3, 1e-300, 5e-324}) {
      const auto r = c.feed(d, 25.0);
      QVERIFY(std::isfinite(r.feed_rate_m_per_s));
      QCOMPARE(r.limit, FeedLimit::FeedDrive);
      QVERIFY(std::abs(r.feed_rate_m_per_s - 36e-3) < 1e-15);
      QVERIFY(r.predicted_force_N < 1e-100);
    }
    QVERIFY(std::isinf(c.feedPerToothForForce(0.0, 300.0)));
  }
  void invalidInputs() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, ModelBasedForceController(ModelBasedForceSettings{}));  // no F_ref
    auto s = landers(300.0);
    s.teeth = 0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, ModelBasedForceController{s});
    s = landers(300.0);
    s.model.feed_exponent = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, ModelBasedForceController{s});
    s = landers(300.0);
    s.max_feed_rate_m_per_s = -1.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, ModelBasedForceController{s});
    const ModelBasedForceController c(landers(300.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, c.feed(1e-3, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, c.feed(1e-3, 25.0, -5.0));
    try {
      c.feed(1e-3, 0.0);
    } catch (const InvalidInput& e) {
      QVERIFY(std::string(e.what()).find("spindle_speed") != std::string::npos);
      QVERIFY(std::string(e.what()).find("must be > 0") != std::string::npos);
    }
  }
};

MX_REGISTER_TEST(TestModelBasedForceController)
#include "test_model_based_force_controller.moc"
