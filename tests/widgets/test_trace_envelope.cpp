// traceEnvelope: one min/max pair per pixel column whatever the number of samples, the extremes of the
// samples in range kept exactly, non-finite values and samples out of range skipped, the band spanning
// the first and last samples; samplesIn counts the samples of a range.
#include <cmath>
#include <limits>
#include <vector>

#include "support/test_constants.h"
#include "test_registry.h"
#include "trace_envelope.h"

using mx::widgets::samplesIn;
using mx::widgets::TraceEnvelope;
using mx::widgets::traceEnvelope;

namespace {
using mx::test::kInf;
using mx::test::kNaN;

// A chattering trace: 60 revolutions' worth of samples at 10 us.
void chatter(std::vector<double>& t, std::vector<double>& v, int n) {
  for (int i = 0; i < n; ++i) {
    t.push_back(i * 1e-5);
    v.push_back(75.0 * std::sin(2.0 * M_PI * 650.0 * t.back()) * (1.0 - std::exp(-t.back() / 0.02)));
  }
}
}  // namespace

class TestTraceEnvelope : public QObject {
  Q_OBJECT
 private slots:
  void longTraceKeepsItsExtremesInTwoPointsPerColumn() {
    std::vector<double> t, v;
    chatter(t, v, 20000);
    const int columns = 780;
    const TraceEnvelope e = traceEnvelope(t, v, t.front(), t.back(), columns);
    QCOMPARE(static_cast<int>(e.t.size()), columns);  // every column holds ~25 samples
    QCOMPARE(e.lower.size(), e.t.size());
    QCOMPARE(e.upper.size(), e.t.size());
    QCOMPARE(*std::min_element(e.lower.begin(), e.lower.end()), *std::min_element(v.begin(), v.end()));
    QCOMPARE(*std::max_element(e.upper.begin(), e.upper.end()), *std::max_element(v.begin(), v.end()));
    QCOMPARE(e.t.front(), t.front());
    QCOMPARE(e.t.back(), t.back());
    QVERIFY(std::is_sorted(e.t.begin(), e.t.end()));
    for (std::size_t k = 0; k < e.t.size(); ++k) QVERIFY(e.lower[k] <= e.upper[k]);
  }

  // Each bucket's pair is the min and max of exactly its own samples.
  void bucketsHoldTheirOwnSamples() {
    const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7};
    const std::vector<double> v{3, -1, 4, 1, -5, 9, 2, 6};
    const TraceEnvelope e = traceEnvelope(t, v, 0.0, 8.0, 4);  // two samples per bucket
    QCOMPARE(e.t, (std::vector<double>{0.0, 2.5, 4.5, 7.0}));
    QCOMPARE(e.lower, (std::vector<double>{-1, 1, -5, 2}));
    QCOMPARE(e.upper, (std::vector<double>{3, 4, 9, 6}));
  }

  // Zoomed in: only the samples in [t0, t1] count, the rest's extremes do not leak in.
  void samplesOutsideTheRangeAreSkipped() {
    const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7};
    const std::vector<double> v{100, -1, 4, 1, -5, 9, 2, -100};
    const TraceEnvelope e = traceEnvelope(t, v, 1.0, 6.0, 2);
    QCOMPARE(e.lower, (std::vector<double>{-1, -5}));
    QCOMPARE(e.upper, (std::vector<double>{4, 9}));
    QCOMPARE(e.t.front(), 1.0);
    QCOMPARE(e.t.back(), 6.0);
    QCOMPARE(samplesIn(t, 1.0, 6.0), std::size_t{6});
    QCOMPARE(samplesIn(t, 1.5, 1.7), std::size_t{0});
    QCOMPARE(samplesIn(t, 6.0, 1.0), std::size_t{0});
  }

  void degenerateInputs_data() {
    QTest::addColumn<std::vector<double>>("time");
    QTest::addColumn<std::vector<double>>("value");
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::addColumn<int>("columns");
    QTest::addColumn<std::vector<double>>("lower");
    QTest::addColumn<std::vector<double>>("upper");
    using V = std::vector<double>;
    QTest::newRow("no samples") << V{} << V{} << 0.0 << 1.0 << 10 << V{} << V{};
    QTest::newRow("no column") << V{0, 1} << V{1, 2} << 0.0 << 1.0 << 0 << V{} << V{};
    QTest::newRow("empty range") << V{0, 1} << V{1, 2} << 1.0 << 1.0 << 10 << V{} << V{};
    QTest::newRow("reversed range") << V{0, 1} << V{1, 2} << 1.0 << 0.0 << 10 << V{} << V{};
    QTest::newRow("infinite range") << V{0, 1} << V{1, 2} << 0.0 << kInf << 10 << V{} << V{};
    QTest::newRow("one sample") << V{0.5} << V{7} << 0.0 << 1.0 << 10 << V{7} << V{7};
    QTest::newRow("fewer samples than columns")
        << V{0, 0.5, 1} << V{1, -2, 3} << 0.0 << 1.0 << 10 << V{1, -2, 3} << V{1, -2, 3};
    QTest::newRow("last sample in the last column")
        << V{0, 0.5, 1} << V{1, -2, 3} << 0.0 << 1.0 << 2 << V{1, -2} << V{1, 3};
    QTest::newRow("non-finite values skipped")
        << V{0, 1, 2, 3} << V{kNaN, 5, kInf, -kInf} << 0.0 << 4.0 << 1 << V{5} << V{5};
    QTest::newRow("only non-finite values") << V{0, 1} << V{kNaN, kNaN} << 0.0 << 2.0 << 1 << V{} << V{};
    QTest::newRow("shorter value list") << V{0, 1, 2} << V{4} << 0.0 << 3.0 << 3 << V{4} << V{4};
  }
  void degenerateInputs() {
    QFETCH(std::vector<double>, time);
    QFETCH(std::vector<double>, value);
    QFETCH(double, t0);
    QFETCH(double, t1);
    QFETCH(int, columns);
    QFETCH(std::vector<double>, lower);
    QFETCH(std::vector<double>, upper);
    const TraceEnvelope e = traceEnvelope(time, value, t0, t1, columns);
    QCOMPARE(e.lower, lower);
    QCOMPARE(e.upper, upper);
    QCOMPARE(e.t.size(), lower.size());
  }
};

MX_REGISTER_TEST(TestTraceEnvelope)
#include "test_trace_envelope.moc"
