// The SDNRP surface-finish panel: the Ra, disturbance and duration controls (clamping, no signal from
// the setters, one debounced runRequested after user changes, Run), the streamed plots, the summary
// with units and the feed-saturation warning; the run without SDNRP drawn dashed beside the run, named
// in the legends, in the axis ranges and the summary, and cleared on its own.
#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <cmath>
#include <limits>

#include "support/shown_texts.h"
#include "support/test_constants.h"
#include "surface_finish_panel.h"
#include "test_registry.h"

using mx::widgets::SurfaceFinishPanel;
using mx::widgets::SurfaceFinishSample;
using mx::widgets::SurfaceFinishSummary;

namespace {
using mx::test::kDash;
using mx::test::kNaN;
const QStringList kSummaryKeys = {"ra_desired_um",   "fd_n",           "f_final_n",      "feed_final_mm_min",
                                  "speed_final_rpm", "ra_produced_um", "ra_baseline_um", "f_baseline_n"};
const QStringList kDataGraphs = {"ra", "ra_dynamic", "force", "force_dynamic", "feed", "speed"};

QVector<SurfaceFinishSample> ramp(int n, double t0, double dt) {
  QVector<SurfaceFinishSample> out;
  for (int i = 0; i < n; ++i) {
    const double t = t0 + i * dt;
    out.push_back({t, 0.8 + 0.01 * i, 0.82 + 0.01 * i, 400.0 + i, 410.0 + i, 300.0 + 2.0 * i, 2000.0});
  }
  return out;
}

// Waits past the debounce interval, processing events.
void waitPastDebounce() {
  QTest::qWait(SurfaceFinishPanel::kDebounceMs + 200);
}
}  // namespace

class TestSurfaceFinishPanel : public QObject {
  Q_OBJECT
 private slots:
  void defaults() {
    SurfaceFinishPanel panel;
    QCOMPARE(panel.durationS(), 15.0);
    QCOMPARE(panel.desiredRaUm(), SurfaceFinishPanel::kDefaultRaUm);
    QVERIFY(!panel.disturbanceOn());
    QCOMPARE(panel.sampleCount(), 0);
    QVERIFY(panel.runButton()->isEnabled());
    QVERIFY(!panel.warningShown());
    for (const QString& key : kSummaryKeys) QCOMPARE(panel.summaryText(key), kDash);
    QCOMPARE(panel.summaryText("no_such_key"), QString());
    QCOMPARE(panel.timeAxisUpper(), 15.0);
    QCOMPARE(panel.raSpin()->objectName(), QString("surfaceFinishRa"));
    QCOMPARE(panel.runButton()->objectName(), QString("surfaceFinishRun"));
  }

  void raClamps_data() {
    QTest::addColumn<double>("input");
    QTest::addColumn<double>("expected");
    QTest::newRow("below min") << 0.1 << 0.25;
    QTest::newRow("zero") << 0.0 << 0.25;
    QTest::newRow("negative") << -1.0 << 0.25;
    QTest::newRow("at min") << 0.25 << 0.25;
    QTest::newRow("inside") << 1.2 << 1.2;
    QTest::newRow("at max") << 2.5 << 2.5;
    QTest::newRow("above max") << 3.0 << 2.5;
    QTest::newRow("+inf") << std::numeric_limits<double>::infinity() << 2.5;
    QTest::newRow("NaN keeps the value") << kNaN << SurfaceFinishPanel::kDefaultRaUm;
  }
  void raClamps() {
    QFETCH(double, input);
    QFETCH(double, expected);
    SurfaceFinishPanel panel;
    panel.setDesiredRaUm(input);
    QCOMPARE(panel.desiredRaUm(), expected);
    QCOMPARE(panel.raSpin()->minimum(), SurfaceFinishPanel::kMinRaUm);
    QCOMPARE(panel.raSpin()->maximum(), SurfaceFinishPanel::kMaxRaUm);
  }

  void durationClamps_data() {
    QTest::addColumn<double>("input");
    QTest::addColumn<double>("expected");
    QTest::newRow("below 1") << 0.5 << 1.0;
    QTest::newRow("1") << 1.0 << 1.0;
    QTest::newRow("30") << 30.0 << 30.0;
    QTest::newRow("120") << 120.0 << 120.0;
    QTest::newRow("above 120") << 500.0 << 120.0;
  }
  void durationClamps() {
    QFETCH(double, input);
    QFETCH(double, expected);
    SurfaceFinishPanel panel;
    panel.setDurationS(input);
    QCOMPARE(panel.durationS(), expected);
    QCOMPARE(panel.timeAxisUpper(), expected);  // x axis [0, duration]
  }

