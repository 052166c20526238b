// Eq. 18-20 over a candidate set: normalisation by the set's maxima, weights, and the choice of q**.
#include <cmath>

#include "core/invalid_input.h"
#include "expert/resultant_cost.h"
#include "test_registry.h"

using namespace mx;

namespace {
RefinementCandidate candidate(double cost, double ts, double mp, double r12, double r1ch, double speed) {
  RefinementCandidate c;
  c.cost = cost;
  c.metrics.settling_time_s = ts;
  c.metrics.overshoot = mp;
  c.metrics.r12h = r12;
  c.metrics.r1ch = r1ch;
  c.q.speed_rev_per_s = speed;
  c.q.mrr_m3_per_s = 1.0;
  return c;
}
}  // namespace

class TestResultantCost : public QObject {
  Q_OBJECT
 private slots:
  void normalisedTerms() {
    std::vector<RefinementCandidate> cs{candidate(1.0, 0.02, 0.5, 0.4, 0.01, 90),
                                        candidate(1.01, 0.01, 0.25, 0.2, 0.02, 95)};
    CostWeights w;  // cr (0.8, 0.1, 0.1), ct = cf = (0.5, 0.5)
    const std::size_t best = selectByResultantCost(cs, w);
    QCOMPARE_LE(std::abs(cs[0].time_cost - 1.0), 1e-15);        // 0.5 * 1 + 0.5 * 1
    QCOMPARE_LE(std::abs(cs[1].time_cost - 0.5), 1e-15);        // 0.5 * 0.5 + 0.5 * 0.5
    QCOMPARE_LE(std::abs(cs[0].frequency_cost - 0.75), 1e-15);  // 0.5 * 1 + 0.5 * 0.5
    QCOMPARE_LE(std::abs(cs[1].frequency_cost - 0.75), 1e-15);  // 0.5 * 0.5 + 0.5 * 1
    QCOMPARE_LE(std::abs(cs[0].resultant - (0.8 + 0.1 + 0.075)), 1e-12);
    QCOMPARE_LE(std::abs(cs[1].resultant - (0.808 + 0.05 + 0.075)), 1e-12);
    QCOMPARE(best, std::size_t(1));  // the better transient outweighs 1 % of C
    w.cr = {1.0, 0.0, 0.0};          // C only: q** = q*
    QCOMPARE(selectByResultantCost(cs, w), std::size_t(0));
  }

  void zeroMaximaGiveZeroTerms() {
    std::vector<RefinementCandidate> cs{candidate(2.0, 0, 0, 0, 0, 90)};
    QCOMPARE(selectByResultantCost(cs, CostWeights{}), std::size_t(0));
    QCOMPARE(cs[0].time_cost, 0.0);
    QCOMPARE(cs[0].frequency_cost, 0.0);
    QCOMPARE_LE(std::abs(cs[0].resultant - 1.6), 1e-15);
    std::vector<RefinementCandidate> none;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, selectByResultantCost(none, CostWeights{}));
  }
};

MX_REGISTER_TEST(TestResultantCost)
#include "test_resultant_cost.moc"
