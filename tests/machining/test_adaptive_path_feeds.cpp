// The adaptive controller along a part program: the cutting blocks are the feed moves below the stock
// top (not air moves, not plunges); the closed loop over them equals the closed loop over the same
// workpiece; each block's feed is its length over the simulated time spent in it, within [0, f_max],
// and its force the largest simulated force there.
#include <cmath>

#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "machining/adaptive_path_feeds.h"
#include "machining/depth_profile.h"
#include "test_registry.h"

using namespace mx;

class TestAdaptivePathFeeds : public QObject {
  Q_OBJECT
 private slots:
  void cuttingBlocksSkipAirAndPlunges() {
    const GcodeProgram p =
        GcodeReader::parse("G21 G90 S715\nG0 Z5\nG1 Z-2 F100\nG1 X10 F600\nG1 Z5\nG1 X20\nG1 Z-3\nX30\n");
    const GcodeRun run = GcodeInterpreter().run(p);
    const auto depths = DepthProfile::fromStockTop(0.0).blockDepths(run);
    const auto cuts = cuttingBlocks(run, depths, true);
    QCOMPARE(cuts.size(), std::size_t(2));  // X10 at 2 mm and X30 at 3 mm
    QCOMPARE(cuts[0].block, std::size_t(3));
    QCOMPARE_LE(std::abs(cuts[0].depth_m - 2e-3), 1e-12);
    QCOMPARE(cuts[1].block, std::size_t(7));
    QCOMPARE_LE(std::abs(cuts[1].length_m - 10e-3), 1e-12);
  }

  void feedsFollowTheClosedLoop() {
    AdaptiveControlSettings s;  // the paper's plant, F_r = 1.2 kN, f_max = 30 mm/s
    s.beta = 0.3;
    // The paper's workpiece split into blocks of 2.935 mm (two per depth step, last one 3.775).
    std::vector<CutBlock> cuts;
    const double depth[] = {2e-3, 3e-3, 5e-3, 3e-3}, length[] = {5.87e-3, 5.87e-3, 5.87e-3, 7.55e-3};
    std::size_t block = 0;
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 2; ++k) cuts.push_back({block++, length[i] / 2, depth[i]});
    const AdaptivePathFeeds feeds(s, cuts);
    // The same workpiece as the paper's profile: the same J_c as a direct run.
    const ClosedLoopResult direct = simulateAdaptiveForceControl(s);
    QCOMPARE_LE(std::abs(feeds.run().metrics.Jc_N_s - direct.metrics.Jc_N_s), 1e-9 * direct.metrics.Jc_N_s);
    double position = 0.0, elapsed = 0.0;
    for (const CutBlock& c : cuts) {
      const auto d = feeds.decisionFor(c.block);
      QVERIFY(d.has_value());
      QVERIFY(d->feed_m_per_s > 0.0 && d->feed_m_per_s <= s.feed_max_m_s + 1e-12);
      QVERIFY(d->predicted_force_N <= feeds.run().metrics.max_force_N + 1e-9);
      elapsed += c.length_m / d->feed_m_per_s;
      position += c.length_m;
    }
    // Time through all blocks = the time the simulated tool took to reach the end of the path.
    double t_end = 0.0;
    for (const ClosedLoopDensePoint& p : feeds.run().dense)
      if (p.position_m < position) t_end = p.t;
    QCOMPARE_LE(std::abs(elapsed - t_end), 2.0 * 60.0 / 715.0 / 32.0);  // within two dense steps
    QVERIFY(!feeds.decisionFor(99).has_value());
  }

  void noCuttingBlockIsAnError() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, AdaptivePathFeeds(AdaptiveControlSettings{}, {}));
  }
};

MX_REGISTER_TEST(TestAdaptivePathFeeds)
#include "test_adaptive_path_feeds.moc"