  void settersDoNotSignal() {
    SurfaceFinishPanel panel;
    QSignalSpy spy(&panel, &SurfaceFinishPanel::runRequested);
    panel.setDesiredRaUm(1.5);
    panel.setDisturbanceOn(true);
    panel.setDurationS(30.0);
    QVERIFY(panel.disturbanceOn());
    waitPastDebounce();
    QCOMPARE(spy.count(), 0);
  }

  void userChangeIsDebounced_data() {
    QTest::addColumn<int>("control");  // 0 Ra, 1 disturbance, 2 duration, 3 all three in a burst
    QTest::newRow("Ra") << 0;
    QTest::newRow("disturbance") << 1;
    QTest::newRow("duration") << 2;
    QTest::newRow("burst of changes") << 3;
  }
  void userChangeIsDebounced() {
    QFETCH(int, control);
    SurfaceFinishPanel panel;
    QSignalSpy spy(&panel, &SurfaceFinishPanel::runRequested);
    if (control == 0 || control == 3) panel.raSpin()->setValue(1.25);
    if (control == 1 || control == 3) panel.disturbanceBox()->setChecked(true);
    if (control == 2 || control == 3) panel.durationSpin()->setValue(20.0);
    if (control == 3) panel.raSpin()->setValue(1.5);
    QCOMPARE(spy.count(), 0);  // not before the debounce interval
    QTest::qWait(SurfaceFinishPanel::kDebounceMs / 2);
    QCOMPARE(spy.count(), 0);
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 1, 2000);
    waitPastDebounce();
    QCOMPARE(spy.count(), 1);  // exactly once
  }

  void runButton() {
    SurfaceFinishPanel panel;
    QSignalSpy spy(&panel, &SurfaceFinishPanel::runRequested);
    panel.runButton()->click();
    QCOMPARE(spy.count(), 1);
    // A pending debounced change is taken by the Run click: no second request.
    panel.raSpin()->setValue(2.0);
    panel.runButton()->click();
    QCOMPARE(spy.count(), 2);
    waitPastDebounce();
    QCOMPARE(spy.count(), 2);
  }

  void busy() {
    SurfaceFinishPanel panel;
    panel.setBusy(true);
    QVERIFY(panel.busy());
    QVERIFY(!panel.runButton()->isEnabled());
    QVERIFY(panel.statusText().contains("running..."));
    panel.setBusy(false);
    QVERIFY(panel.runButton()->isEnabled());
    QVERIFY(!panel.statusText().contains("running"));
  }

  void appendSamples() {
    SurfaceFinishPanel panel;
    panel.setBusy(true);
    panel.appendSamples(ramp(10, 0.0, 0.1));
    QCOMPARE(panel.sampleCount(), 10);
    for (const QString& g : kDataGraphs) QCOMPARE(panel.graphDataCount(g), 10);
    panel.appendSamples(ramp(5, 1.0, 0.1));
    QCOMPARE(panel.sampleCount(), 15);
    for (const QString& g : kDataGraphs) QCOMPARE(panel.graphDataCount(g), 15);
    QCOMPARE(panel.graphDataCount("ra_desired"), 2);  // dashed line over [0, duration]
    QCOMPARE(panel.graphDataCount("fd"), 0);          // known with the summary
    QCOMPARE(panel.graphDataCount("nope"), -1);
    QCOMPARE(panel.timeAxisUpper(), 15.0);
    QVERIFY(panel.statusText().contains("running..."));
    panel.appendSamples({});
    QCOMPARE(panel.sampleCount(), 15);
  }

  void samplesBeyondDurationWidenTheAxis() {
    SurfaceFinishPanel panel;
    panel.setDurationS(2.0);
    panel.appendSamples(ramp(4, 1.0, 1.0));  // t = 1..4 s
    QCOMPARE(panel.timeAxisUpper(), 4.0);
  }

  void nonFiniteValuesAreSkipped() {
    SurfaceFinishPanel panel;
    panel.appendSamples({{0.0, kNaN, 0.8, 400.0, 400.0, 300.0, 2000.0}, {kNaN, 0.8, 0.8, 400.0, 400.0, 300.0, 2000.0}});
    QCOMPARE(panel.sampleCount(), 1);  // a sample without time is dropped
    QCOMPARE(panel.graphDataCount("ra"), 0);
    QCOMPARE(panel.graphDataCount("ra_dynamic"), 1);
  }

  void summary_data() {
    QTest::addColumn<bool>("saturated");
    QTest::newRow("reached") << false;
    QTest::newRow("feed saturated") << true;
  }
  void summary() {
    QFETCH(bool, saturated);
    SurfaceFinishPanel panel;
    panel.setBusy(true);
    panel.appendSamples(ramp(20, 0.0, 0.5));
    SurfaceFinishSummary s;
    s.ra_desired_um = 0.8;
    s.fd_n = 512.345;
    s.f_final_n = 509.87;
    s.feed_final_mm_min = 1234.56;
    s.speed_final_rpm = 2000.0;
    s.ra_produced_um = 0.81234;
    s.feed_saturated = saturated;
    panel.setSummary(s);
    panel.setBusy(false);
    QCOMPARE(panel.summaryText("ra_desired_um"), QString("0.8000"));
    QCOMPARE(panel.summaryText("fd_n"), QString("512.3"));
    QCOMPARE(panel.summaryText("f_final_n"), QString("509.9"));
    QCOMPARE(panel.summaryText("feed_final_mm_min"), QString("1235"));
    QCOMPARE(panel.summaryText("speed_final_rpm"), QString("2000"));
    QCOMPARE(panel.summaryText("ra_produced_um"), QString("0.8123"));
    QCOMPARE(panel.graphDataCount("fd"), 2);
    QVERIFY(panel.graphInLegend("fd"));
    QVERIFY(panel.graphName("fd").contains("512.3 N"));
    QVERIFY(panel.graphName("ra_desired").contains("0.8000 \u00b5m"));
    QCOMPARE(panel.warningShown(), saturated);
    if (saturated) {
      QVERIFY(panel.warningText().contains("F_d not reachable within the feed limits"));
      QVERIFY(panel.warningText().contains("1235 mm/min"));
    }
    QVERIFY(panel.statusText().contains("0.8123 \u00b5m"));

    panel.clear();
    QCOMPARE(panel.sampleCount(), 0);
    for (const QString& g : kDataGraphs) QCOMPARE(panel.graphDataCount(g), 0);
    QCOMPARE(panel.graphDataCount("fd"), 0);
    QVERIFY(!panel.graphInLegend("fd"));
    QVERIFY(!panel.warningShown());
    for (const QString& key : kSummaryKeys) QCOMPARE(panel.summaryText(key), kDash);
  }

  void desiredLineFollowsRa() {
    SurfaceFinishPanel panel;
    panel.setDesiredRaUm(1.6);
    QVERIFY(panel.graphName("ra_desired").contains("1.600 \u00b5m"));
  }

  void labelsAxesAndLegends() {
    SurfaceFinishPanel panel;
    const QStringList axes = panel.axisLabels();
    QCOMPARE(axes.size(), 8);
    for (int i = 0; i < axes.size(); i += 2) QCOMPARE(axes[i], QString("Time t [s]"));
    QVERIFY(axes[1].contains("[\u00b5m]"));
    QVERIFY(axes[3].contains("[N]"));
    QVERIFY(axes[5].contains("[mm/min]"));
    QVERIFY(axes[7].contains("[rpm]"));
    for (const QString& a : axes) QVERIFY2(a.contains('[') && a.contains(']'), qPrintable(a));
    for (const QString& g : kDataGraphs) {
      QVERIFY2(panel.graphInLegend(g), qPrintable(g));
      QVERIFY2(panel.graphName(g).contains('['), qPrintable(g));
    }
    QVERIFY(panel.graphInLegend("ra_desired"));
    // Every label naming a quantity (ends with ':') carries a unit; controls have tooltips.
    for (const QLabel* l : panel.findChildren<QLabel*>())
      if (l->text().endsWith(':')) QVERIFY2(l->text().contains('[') && l->text().contains(']'), qPrintable(l->text()));
    for (QWidget* w : {static_cast<QWidget*>(panel.raSpin()), static_cast<QWidget*>(panel.disturbanceBox()),
                       static_cast<QWidget*>(panel.durationSpin()), static_cast<QWidget*>(panel.runButton())})
      QVERIFY(!w->toolTip().isEmpty());
  }

  void baselineBesideTheRun() {
    SurfaceFinishPanel panel;
    QVERIFY(panel.compareOn());  // compared by default
    QVERIFY(!panel.compareBox()->toolTip().isEmpty());
    QSignalSpy spy(&panel, &SurfaceFinishPanel::runRequested);
    panel.setCompareOn(false);
    QVERIFY(!panel.compareOn());
    QCOMPARE(spy.count(), 0);  // no signal from the setter
    const QStringList baseline = {"ra_baseline", "force_baseline", "feed_baseline", "speed_baseline"};
    for (const QString& g : baseline) {
      QCOMPARE(panel.graphDataCount(g), 0);
      QVERIFY2(!panel.graphInLegend(g), qPrintable(g));
    }
    panel.appendSamples(ramp(20, 0.0, 0.5));  // F 400..429 N
    SurfaceFinishSummary s;
    s.ra_desired_um = 0.81;
    s.fd_n = 410.0;
    s.f_final_n = 410.1;
    s.ra_produced_um = 0.812;
    panel.setSummary(s);
    // Without SDNRP: constant feed 430.41 mm/min and speed 1571 rpm, F 500..519 N with the disturbance.
    QVector<SurfaceFinishSample> held;
    for (int i = 0; i < 20; ++i) held.push_back({0.5 * i, 1.9, 1.95 + 0.01 * i, 480.0, 500.0 + i, 430.41, 1571.0});
    SurfaceFinishSummary b = s;
    b.f_final_n = 509.5;
    b.ra_produced_um = 1.9723;
    panel.setBaseline(held, b);
    QCOMPARE(panel.baselineSampleCount(), 20);
    const int plot[] = {0, 1, 2, 3};
    for (int i = 0; i < baseline.size(); ++i) {
      const QString& g = baseline[i];
      QCOMPARE(panel.graphDataCount(g), 20);
      QVERIFY2(panel.graphInLegend(g), qPrintable(g));
      QCOMPARE(panel.graphPenStyle(g), Qt::DashLine);
      QVERIFY2(panel.graphName(g).contains("no SDNRP") && panel.graphName(g).contains('['), qPrintable(g));
      QCOMPARE(panel.graphPlot(g), plot[i]);
    }
    for (const QString& g : kDataGraphs) {
      QCOMPARE(panel.graphPenStyle(g), Qt::SolidLine);
      QVERIFY2(panel.graphName(g).contains("SDNRP") && !panel.graphName(g).contains("no SDNRP"), qPrintable(g));
    }
    QCOMPARE(panel.graphPlot("ra"), 0);
    QCOMPARE(panel.graphPlot("nope"), -1);
    QCOMPARE(panel.graphPenStyle("nope"), Qt::NoPen);
    // the measured (dynamic) F and Ra are drawn, the feed and speed as held
    QCOMPARE(panel.graphValueRange("force_baseline")->first, 500.0);
    QCOMPARE(panel.graphValueRange("force_baseline")->second, 519.0);
    QCOMPARE(panel.graphValueRange("ra_baseline")->second, 1.95 + 0.01 * 19);
    QCOMPARE(panel.graphValueRange("feed_baseline")->first, 430.41);
    QCOMPARE(panel.graphValueRange("feed_baseline")->second, 430.41);
    QCOMPARE(panel.graphValueRange("speed_baseline")->first, 1571.0);
    QVERIFY(!panel.graphValueRange("nope"));
    QCOMPARE(panel.valueAxisUpper(1), 519.0 * 1.1);  // the axes hold both runs
    QCOMPARE(panel.valueAxisUpper(0), (1.95 + 0.01 * 19) * 1.1);
    QCOMPARE(panel.summaryText("ra_baseline_um"), QString("1.972"));
    QCOMPARE(panel.summaryText("f_baseline_n"), QString("509.5"));
    QCOMPARE(panel.summaryText("ra_produced_um"), QString("0.8120"));
    QVERIFY2(panel.statusText().contains("without SDNRP (constant feed) 1.972 \u00b5m"),
             qPrintable(panel.statusText()));

    panel.clearBaseline();  // the run stays
    QCOMPARE(panel.baselineSampleCount(), 0);
    QCOMPARE(panel.sampleCount(), 20);
    QCOMPARE(panel.graphDataCount("force"), 20);
    for (const QString& g : baseline) {
      QCOMPARE(panel.graphDataCount(g), 0);
      QVERIFY(!panel.graphInLegend(g));
    }
    QCOMPARE(panel.valueAxisUpper(1), 429.0 * 1.1);
    QCOMPARE(panel.summaryText("ra_baseline_um"), kDash);
    QCOMPARE(panel.summaryText("ra_produced_um"), QString("0.8120"));
    QVERIFY(!panel.statusText().contains("without SDNRP"));

    panel.setBaseline(held, b);
    panel.clear();  // clears both
    QCOMPARE(panel.baselineSampleCount(), 0);
    QCOMPARE(panel.graphDataCount("force_baseline"), 0);
    QCOMPARE(panel.summaryText("f_baseline_n"), kDash);
  }

  void showsAt1080p() {
    SurfaceFinishPanel panel;
    panel.resize(1920, 1000);
    panel.appendSamples(ramp(100, 0.0, 0.15));
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(panel.minimumSizeHint().width() <= 1920);
    QVERIFY(panel.minimumSizeHint().height() <= 1000);
  }
};

MX_REGISTER_TEST(TestSurfaceFinishPanel)
#include "test_surface_finish_panel.moc"
