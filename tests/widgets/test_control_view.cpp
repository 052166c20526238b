// ControlView: the beta slider and spin box stay in sync and emit one debounced betaChanged
// per user change; the closed-loop traces fill the stacked plots (shared time axis, labelled rows, feed
// limit); metrics show as text with units; settings and workpiece round trip without signals; the
// figures 9-12 export writes a PNG of the requested size. At 1080p (a bottom dock of 1920 x 430) the
// stacked rows keep their height and scroll, J_c and the pole-zero map stand side by side, and no legend
// covers a plot or cuts a name.
#include <qcustomplot.h>

#include <QApplication>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "control_metrics_panel.h"
#include "control_plots.h"
#include "control_settings_editor.h"
#include "control_view.h"
#include "display_units.h"
#include "jc_curve_plot.h"
#include "pole_zero_plot.h"
#include "support/plot_layout_checks.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
constexpr double kPeriod = 0.01;  // sampling period [s]
constexpr double kRef = 1200.0;

double depthAt(double t) {
  return t < 1.0 ? 1.0 : t < 1.8 ? 2.0 : t < 2.4 ? 1.5 : 0.5;
}

// A plausible closed loop: the force follows the reference, with a decaying oscillation after each depth
// step proportional to the depth ratio; the feed compensates the depth.
double forceAt(double t) {
  double f = kRef * (1.0 - std::exp(-t / 0.08) * std::cos(2.0 * M_PI * 3.0 * t));
  const double steps[] = {1.0, 1.8, 2.4};
  for (double ts : steps)
    if (t >= ts) {
      const double ratio = depthAt(ts) / depthAt(ts - 1e-9) - 1.0;
      f += kRef * ratio * std::exp(-(t - ts) / 0.06) * std::cos(2.0 * M_PI * 5.0 * (t - ts));
    }
  return f;
}

double feedAt(double t) {
  return std::clamp(12.0 / depthAt(t) * (1.0 - std::exp(-t / 0.05)), 0.0, 30.0);
}

ControlTraces syntheticTraces(int samples = 300, int dense_per_sample = 10, int n_theta = 4) {
  ControlTraces c;
  const QStringList names = {"a1", "a2", "b0", "b1", "b2"};
  c.theta_names = names.mid(0, n_theta);
  for (int k = 0; k < samples; ++k) {
    const double t = k * kPeriod;
    c.t_s << t;
    c.reference_n << kRef;
    c.model_n << kRef * (1.0 - std::exp(-t / 0.06) * (1.0 + t / 0.06));
    c.force_sampled_n << forceAt(t);
    c.error_n << c.force_sampled_n.back() - c.model_n.back();
    c.feed_mm_s << feedAt(t);
    QVector<double> theta;
    for (int j = 0; j < n_theta; ++j) theta << 0.2 + (0.5 - 0.3 * j) * (1.0 - std::exp(-t / 0.3));
    c.theta << theta;
    for (int i = 0; i < dense_per_sample; ++i) {
      const double frac = static_cast<double>(i) / dense_per_sample, td = t + frac * kPeriod;
      c.dense_t_s << td;
      c.dense_force_n << forceAt(td) + 60.0 * std::sin(M_PI * frac) * std::exp(-td);
      c.dense_feed_mm_s << feedAt(td);
    }
  }
  c.depth_t_s = {0.0, 1.0, 1.8, 2.4, samples * kPeriod};
  c.depth_mm = {1.0, 2.0, 1.5, 0.5, 0.5};
  return c;
}

