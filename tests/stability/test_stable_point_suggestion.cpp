// A chatter-free point near a chattering one, judged by the boundary: on the two-parabola envelope of
// two_lobes_fixture.h (cusp 5 mm at 150 rev/s), every answer is known by hand.
#include <cmath>
#include <optional>

#include "stability/stable_point_suggestion.h"
#include "test_registry.h"
#include "two_lobes_fixture.h"

using namespace mx;

namespace {
using mx::test::twoLobes;
using mx::test::twoLobesEnvelopeMm;
using Kind = StablePointSuggestion::Kind;
}  // namespace

class TestStablePointSuggestion : public QObject {
  Q_OBJECT
 private slots:
  void cases_data() {
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("chatter_hz");  // 0: unknown
    QTest::addColumn<double>("max_speed");
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("speed_out");
    QTest::addColumn<double>("depth_out_mm");
    QTest::addColumn<int>("k");
    // 2 teeth, f_c = 340 Hz: N_1 = 170 rev/s (3.08 mm > 1.5: stable), N_2 = 85 (1.36 mm: unstable).
    QTest::newRow("Smith-Tlusty k = 1") << 100.0 << 1.5 << 340.0 << 1e9 << int(Kind::SmithTlusty) << 170.0 << 1.5 << 1;
    // N_1 = 170 lies above the machine's 160 rev/s; N_2 = 85 chatters: the nearest stable stretch
    // (118-160 rev/s) and its peak, the cusp.
    QTest::newRow("Smith-Tlusty out of range")
        << 105.0 << 1.5 << 340.0 << 160.0 << int(Kind::NearestStableSpeed) << 150.0 << 1.5 << 0;
    QTest::newRow("nearest stable stretch")
        << 105.0 << 1.5 << 0.0 << 1e9 << int(Kind::NearestStableSpeed) << 150.0 << 1.5 << 0;
    QTest::newRow("left stretch is nearer")
        << 92.0 << 1.5 << 0.0 << 1e9 << int(Kind::NearestStableSpeed) << 80.0 << 1.5 << 0;
    // 6 mm is above every lobe up to 240 rev/s: the nearest pocket peak is the cusp, at 99 % of 5 mm.
    QTest::newRow("no stable speed: shallower")
        << 140.0 << 6.0 << 0.0 << 240.0 << int(Kind::ShallowerDepth) << 150.0 << 4.95 << 0;
    // The end of the range counts as a pocket when the boundary rises to it.
    QTest::newRow("no stable speed: range end")
        << 235.0 << 6.0 << 0.0 << 240.0 << int(Kind::ShallowerDepth) << 240.0 << 0.99 * twoLobesEnvelopeMm(240.0) << 0;
  }
  void cases() {
    QFETCH(double, speed);
    QFETCH(double, depth_mm);
    QFETCH(double, chatter_hz);
    QFETCH(double, max_speed);
    QFETCH(int, kind);
    QFETCH(double, speed_out);
    QFETCH(double, depth_out_mm);
    QFETCH(int, k);
    const StabilityBoundary boundary(twoLobes());
    const auto s =
        suggestStablePoint(boundary, speed, depth_mm * 1e-3,
                           chatter_hz > 0.0 ? std::optional<double>(chatter_hz) : std::nullopt, 2, 0.0, max_speed);
    QVERIFY(s);
    QCOMPARE(int(s->kind), kind);
    QCOMPARE_LE(std::abs(s->speed_rev_per_s - speed_out), 1e-9);
    QCOMPARE_LE(std::abs(s->depth_m * 1e3 - depth_out_mm), 1e-9);
    QCOMPARE(s->k, k);
    // Invariant: whatever is offered is stable on the boundary.
    QCOMPARE(boundary.verdict(s->speed_rev_per_s, s->depth_m), StabilityVerdict::Stable);
  }

  void aRangeWithoutComputedSpeedsOffersNothing() {
    const StabilityBoundary boundary(twoLobes());
    QVERIFY(!suggestStablePoint(boundary, 100.0, 1.5e-3, 340.0, 2, 0.0, 50.0));
  }

  // A point the lobes call stable (the simulation disagrees): its own speed is never offered back.
  void theCurrentSpeedIsNotOfferedBack() {
    const StabilityBoundary boundary(twoLobes());
    const auto s = suggestStablePoint(boundary, 170.0, 1.5e-3, 340.0, 2, 0.0, 1e9);
    QVERIFY(s);
    QVERIFY(std::abs(s->speed_rev_per_s - 170.0) > 1.7);
    QCOMPARE(boundary.verdict(s->speed_rev_per_s, s->depth_m), StabilityVerdict::Stable);
  }
};

MX_REGISTER_TEST(TestStablePointSuggestion)
#include "test_stable_point_suggestion.moc"
