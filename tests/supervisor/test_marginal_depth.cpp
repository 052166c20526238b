// The appendix's marginal-depth search on the face-milling TDS: with the paper's structures (A6-A9)
// and our lead angle and part width, 1 mm is stable, 2 mm chatters, and the marginal depth lies
// between them.
#include <atomic>

#include "supervisor/marginal_depth.h"
#include "test_registry.h"

using namespace mx;

class TestMarginalDepth : public QObject {
  Q_OBJECT
 private slots:
  void oneMillimetreStableTwoUnstable() {
    MarginalDepthSearch s(FaceMillingParameters{}, MarginalDepthSettings{});
    const DepthTrial one = s.trial(1e-3), two = s.trial(2e-3);
    qInfo("indicator 1 mm %.4f, 2 mm %.4f", one.indicator, two.indicator);
    QVERIFY(!one.chatter);
    QVERIFY(two.chatter);
    QVERIFY(one.indicator < 1e-3);
    QVERIFY(two.indicator > 0.5);
  }

  void bisection() {
    MarginalDepthSettings set;
    set.tolerance_m = 0.05e-3;
    MarginalDepthSearch s(FaceMillingParameters{}, set);
    const MarginalDepthResult r = s.search();
    qInfo("marginal depth %.3f mm (%zu trials)", r.marginal_depth_m * 1e3, r.trials.size());
    QVERIFY(r.bracketed);
    QVERIFY(r.marginal_depth_m > 1e-3 && r.marginal_depth_m < 2e-3);
    QVERIFY(r.unstable_depth_m - r.stable_depth_m <= set.tolerance_m);
    QVERIFY(!s.trial(r.stable_depth_m).chatter);
  }

  void cancelAndValidation() {
    std::atomic<bool> cancel{true};
    JobControl job;
    job.cancel = &cancel;
    MarginalDepthSearch s(FaceMillingParameters{}, MarginalDepthSettings{});
    QVERIFY_THROWS_EXCEPTION(Cancelled, s.search(job));
    MarginalDepthSettings bad;
    bad.depth_high_m = bad.depth_low_m;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, (MarginalDepthSearch{FaceMillingParameters{}, bad}));
  }
};

MX_REGISTER_TEST(TestMarginalDepth)
#include "test_marginal_depth.moc"
