// SupervisorView: run / stop / compare, the operator's feed hold toggle and chatter button,
// the controller combo (signal on user change only), the running state, speed, metrics and the tabs;
// module L's time constant and restart mode (a signal per committed change, none from the setter).
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QImage>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "supervision_timeline.h"
#include "supervisor_comparison.h"
#include "supervisor_view.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
int darkPixels(const QImage& image) {
  int dark = 0;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2)
      if (qGray(image.pixel(x, y)) < 128) ++dark;
  return dark;
}
}  // namespace

class TestSupervisorView : public QObject {
  Q_OBJECT
 private slots:
  void runStopAndRunningState() {
    SupervisorView view;
    QSignalSpy run(&view, &SupervisorView::runRequested), stop(&view, &SupervisorView::stopRequested);
    QSignalSpy compare(&view, &SupervisorView::compareRequested);
    QVERIFY(!view.isRunning());
    QVERIFY(view.runButton()->isEnabled());
    QVERIFY(!view.stopButton()->isEnabled());
    QVERIFY(!view.feedHoldButton()->isEnabled());
    QVERIFY(!view.chatterButton()->isEnabled());
    QTest::mouseClick(view.runButton(), Qt::LeftButton);
    QCOMPARE(run.count(), 1);
    view.setRunning(true);
    QVERIFY(!view.runButton()->isEnabled());
    QVERIFY(view.stopButton()->isEnabled());
    QVERIFY(view.feedHoldButton()->isEnabled());
    QVERIFY(view.chatterButton()->isEnabled());
    QVERIFY(!view.controllerCombo()->isEnabled());
    QTest::mouseClick(view.stopButton(), Qt::LeftButton);
    QCOMPARE(stop.count(), 1);
    view.setRunning(false);
    QVERIFY(view.runButton()->isEnabled());
    QTest::mouseClick(view.compareButton(), Qt::LeftButton);
    QCOMPARE(compare.count(), 1);
    QCOMPARE(run.count(), 1);
  }

  void operatorButtons() {
    SupervisorView view;
    QSignalSpy hold(&view, &SupervisorView::feedHoldToggled), chatter(&view, &SupervisorView::chatterSignalled);
    QTest::mouseClick(view.feedHoldButton(), Qt::LeftButton);  // disabled while idle
    QTest::mouseClick(view.chatterButton(), Qt::LeftButton);
    QCOMPARE(hold.count() + chatter.count(), 0);
    view.setRunning(true);
    QTest::mouseClick(view.feedHoldButton(), Qt::LeftButton);
    QCOMPARE(hold.count(), 1);
    QCOMPARE(hold.at(0).at(0).toBool(), true);
    QVERIFY(view.feedHoldOn());
    QTest::mouseClick(view.chatterButton(), Qt::LeftButton);
    QCOMPARE(chatter.count(), 1);
    QTest::mouseClick(view.feedHoldButton(), Qt::LeftButton);
    QCOMPARE(hold.count(), 2);
    QCOMPARE(hold.at(1).at(0).toBool(), false);
    QVERIFY(!view.feedHoldOn());
    // A run that ends while holding releases the button without a signal.
    QTest::mouseClick(view.feedHoldButton(), Qt::LeftButton);
    QCOMPARE(hold.count(), 3);
    view.setRunning(false);
    QVERIFY(!view.feedHoldOn());
    QCOMPARE(hold.count(), 3);
  }

