// The non-dominated set (skyline and divide and conquer) equals the O(n^2) definition on random point sets (continuous,
// with ties on a coarse lattice, duplicates, anti-correlated fronts), and every returned point is non-dominated.
#include <random>

#include "pareto/pareto_front.h"
#include "test_registry.h"

using namespace mx;

namespace {
std::vector<ObjectiveVector> randomPoints(int n, int kind, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<ObjectiveVector> out;
  for (int i = 0; i < n; ++i) {
    ObjectiveVector p{u(rng), u(rng), u(rng), u(rng)};
    if (kind == 1)
      for (double& v : p) v = std::floor(v * 5.0) / 5.0;  // lattice: many ties and duplicates
    if (kind == 2) {                                      // anti-correlated: near the plane sum = 2 (large fronts)
      const double s = p[0] + p[1] + p[2] + p[3];
      for (double& v : p) v = v * 2.0 / s + 0.01 * u(rng);
    }
    if (kind == 4)  // two levels per objective: ties in every sweep dimension
      for (double& v : p) v = v < 0.5 ? 0.0 : 1.0;
    if (kind == 5) p = {u(rng), std::floor(u(rng) * 3.0), std::floor(u(rng) * 3.0), u(rng)};
    if (kind == 3 && i % 3 == 0 && i > 0) p = out[static_cast<std::size_t>(i - 1)];  // exact duplicates
    out.push_back(p);
  }
  return out;
}
}  // namespace

class TestParetoFront : public QObject {
  Q_OBJECT
 private slots:
  void matchesBruteForce_data() {
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("kind");
    QTest::addColumn<unsigned>("seed");
    QTest::newRow("empty") << 0 << 0 << 1u;
    QTest::newRow("one") << 1 << 0 << 1u;
    QTest::newRow("uniform 3000") << 3000 << 0 << 2u;
    QTest::newRow("lattice 3000") << 3000 << 1 << 3u;
    QTest::newRow("anti-correlated 2000") << 2000 << 2 << 4u;
    QTest::newRow("duplicates 3000") << 3000 << 3 << 5u;
    QTest::newRow("binary lattice 500") << 500 << 4 << 6u;
    QTest::newRow("ties in objectives 1, 2") << 3000 << 5 << 7u;
    QTest::newRow("anti-correlated 4000") << 4000 << 2 << 8u;
  }
  void matchesBruteForce() {
    QFETCH(int, n);
    QFETCH(int, kind);
    QFETCH(unsigned, seed);
    const auto pts = randomPoints(n, kind, seed);
    const auto fast = nonDominated(pts);
    QCOMPARE(fast, nonDominatedBruteForce(pts));
    QCOMPARE(nonDominatedDivideAndConquer(pts), fast);
    for (std::size_t i : fast)
      for (const ObjectiveVector& q : pts) QVERIFY(!dominates(q, pts[i]));
  }
  void dominance() {
    QVERIFY(dominates({1, 1, 1, 1}, {1, 1, 1, 0}));
    QVERIFY(!dominates({1, 1, 1, 1}, {1, 1, 1, 1}));
    QVERIFY(!dominates({1, 0, 1, 1}, {0, 1, 1, 1}));
  }
};

MX_REGISTER_TEST(TestParetoFront)
#include "test_pareto_front.moc"