// A view with every legend entry there is: five estimates, programme changes, an unstable zero and the
// current beta in the unstable-zero region (the longest J_c entry).
void fillForLayout(ControlView& view) {
  view.setBeta(-0.8);
  ControlTraces t = syntheticTraces(300, 10, 5);
  t.change_t_s = {1.0, 1.8};
  view.setTraces(t);
  JcCurveView c;
  for (int i = 0; i <= 40; ++i) {
    c.beta << -1.0 + 0.05 * i;
    c.jc_n_s << 2000.0 + 9000.0 * (c.beta.back() + 0.3) * (c.beta.back() + 0.3);
  }
  c.best_beta = -0.3;
  c.threshold_beta = -0.62;
  view.setJcCurve(c);
  ControlMetricsView m;
  m.jc_n_s = 12345.6;
  view.setMetrics(m);
  view.setPoleZero({{{0.0, 0.0}, {0.0, 0.0}, {0.61, 0.0}}, {{-0.4, 0.0}, {-1.3, 0.0}}});
}

QCustomPlot* plotIn(const QWidget* widget) {
  return widget->findChild<QCustomPlot*>();
}

// The entries a legend draws (a re-flowed legend can have empty cells).
int drawnEntries(const QCPLegend* legend) {
  int n = 0;
  for (int i = 0; i < legend->itemCount(); ++i) n += legend->item(i) ? 1 : 0;
  return n;
}

// Shows the view at `size` and lets the plots settle: a layout can refit the legends and resize the rows.
bool showAt(QWidget& view, const QSize& size) {
  view.resize(size);
  view.show();
  if (!QTest::qWaitForWindowExposed(&view)) return false;
  QTest::qWait(100);
  for (QCustomPlot* plot : view.findChildren<QCustomPlot*>()) plot->replot();
  return true;
}
}  // namespace

class TestControlView : public QObject {
  Q_OBJECT
 private slots:
  void betaSliderAndSpinStayInSync_data() {
    QTest::addColumn<double>("beta");
    QTest::addColumn<int>("ticks");
    QTest::addColumn<double>("shown");
    QTest::newRow("paper best") << -0.3 << -30 << -0.3;
    QTest::newRow("ZOH") << 0.0 << 0 << 0.0;
    QTest::newRow("FOH") << 1.0 << 100 << 1.0;
    QTest::newRow("lower end") << -1.0 << -100 << -1.0;
    QTest::newRow("rounded to 0.01") << 0.304 << 30 << 0.3;
    QTest::newRow("clamped above") << 1.7 << 100 << 1.0;
    QTest::newRow("clamped below") << -3.0 << -100 << -1.0;
    QTest::newRow("NaN: 0") << std::nan("") << 0 << 0.0;
  }
  void betaSliderAndSpinStayInSync() {
    QFETCH(double, beta);
    QFETCH(int, ticks);
    QFETCH(double, shown);
    ControlView view;
    QSignalSpy spy(&view, &ControlView::betaChanged);
    view.setBeta(beta);
    QCOMPARE(view.betaSlider()->value(), ticks);
    QCOMPARE(view.betaSpin()->value(), shown);
    QCOMPARE(view.beta(), shown);
    QTest::qWait(250);
    QCOMPARE(spy.count(), 0);  // setBeta emits nothing
    QCOMPARE(view.jcPlot()->currentBeta(), shown);
  }

  void userMovesEmitOnceDebounced() {
    ControlView view;
    QSignalSpy spy(&view, &ControlView::betaChanged);
    view.betaSlider()->setValue(10);  // as a drag or key press does
    view.betaSlider()->setValue(20);
    view.betaSlider()->setValue(35);
    QCOMPARE(view.betaSpin()->value(), 0.35);
    QCOMPARE(spy.count(), 0);                      // not before the debounce
    QCOMPARE(view.jcPlot()->currentBeta(), 0.35);  // the marker follows at once
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 1, 1000);
    QCOMPARE(spy.at(0).at(0).toDouble(), 0.35);
    QTest::qWait(300);
    QCOMPARE(spy.count(), 1);