  void controllerComboAndSpeed() {
    SupervisorView view;
    QSignalSpy changed(&view, &SupervisorView::controllerChanged);
    QCOMPARE(view.controllerCombo()->count(), 3);
    QCOMPARE(view.controller(), QStringLiteral("none"));
    view.setController("smc2");
    QCOMPARE(view.controller(), QStringLiteral("smc2"));
    QCOMPARE(changed.count(), 0);
    QCOMPARE(view.controllerCombo()->currentText(), QStringLiteral("SMC II (job shop)"));
    view.controllerCombo()->setCurrentIndex(1);  // as the user would
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).toString(), QStringLiteral("smc1"));
    view.setControllers({"smc1", "smc2"});  // keeps the current one, no signal
    QCOMPARE(view.controller(), QStringLiteral("smc1"));
    QCOMPARE(changed.count(), 1);
    view.setController("unknown");
    QCOMPARE(view.controller(), QStringLiteral("smc1"));
    QCOMPARE(view.speedFactor(), 1.0);
    view.speedCombo()->setCurrentIndex(2);
    QCOMPARE(view.speedFactor(), 20.0);
    view.speedCombo()->setCurrentIndex(3);
    QCOMPARE(view.speedFactor(), 0.0);
  }

  void modelControllerSettings() {
    SupervisorView view;
    QSignalSpy tau(&view, &SupervisorView::timeConstantEdited), reset(&view, &SupervisorView::resetFeedEdited);
    QCOMPARE(view.timeConstantMs(), 200.0);  // the project file's defaults
    QCOMPARE(view.resetFeed(), QStringLiteral("model"));
    QCOMPARE(view.timeConstantSpin()->minimum(), 1.0);
    QCOMPARE(view.timeConstantSpin()->maximum(), 1e5);
    QVERIFY(!view.timeConstantSpin()->keyboardTracking());
    QVERIFY(!view.timeConstantSpin()->toolTip().isEmpty() && !view.resetFeedCombo()->toolTip().isEmpty());
    view.setModelController(350.0, "current");
    QCOMPARE(view.timeConstantMs(), 350.0);
    QCOMPARE(view.resetFeed(), QStringLiteral("current"));
    QCOMPARE(view.resetFeedCombo()->currentText(), QStringLiteral("from the current feed (bumpless)"));
    QCOMPARE(tau.count() + reset.count(), 0);
    view.resetFeedCombo()->setCurrentIndex(0);  // as the user would
    QCOMPARE(reset.count(), 1);
    QCOMPARE(reset.at(0).at(0).toString(), QStringLiteral("model"));
    view.timeConstantSpin()->stepUp();  // a step is a committed value
    QCOMPARE(tau.count(), 1);
    QCOMPARE(tau.at(0).at(0).toDouble(), 360.0);
    view.setRunning(true);  // a running cycle keeps its settings
    QVERIFY(!view.timeConstantSpin()->isEnabled() && !view.resetFeedCombo()->isEnabled());
    view.setRunning(false);
    QVERIFY(view.timeConstantSpin()->isEnabled() && view.resetFeedCombo()->isEnabled());
  }

  // Typed values count when committed (Enter): the edges of [1, 1e5] ms are taken, a value below is not.
  void timeConstantTyped_data() {
    QTest::addColumn<QString>("typed");
    QTest::addColumn<bool>("committed");
    QTest::addColumn<double>("shown");
    QTest::newRow("1 ms") << "1" << true << 1.0;
    QTest::newRow("100000 ms") << "100000" << true << 1e5;
    QTest::newRow("0.5 ms refused") << "0.5" << false << 200.0;
  }
  void timeConstantTyped() {
    QFETCH(QString, typed);
    QFETCH(bool, committed);
    QFETCH(double, shown);
    SupervisorView view;
    QSignalSpy tau(&view, &SupervisorView::timeConstantEdited);
    QDoubleSpinBox* spin = view.timeConstantSpin();
    spin->selectAll();
    QTest::keyClicks(spin, typed);
    QCOMPARE(spin->cleanText(), typed);
    QCOMPARE(tau.count(), 0);  // not per keystroke
    QTest::keyClick(spin, Qt::Key_Return);
    QCOMPARE(tau.count(), committed ? 1 : 0);
    if (committed) QCOMPARE(tau.at(0).at(0).toDouble(), shown);
    QCOMPARE(view.timeConstantMs(), shown);
  }

  void metricsStatusAndParts() {
    SupervisorView view;
    SupervisionMetricsView m;
    m.controller = "smc2";
    m.max_power_pct_of_limit = 98.6;
    m.overshoot_pct = 113.4;
    m.chatter_detected = true;
    m.chatter_time_s = 2.345;
    m.passes = 2;
    m.cycle_time_s = 11.7;
    view.setMetrics(m);
    const QString text = view.metricsText();
    QVERIFY2(text.contains(QStringLiteral("max. power 99 % of the limit")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("force overshoot 113 %")));
    QVERIFY(text.contains(QStringLiteral("chatter detected at 2.35 s")));
    QVERIFY(text.contains(QStringLiteral("2 pass(es)")));
    QVERIFY(text.contains(QStringLiteral("cycle time 11.70 s")));
    view.setStatus("Running SMC II, t = 3.2 s");
    QCOMPARE(view.statusText(), QStringLiteral("Running SMC II, t = 3.2 s"));
    QVERIFY(view.chartView() && view.timeline() && view.editor() && view.comparison());
    QCOMPARE(view.tabs()->count(), 3);
    QCOMPARE(view.tabs()->tabText(2), QStringLiteral("Edit chart"));
    // The chart follows the run's tokens.
    GrafcetChartData c;
    c.steps = {{1, "Init", true, {"L*"}}, {2, "Idle", false, {"A"}}};
    c.transitions = {{1, {1}, {2}, "1", 1}};
    view.chartView()->setChart(c);
    view.chartView()->setActiveSteps({2});
    QCOMPARE(view.chartView()->activeSteps(), QList<int>{2});
  }

  void rendersTheDock() {  // a look at the whole dock at 1080p-like size
    SupervisorView view;
    view.setAttribute(Qt::WA_DontShowOnScreen);
    GrafcetChartData c;
    c.name = "SMC I (transfer line)";
    c.steps = {{1, "Initialize modules", true, {"L*"}},
               {2, "No contact and no chatter", false, {"A", "B", "I", "J"}},
               {3, "Reset modules", false, {"A", "B", "L*"}},
               {4, "Contact and no chatter", false, {"A", "B", "I", "J", "L"}},
               {5, "Operator feed hold active", false, {"A", "B", "C"}}};
    c.transitions = {{1, {1}, {2}, "1", 1}, {2, {2}, {5}, "a", 1},     {3, {2}, {3}, "b", 2},    {4, {3}, {4}, "1", 1},
                     {5, {4}, {5}, "a", 1}, {6, {4}, {2}, "not b", 2}, {7, {5}, {2}, "not a", 1}};
    view.chartView()->setChart(c);
    view.editor()->setChart(c);
    view.chartView()->setActiveSteps({4});
    view.resize(1800, 900);
    view.show();
    const QImage chart = view.grab().toImage();
    QCOMPARE(chart.size(), QSize(1800, 900));
    QVERIFY(darkPixels(chart) > 2000);  // text, chart boxes and plot axes are drawn
    view.tabs()->setCurrentIndex(2);
    const QImage editor = view.grab().toImage();
    QVERIFY(darkPixels(editor) > 2000);
    QVERIFY(editor != chart);
    const QTemporaryDir dir;
    QVERIFY(editor.save(dir.filePath("supervisor_editor.png")));
    QCOMPARE(QImage(dir.filePath("supervisor_editor.png")).size(), editor.size());
  }
};

MX_REGISTER_TEST(TestSupervisorView)
#include "test_supervisor_view.moc"
