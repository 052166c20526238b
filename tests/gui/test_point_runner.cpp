// The readout thread: answers come back on the GUI thread; while one evaluation runs only the latest
// request waits, so a burst of requests ends with the answer to the last one, in fewer evaluations than
// requests; a replaced request's power-limit curve is computed for the request that replaced it.
#include <QSignalSpy>
#include <memory>

#include "point_runner.h"
#include "stability/zero_order_lobes.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
// The lobes of Rubio's R1 over 2000-6000 rpm (ZOA), as the chart's snapshot holds them.
std::shared_ptr<const gui::PointEvaluator> evaluatorOfR1() {
  auto snapshot = std::make_shared<gui::LobeSnapshot>();
  gui::ToolLobes tool;
  tool.setup = test::rubioR1();
  tool.margined =
      computeZoaLobes(tool.setup, SpeedGrid{2000.0 / 60.0, 6000.0 / 60.0, 10.0 / 60.0}.values(), ZoaOptions{});
  snapshot->tools.push_back(tool);
  return std::make_shared<gui::PointEvaluator>(snapshot, SpindlePowerCurve{});
}
}  // namespace

class TestPointRunner : public QObject {
  Q_OBJECT
 private slots:
  void theLastRequestGetsTheLastAnswer() {
    gui::PointRunner runner;
    const auto evaluator = evaluatorOfR1();
    QSignalSpy answers(&runner, &gui::PointRunner::evaluated);
    quint64 last = 0;
    for (int i = 0; i < 50; ++i) last = runner.submit({evaluator, 0, {2000.0 + 60.0 * i, 0.5, 0.1}, i == 0});
    QTRY_VERIFY(!runner.busy());
    int readouts = 0;
    bool curve = false;
    for (const QList<QVariant>& a : answers) {
      const auto r = a.front().value<gui::PointJobResult>();
      if (r.readout) ++readouts;
      curve = curve || r.power_limit_mm.has_value();
    }
    QVERIFY(readouts < 50);  // coalesced
    QVERIFY(curve);          // the first request's curve, computed for a later request
    gui::PointJobResult lastReadout;
    for (const QList<QVariant>& a : answers)
      if (auto r = a.front().value<gui::PointJobResult>(); r.readout) lastReadout = r;
    QCOMPARE(lastReadout.generation, last);
    QCOMPARE(lastReadout.readout->speed_rpm, 2000.0 + 60.0 * 49);
    const widgets::PointReadout direct = evaluator->evaluate(0, 2000.0 + 60.0 * 49, 0.5, 0.1);
    QCOMPARE(lastReadout.readout->peak_power_w, direct.peak_power_w);
    QCOMPARE(lastReadout.readout->blim_mm, direct.blim_mm);
  }
};

MX_REGISTER_TEST(TestPointRunner)
#include "test_point_runner.moc"