    view.betaSpin()->setValue(-0.3);  // the spin box drives the slider
    QCOMPARE(view.betaSlider()->value(), -30);
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 2, 1000);
    QCOMPARE(spy.at(1).at(0).toDouble(), -0.3);

    // Back and forth to the emitted value: nothing to recompute.
    view.betaSlider()->setValue(-29);
    view.betaSlider()->setValue(-30);
    QTest::qWait(300);
    QCOMPARE(spy.count(), 2);
  }

  void releaseEmitsAtOnce() {
    ControlView view;
    QSignalSpy spy(&view, &ControlView::betaChanged);
    view.betaSlider()->setSliderDown(true);
    view.betaSlider()->setValue(-60);
    view.betaSlider()->setSliderDown(false);  // sliderReleased
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toDouble(), -0.6);
    QTest::qWait(300);
    QCOMPARE(spy.count(), 1);  // the pending debounce does not emit again
  }

  void sweepButtonRequestsSweep() {
    ControlView view;
    QSignalSpy spy(&view, &ControlView::sweepRequested);
    view.sweepButton()->click();
    QCOMPARE(spy.count(), 1);
  }

  void tracesFillTheGraphs_data() {
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("dense");
    QTest::addColumn<int>("thetas");
    QTest::newRow("beta = 0: 4 estimates") << 300 << 10 << 4;
    QTest::newRow("beta != 0: 5 estimates") << 300 << 10 << 5;
    QTest::newRow("one sample") << 1 << 1 << 4;
    QTest::newRow("no continuous output") << 50 << 0 << 4;
    QTest::newRow("empty") << 0 << 0 << 0;
  }
  void tracesFillTheGraphs() {
    QFETCH(int, samples);
    QFETCH(int, dense);
    QFETCH(int, thetas);
    ControlView view;
    view.setTraces(syntheticTraces(samples, dense, thetas));
    for (const char* name : {"reference", "model", "force sampled", "error", "feed"})
      QCOMPARE(view.graphPointCount(name), samples);
    QCOMPARE(view.graphPointCount("force continuous"), samples * dense);
    QCOMPARE(view.graphPointCount("feed continuous"), samples * dense);
    QCOMPARE(view.graphPointCount("depth"), 5);
    const QStringList names = {"a1", "a2", "b0", "b1", "b2"};
    for (int j = 0; j < 5; ++j) QCOMPARE(view.graphPointCount("theta " + names[j]), j < thetas ? samples : -1);
    QCOMPARE(view.graphPointCount("no such graph"), -1);
    const auto [t0, t1] = view.plots()->timeRange();
    QVERIFY(t1 > t0);
    if (samples > 1) {
      QCOMPARE(t0, 0.0);
      QVERIFY(std::abs(t1 - (samples * kPeriod - (dense ? kPeriod / dense : kPeriod))) < 1e-9);
    }
  }

  void mismatchedAndNonFiniteSamplesAreSkipped() {
    ControlTraces t = syntheticTraces(20, 2, 4);
    t.model_n.resize(10);  // shorter series: the common length
    t.error_n[3] = std::nan("");
    t.feed_mm_s[4] = INFINITY;
    ControlView view;
    view.setTraces(t);
    QCOMPARE(view.graphPointCount("model"), 10);
    QCOMPARE(view.graphPointCount("error"), 19);
    QCOMPARE(view.graphPointCount("feed"), 19);
  }

  void plotsAreLabelledWithUnits() {
    ControlPlots all;
    QCOMPARE(all.rowCount(), 4);
    QCOMPARE(all.valueAxisLabel(0), QString("Force F [N]"));
    QCOMPARE(all.valueAxisLabel(1), QString("Error e [N]"));
    QCOMPARE(all.valueAxisLabel(2), QString("Feed f [mm/min]"));
    QCOMPARE(all.valueAxisLabel(3), QString("Estimates \u03b8 [\u2013]"));
    QCOMPARE(all.valueAxisLabel(4), QString());
    QCOMPARE(all.timeAxisLabel(), QString("Time t [s]"));
    all.setTraces(syntheticTraces(30, 2, 4));
    QCOMPARE(all.legendNames(0).size(), 5);
    QVERIFY(all.legendNames(0).contains("Depth b [mm] (right axis)"));
    QCOMPARE(all.legendNames(3), QStringList({"a1", "a2", "b0", "b1"}));
    ControlPlots responses(ControlPlots::Rows::Responses);
    QCOMPARE(responses.rowCount(), 3);
    QCOMPARE(responses.graphPointCount("theta a1"), -1);
  }

  // beta = 0 estimates four parameters and beta != 0 five: the estimates' legend follows, with no entry
  // left of a removed graph (such an entry outlived its graph and crashed the next layout).
  void thetaLegendFollowsTheEstimates() {
    ControlPlots plots;
    plots.resize(800, 600);
    plots.setTraces(syntheticTraces(30, 2, 4));
    plots.setTraces(syntheticTraces(30, 2, 5));
    QCOMPARE(plots.legendNames(3), QStringList({"a1", "a2", "b0", "b1", "b2"}));
    plots.setTraces(syntheticTraces(30, 2, 4));
    QCOMPARE(plots.legendNames(3), QStringList({"a1", "a2", "b0", "b1"}));
    QVERIFY(!plots.grab().isNull());  // lays the legends out
  }

  // Pareto paper, Fig. 6: the changes of programmed point as vertical lines in the feed row, named in its legend,
  // up to the largest sampled feed; no entry without changes.
  void programmeChangesAreMarkedInTheFeedRow() {
    ControlPlots plots;
    ControlTraces t = syntheticTraces(30, 2, 4);
    plots.setTraces(t);
    QCOMPARE(plots.graphPointCount("changes"), 0);
    QVERIFY(!plots.legendNames(2).contains("Change of programmed N or b"));
    QCOMPARE(drawnEntries(mx::test::legendsOf(plotIn(&plots))[2]), 2);  // no entries of hidden graphs (no limit)
    t.change_t_s = {t.t_s[10], t.t_s[20]};
    plots.setTraces(t);
    QCOMPARE(plots.graphPointCount("changes"), 2);
    QVERIFY(plots.legendNames(2).contains("Change of programmed N or b"));
    QCOMPARE(drawnEntries(mx::test::legendsOf(plotIn(&plots))[2]), 3);
    QVERIFY(plots.valueRange(2).second >= *std::max_element(t.feed_mm_s.begin(), t.feed_mm_s.end()));
  }

  void feedLimitLine_data() {
    QTest::addColumn<double>("limit");
    QTest::addColumn<int>("points");
    QTest::newRow("30 mm/s") << 30.0 << 2;
    QTest::newRow("zero: none") << 0.0 << 0;
    QTest::newRow("negative: none") << -5.0 << 0;
    QTest::newRow("NaN: none") << std::nan("") << 0;
  }
  void feedLimitLine() {
    QFETCH(double, limit);
    QFETCH(int, points);
    ControlView view;
    view.setTraces(syntheticTraces(40, 2, 4));
    ControllerSettingsView s;
    s.feed_max_mm_s = limit;
    view.setSettings(s);
    QCOMPARE(view.graphPointCount("feed limit"), points);
    if (points > 0) QVERIFY(view.plots()->valueRange(2).second > limit);  // the limit is in view
    QCOMPARE(view.plots()->legendNames(2).contains("Feed limit f_max"), points > 0);
    QCOMPARE(drawnEntries(mx::test::legendsOf(plotIn(view.plots()))[2]), points > 0 ? 3 : 2);
  }

  void metricsShownWithUnits() {
    ControlView view;
    QCOMPARE(view.metricsPanel()->valueText("jc"), QString("\u2013"));
    view.setTraces(syntheticTraces(300, 2, 4));  // depth 1 -> 2 -> 1.5 -> 0.5 mm
    ControlMetricsView m;
    m.overshoot_pct = {12.346, 4.0, 8.5};
    m.settling_time_s = 0.4321;
    m.jc_n_s = 3.14159;
    m.max_force_n = 1834.0;
    m.min_feed_mm_s = 0.0;
    m.max_feed_mm_s = 30.0;
    m.unstable_zero = true;
    view.setMetrics(m);
    ControlMetricsPanel* p = view.metricsPanel();
    QCOMPARE(p->valueText("overshoot"), QString("step 1: 12.35 (1.000 \u2192 2.000 mm, overshoot)\n"
                                                "step 2: 4.000 (2.000 \u2192 1.500 mm, undershoot)\n"
                                                "step 3: 8.500 (1.500 \u2192 0.5000 mm, undershoot)"));
    QCOMPARE(p->valueText("settling_time"), QString("0.4321"));
    QCOMPARE(p->valueText("jc"), QString("3.142"));
    QCOMPARE(p->valueText("max_force"), QString("1834"));
    QCOMPARE(p->valueText("feed_range"), QString("0 to 1800"));  // 30 mm/s in mm/min
    QVERIFY(p->warningShown());
    QVERIFY(p->valueText("warning").startsWith("Unstable zero"));
    m.unstable_zero = false;
    m.jc_n_s = std::nan("");
    view.setMetrics(m);
    QVERIFY(!p->warningShown());
    QCOMPARE(p->valueText("jc"), QString("\u2013"));
  }

  void jcCurveAndPoleZeroReachTheirPlots() {
    ControlView view;
    view.setBeta(0.3);
    JcCurveView c;
    for (int i = 0; i <= 20; ++i) {
      c.beta << -1.0 + 0.1 * i;
      c.jc_n_s << 2.0 + 5.0 * (c.beta.back() + 0.3) * (c.beta.back() + 0.3);
    }
    c.best_beta = -0.3;
    c.threshold_beta = -0.62;
    view.setJcCurve(c);
    QCOMPARE(view.graphPointCount("Jc"), 21);
    QVERIFY(view.jcPlot()->regionShaded());
    QCOMPARE(view.jcPlot()->currentBeta(), 0.3);
    view.setPoleZero({{{0.0, 0.0}, {0.0, 0.0}, {0.6, 0.0}}, {{-0.4, 0.0}, {-1.3, 0.0}}});
    QCOMPARE(view.graphPointCount("poles"), 3);
    QCOMPARE(view.graphPointCount("zeros"), 2);
    QCOMPARE(view.poleZeroPlot()->unstableZeroCount(), 1);
  }

  void settingsAndWorkpieceRoundTripWithoutSignals() {
    ControlView view;
    QSignalSpy settings_spy(&view, &ControlView::settingsEdited);
    QSignalSpy work_spy(&view, &ControlView::workpieceEdited);
    ControllerSettingsView s;
    s.lambda = 0.98;
    s.p0 = 2.5e6;
    s.theta0 = -0.1;
    s.reset = 2;
    s.reset_fraction = 0.1;
    s.xi = 1.2;
    s.tr_periods = 7.0;
    s.tau_c_ms = 3.5;
    s.feed_max_mm_s = 25.0;
    s.force_reference_n = 900.0;
    view.setSettings(s);
    QCOMPARE(view.settings(), s);
    const QVector<DepthStepView> steps = {{100.0, 1.0}, {80.0, 2.0}, {60.0, 1.5}, {40.0, 0.5}};
    view.setWorkpiece(steps);
    QCOMPARE(view.workpiece(), steps);
    QCOMPARE(settings_spy.count(), 0);
    QCOMPARE(work_spy.count(), 0);
  }

  void busyAndStatus() {
    ControlView view;
    view.setBusy(true);
    QVERIFY(view.isBusy());
    view.setStatus("Computing \u03b2 = 0.30");
    QCOMPARE(view.statusText(), QString("Computing \u03b2 = 0.30"));
    view.setBusy(false);
    QVERIFY(!view.isBusy());
  }

  void saveResponsePlotsWritesPng_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::newRow("default 1600x1200") << 1600 << 1200;
    QTest::newRow("small 800x600") << 800 << 600;
  }
  void saveResponsePlotsWritesPng() {
    QFETCH(int, width);
    QFETCH(int, height);
    QTemporaryDir dir;
    ControlView view;
    view.setBeta(-0.3);
    view.setTraces(syntheticTraces());
    const QString path = dir.filePath("responses.png");
    QVERIFY(view.saveResponsePlots(path, width, height));
    const QImage image(path);
    QCOMPARE(image.size(), QSize(width, height));
    QVERIFY(QFileInfo(path).size() > 1000);
    QVERIFY(!view.saveResponsePlots(QString(), width, height));
    QVERIFY(!view.saveResponsePlots(dir.filePath("no/such/dir/x.png"), width, height));
  }

  void saveJcPlotWritesPng() {
    QTemporaryDir dir;
    ControlView view;
    const QString path = dir.filePath("jc.png");
    QVERIFY(view.saveJcPlot(path, 1200, 700));
    QCOMPARE(QImage(path).size(), QSize(1200, 700));
    QVERIFY(!view.saveJcPlot(QString()));
  }

  // MX_CONTROL_PNG_DIR=dir writes the export images of synthetic data there, to look at.
  void writeImagesForReview() {
    const QString dir = qEnvironmentVariable("MX_CONTROL_PNG_DIR");
    if (dir.isEmpty()) QSKIP("MX_CONTROL_PNG_DIR not set");
    ControlView view;
    view.setBeta(-0.3);
    view.setTraces(syntheticTraces());
    JcCurveView c;
    for (int i = 0; i <= 32; ++i) {
      c.beta << -0.6 + 0.05 * i;
      c.jc_n_s << 2.0 + 5.0 * (c.beta.back() + 0.3) * (c.beta.back() + 0.3);
    }
    c.best_beta = -0.3;
    c.threshold_beta = -0.62;
    view.setJcCurve(c);
    view.setPoleZero({{{0.0, 0.0}, {0.0, 0.0}, {0.61, 0.0}}, {{-0.4, 0.0}, {0.1, 0.2}, {0.1, -0.2}}});
    QVERIFY(view.saveResponsePlots(dir + "/control_responses.png"));
    QVERIFY(view.saveJcPlot(dir + "/control_jc.png"));
    QVERIFY(view.poleZeroPlot()->savePng(dir + "/control_pz.png", 600, 500));
    view.resize(1900, 1000);
    view.show();
    QTest::qWait(200);
    QVERIFY(view.grab().save(dir + "/control_view.png"));
  }

  // The bottom dock at 1080p: 1920 x 430. The view fits it (the dock does not scroll); the closed-loop rows
  // keep kMinRowHeight each and scroll in their column; J_c and the pole-zero map stand side by side,
  // whole; no legend over a plot, no name cut, value-axis tick labels apart.
  void readsWellInADockAt1080p() {
    ControlView view;
    fillForLayout(view);
    QVERIFY(showAt(view, QSize(1920, 430)));
    QCOMPARE_LE(view.minimumSizeHint().height(), 300);  // the columns scroll, never the dock
    QCustomPlot* rows = plotIn(view.plots());
    QCOMPARE(rows->axisRects().size(), 4);
    for (const QCPAxisRect* rect : rows->axisRects()) {
      QCOMPARE_GE(rect->rect().height(), ControlPlots::kMinRowHeight);
      for (const QCPAxis* axis : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atRight)})
        if (axis->visible()) QCOMPARE(mx::test::tickLabelProblem(axis), QString());
    }
    QCOMPARE_GT(view.plotsScroll()->verticalScrollBar()->maximum(), 0);  // the rows scroll, not squashed
    QCOMPARE(view.chartsOrientation(), Qt::Horizontal);
    QCOMPARE(view.chartsScroll()->verticalScrollBar()->maximum(), 0);  // both charts whole
    for (const QWidget* w : {static_cast<QWidget*>(view.plots()), static_cast<QWidget*>(view.jcPlot()),
                             static_cast<QWidget*>(view.poleZeroPlot())}) {
      QCOMPARE(mx::test::legendProblem(plotIn(w)), QString());
      QCOMPARE(mx::test::captionProblem(plotIn(w)), QString());
    }
    QCOMPARE(view.plots()->legendNames(2).size(), 4);  // feed, between samples, limit, changes
    QCOMPARE(view.plots()->legendNames(3).size(), 5);
  }

  // A tall dock: the charts one above the other, the rows taller than their minimum with nothing to scroll.
  void tallDockStacksTheCharts() {
    ControlView view;
    fillForLayout(view);
    QVERIFY(showAt(view, QSize(1920, 1000)));
    QCOMPARE(view.chartsOrientation(), Qt::Vertical);
    QCOMPARE(view.plotsScroll()->verticalScrollBar()->maximum(), 0);
    for (const QCPAxisRect* rect : plotIn(view.plots())->axisRects())
      QCOMPARE_GT(rect->rect().height(), ControlPlots::kMinRowHeight);
    for (const QWidget* w : {static_cast<QWidget*>(view.jcPlot()), static_cast<QWidget*>(view.poleZeroPlot())})
      QCOMPARE(mx::test::legendProblem(plotIn(w)), QString());
  }

  // The rows' legends take as many columns as the width holds without cutting a name: all five force
  // entries in one line when wide, more lines when narrow; never over a row.
  void rowLegendsFitTheWidth_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("force_legend_rows");
    QTest::newRow("narrow 360") << 360 << 5;
    QTest::newRow("dock 900") << 900 << 2;
    QTest::newRow("wide 1500") << 1500 << 1;
  }
  void rowLegendsFitTheWidth() {
    QFETCH(int, width);
    QFETCH(int, force_legend_rows);
    const mx::test::LayoutAbortCounter layout;
    QScrollArea area;  // as in the view
    area.setWidgetResizable(true);
    area.setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* plots = new ControlPlots;
    area.setWidget(plots);
    ControlTraces t = syntheticTraces(100, 4, 5);
    t.change_t_s = {0.3};
    plots->setTraces(t);
    area.resize(width, 430);
    area.show();
    QVERIFY(QTest::qWaitForWindowExposed(&area));
    QTest::qWait(100);
    QCustomPlot* plot = plotIn(plots);
    plot->replot();
    QCOMPARE(mx::test::legendProblem(plot), QString());
    const QList<QCPLegend*> legends = mx::test::legendsOf(plot);
    QCOMPARE(legends.size(), 4);
    QCOMPARE(legends.front()->rowCount(), force_legend_rows);
    for (const QCPLegend* legend : legends)  // packed from the left, not spread over the row
      QCOMPARE(legend->outerRect().width(), legend->minimumOuterSizeHint().width());
    for (const QCPAxisRect* rect : plot->axisRects()) QCOMPARE_GE(rect->rect().height(), ControlPlots::kMinRowHeight);
    QCOMPARE(layout.aborts(), 0);
  }

  // At its minimum width the widest legend entry ("Plant F_p between samples") still fits beside the
  // rows' axes, in millimetres and in inches.
  void minimumWidthCutsNoName_data() {
    QTest::addColumn<bool>("inch");
    QTest::newRow("mm") << false;
    QTest::newRow("inch") << true;
  }
  void minimumWidthCutsNoName() {
    QFETCH(bool, inch);
    const mx::test::LayoutAbortCounter layout;
    DisplayUnits units;
    if (inch) units.setShop(ShopUnits::inch());
    ControlPlots plots;
    plots.setUnits(&units);
    plots.setTraces(syntheticTraces(100, 4, 5));
    QVERIFY(showAt(plots, plots.minimumSizeHint()));
    QCustomPlot* plot = plotIn(&plots);
    QCOMPARE(plot->width(), plots.minimumSizeHint().width());
    QCOMPARE(mx::test::legendProblem(plot), QString());
    QCOMPARE(layout.aborts(), 0);
  }

  // Squeezed below what its legends need (a plot resized by hand), the layout still solves: the legend
  // takes the whole strip and the rows keep their place, instead of QCustomPlot aborting the layout.
  void squeezedBelowItsLegendsTheLayoutSolves() {
    const mx::test::LayoutAbortCounter layout;
    ControlPlots plots;
    plots.setTraces(syntheticTraces(100, 4, 5));
    QCustomPlot* plot = plotIn(&plots);
    plot->setMinimumSize(0, 0);
    plot->resize(260, 1200);
    plot->setViewport(QRect(0, 0, 260, 1200));
    plot->replot();
    QCOMPARE(layout.aborts(), 0);
    const QCPLegend* force_legend = mx::test::legendsOf(plot).front();
    QCOMPARE_LT(force_legend->outerRect().width(), force_legend->minimumOuterSizeHint().width());
    QCOMPARE_GT(force_legend->outerRect().width(), 0);
    QCOMPARE_LE(force_legend->outerRect().right(), plot->viewport().right());
  }

  // The export lays its legends out for the image's width: at 1600 px every row's legend is one line.
  void exportFitsItsLegendsToTheImage() {
    QTemporaryDir dir;
    ControlPlots plots(ControlPlots::Rows::Responses);
    plots.resize(500, 700);
    plots.setTraces(syntheticTraces(100, 4, 4));
    QVERIFY(plots.savePng(dir.filePath("responses.png"), 1600, 1200));
    for (const QCPLegend* legend : mx::test::legendsOf(plotIn(&plots))) QCOMPARE(legend->rowCount(), 1);
  }

  // Shop units: the force rows, the depth and the feed axis relabel, the traces and metrics convert.
  void followsShopUnits() {
    DisplayUnits units;
    ControlView view;
    view.setUnits(&units);
    ControlTraces t;
    t.t_s = {0.0, 0.1, 0.2};
    t.reference_n = t.model_n = t.force_sampled_n = {444.82216152605, 444.82216152605, 444.82216152605};
    t.error_n = {0.0, 0.0, 0.0};
    t.feed_mm_s = {25.4 / 60.0, 25.4 / 60.0, 25.4 / 60.0};  // 1 IPM
    view.setTraces(t);
    ControlMetricsView m;
    m.max_force_n = 1834.0;
    m.min_feed_mm_s = 0.0;
    m.max_feed_mm_s = 25.4;
    view.setMetrics(m);
    units.setShop(ShopUnits::inch());
    ControlPlots* p = view.plots();
    QCOMPARE(p->valueAxisLabel(0), QString("Force F [lbf]"));
    QCOMPARE(p->valueAxisLabel(1), QString("Error e [lbf]"));
    QCOMPARE(p->valueAxisLabel(2), QString("Feed f [IPM]"));
    const auto force = p->valueRange(0);
    QVERIFY2(force.first < 100.0 && force.second > 100.0 && force.second < 200.0,
             qPrintable(QString("%1 .. %2").arg(force.first).arg(force.second)));  // 100 lbf inside
    const auto feed = p->valueRange(2);
    // 1 IPM and the default feed limit f_max = 30 mm/s = 70.9 IPM on the axis.
    QVERIFY2(feed.first < 1.0 && feed.second > 70.9 && feed.second < 100.0,
             qPrintable(QString("%1 .. %2").arg(feed.first).arg(feed.second)));
    QCOMPARE(view.metricsPanel()->valueText("max_force"), QString("412.3"));
    QCOMPARE(view.metricsPanel()->valueText("feed_range"), QString("0 to 60.00"));
    QCOMPARE(view.settingsEditor()->field("force_reference_n")->text(), QString("269.771"));  // 1200 N
  }
};

MX_REGISTER_TEST(TestControlView)
#include "test_control_view.moc"
