// The lobe chart's markers: each group (the expert's q* and q**, the Pareto choice) is cleared and
// redrawn on its own; clearing every group empties the chart; a change of length unit keeps them, and
// the markers of one change share one queued replot. The model title above the plot. The legend under
// the plot keys styles only, whatever the number of tools; the tool list beside it shows, hides and
// activates tools; 20 tools get distinct colours; an export names every tool and is not cut off; the
// pocket list moves the point; the cursor readout gives b_lim under the mouse.
#include <qcustomplot.h>

#include <QCheckBox>
#include <QImage>
#include <QListWidget>
#include <QRegularExpression>
#include <QSet>
#include <QSignalSpy>
#include <QStringList>
#include <QTemporaryDir>
#include <QTest>
#include <array>
#include <cmath>

#include "lobe_chart_view.h"
#include "lobe_tool_panel.h"
#include "test_registry.h"

using mx::widgets::LobeChartView;
using mx::widgets::ToolLobeSeries;

namespace {

// `count` tools T1, T2... whose nominal lobes are V shapes b = m_k + 0.001 |N - c_k| (c = 2000, 3000,
// 4000 rpm; m = 0.5, 0.3, 0.45 mm, tool i adds 0.01 i mm) on [1000, 5000] rpm every 5 rpm; the margined
// lobe is 0.9 of it. T1's pockets: 2400 rpm (0.9 mm) and 3575 rpm (0.875 mm), margined 0.81, 0.7875.
QVector<ToolLobeSeries> vSeries(int count) {
  QVector<ToolLobeSeries> series;
  for (int i = 0; i < count; ++i) {
    ToolLobeSeries s;
    s.tool_id = QString("T%1").arg(i + 1);
    for (int j = 0; j <= 800; ++j) {
      const double n = 1000.0 + 5.0 * j;
      const double b = std::min({0.5 + 0.001 * std::abs(n - 2000.0), 0.3 + 0.001 * std::abs(n - 3000.0),
                                 0.45 + 0.001 * std::abs(n - 4000.0)}) +
                       0.01 * i;
      s.speed_rpm.push_back(n);
      s.nominal_mm.push_back(b);
      s.margined_mm.push_back(0.9 * b);
    }
    series.push_back(s);
  }
  return series;
}

// CIE L*a*b* of an sRGB colour (D65), for the Delta E_76 between two colours.
std::array<double, 3> lab(const QColor& c) {
  const auto linear = [](double u) { return u > 0.04045 ? std::pow((u + 0.055) / 1.055, 2.4) : u / 12.92; };
  const double r = linear(c.redF()), g = linear(c.greenF()), b = linear(c.blueF());
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

// The chart on screen (1100 x 650) with vSeries(tools), delta = 0.05 1/s, alpha = 0.95.
bool showWithTools(LobeChartView& chart, int tools) {
  chart.resize(1100, 650);
  chart.show();
  if (!QTest::qWaitForWindowExposed(&chart)) return false;
  chart.setSeries(vSeries(tools), 0.05, 0.95);
  return true;
}

QCustomPlot* plotOf(const LobeChartView& chart) {
  return qobject_cast<QCustomPlot*>(chart.plotWidget());
}

bool graphVisible(const LobeChartView& chart, const QString& name) {
  QCustomPlot* plot = plotOf(chart);
  for (int i = 0; i < plot->graphCount(); ++i)
    if (plot->graph(i)->name() == name) return plot->graph(i)->visible();
  return false;
}

}  // namespace

class TestLobeChartView : public QObject {
  Q_OBJECT

 private slots:
  void groupsAreClearedOneByOne() {
    LobeChartView chart;
    chart.setMarker("q*", 9000.0, 2.0, Qt::blue, "expert");
    chart.setMarker("q**", 9500.0, 2.5, Qt::magenta, "expert");
    chart.setMarker("Pareto q", 8000.0, 1.5, Qt::green, "pareto");
    QCOMPARE(chart.markerNames(), (QStringList{"q*", "q**", "Pareto q"}));
    chart.clearMarkers("expert");
    QCOMPARE(chart.markerNames(), QStringList{"Pareto q"});
    chart.setMarker("q*", 9100.0, 2.0, Qt::blue, "expert");
    QCOMPARE(chart.markerNames(), (QStringList{"Pareto q", "q*"}));
    chart.clearMarkers("nobody");
    QCOMPARE(chart.markerNames().size(), 2);
    chart.clearMarkers();
    QVERIFY(chart.markerNames().isEmpty());
  }

  // Shift + arrow keys: to the next grid line of that axis, the speed's counted from the grid's first
  // speed (800 + k 1000 rpm); the other axis stays.
  void shiftArrowsSnapToTheGridFromItsStart_data() {
    QTest::addColumn<int>("key");
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::newRow("right from off the grid") << int(Qt::Key_Right) << 3800.0 << 1.206;
    QTest::newRow("left from off the grid") << int(Qt::Key_Left) << 2800.0 << 1.206;
    QTest::newRow("up") << int(Qt::Key_Up) << 3264.0 << 1.25;
    QTest::newRow("down") << int(Qt::Key_Down) << 3264.0 << 1.2;
  }
  void shiftArrowsSnapToTheGridFromItsStart() {
    QFETCH(int, key);
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    LobeChartView chart;
    chart.setSnapGrid(800.0, 1000.0, 0.05);
    chart.setOperatingPoint(3264.0, 1.206, mx::widgets::PointVerdict::Unknown);
    QSignalSpy released(&chart, &LobeChartView::pointReleased);
    QTest::keyClick(&chart, Qt::Key(key), Qt::ShiftModifier);
    QCOMPARE(released.count(), 1);
    QCOMPARE_LE(std::abs(released.front()[0].toDouble() - speed_rpm), 1e-9);
    QCOMPARE_LE(std::abs(released.front()[1].toDouble() - depth_mm), 1e-9);
    // From a grid line the next press moves exactly one step.
    chart.setOperatingPoint(speed_rpm, depth_mm, mx::widgets::PointVerdict::Unknown);
    QTest::keyClick(&chart, Qt::Key(key), Qt::ShiftModifier);
    const double sign = key == Qt::Key_Right || key == Qt::Key_Up ? 1.0 : -1.0;
    const bool horizontal = key == Qt::Key_Right || key == Qt::Key_Left;
    QCOMPARE_LE(std::abs(released.back()[0].toDouble() - (speed_rpm + (horizontal ? sign * 1000.0 : 0.0))), 1e-9);
    QCOMPARE_LE(std::abs(released.back()[1].toDouble() - (depth_mm + (horizontal ? 0.0 : sign * 0.05))), 1e-9);
  }

  // A weight step clears and redraws q* and q**: one full replot when the event loop turns, none while
  // the markers change (each used to replot the whole chart at once, and a quick wheel over a weight
  // held the window for 0.4 s).
  void markerChangesShareOneQueuedReplot() {
    LobeChartView chart;
    chart.resize(800, 500);
    chart.show();
    QVERIFY(QTest::qWaitForWindowExposed(&chart));
    chart.setMarker("q*", 9000.0, 2.0, Qt::blue, "expert");
    QTest::qWait(50);  // the replots queued so far
    auto* plot = qobject_cast<QCustomPlot*>(chart.plotWidget());
    QVERIFY(plot);
    QSignalSpy replots(plot, &QCustomPlot::afterReplot);
    chart.clearMarkers("expert");
    chart.setMarker("q*", 9100.0, 2.0, Qt::blue, "expert");
    chart.setMarker("q**", 9500.0, 2.5, Qt::magenta, "expert");
    chart.clearMarkers("pareto");
    QCOMPARE(replots.count(), 0);
    QTRY_COMPARE(replots.count(), 1);
    QTest::qWait(50);
    QCOMPARE(replots.count(), 1);
  }

  void markersSurviveAUnitChange() {
    LobeChartView chart;
    chart.setMarker("q*", 9000.0, 2.0, Qt::blue, "expert");
    chart.setLengthUnit(1.0 / 25.4, "in");
    QCOMPARE(chart.markerNames(), QStringList{"q*"});
  }

  // The model title: shown above the plot, replaced, hidden by "" and by clear().
  void modelLabelIsATitleRow() {
    LobeChartView chart;
    chart.resize(800, 500);
    chart.clear();
    QTest::qWait(20);  // the queued replot of the empty chart
    const QImage without = chart.grab().toImage();
    chart.setModelLabel("Tool R1: SDM, 3 teeth, variable pitch");
    chart.setModelLabel("Tool R1: ZOA, 3 teeth, variable pitch");
    QCOMPARE(chart.modelLabel(), QString("Tool R1: ZOA, 3 teeth, variable pitch"));
    QTRY_VERIFY(chart.grab().toImage() != without);  // the replot is queued
    chart.setModelLabel({});
    QCOMPARE(chart.modelLabel(), QString());
    chart.setModelLabel("Tool R2: ZOA, 2 teeth, uniform pitch");
    chart.clear();
    QCOMPARE(chart.modelLabel(), QString());
  }

  // On screen the legend keys the line styles and regions: as many entries for 20 tools as for 2,
  // none of them a tool, all below the axes.
  void legendKeysStylesBelowThePlot_data() {
    QTest::addColumn<int>("tools");
    QTest::newRow("2 tools") << 2;
    QTest::newRow("6 tools") << 6;
    QTest::newRow("20 tools") << 20;
  }
  void legendKeysStylesBelowThePlot() {
    QFETCH(int, tools);
    LobeChartView chart;
    QVERIFY(showWithTools(chart, tools));
    const QStringList names = chart.legendNames();
    QCOMPARE(names.size(), 4);  // unstable, admissible, nominal and margined line styles
    for (const QString& name : names) QVERIFY2(!name.startsWith("T"), qPrintable(name));
    QCOMPARE(chart.toolPanel()->toolList()->count(), tools);
    QCustomPlot* plot = plotOf(chart);
    plot->replot();
    QVERIFY(!plot->legend->outerRect().intersects(plot->axisRect()->outerRect()));
    QCOMPARE_GE(plot->axisRect()->outerRect().height(), 400);
  }

  // 20 tools, 20 colours: every pair at least Delta E_76 = 25 apart (clearly different side by side);
  // with the marker shapes no (colour, shape) pair repeats within 140 tools.
  void twentyToolsHaveDistinctColours() {
    double closest = 1e9;
    for (int i = 0; i < LobeChartView::kDistinctColors; ++i)
      for (int j = i + 1; j < LobeChartView::kDistinctColors; ++j) {
        const auto a = lab(LobeChartView::toolColor(i)), b = lab(LobeChartView::toolColor(j));
        closest = std::min(closest, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
      }
    QCOMPARE_GE(closest, 25.0);
    QSet<QPair<QRgb, int>> styles;
    for (int i = 0; i < 140; ++i) styles.insert({LobeChartView::toolColor(i).rgb(), LobeChartView::toolShape(i)});
    QCOMPARE(styles.size(), 140);
  }

  // The exported image names every shown tool in its legend, and is as tall as that legend needs
  // below 560 px of plot (900 px are enough for 20 tools, 600 px are not); the screen's legend is as
  // before afterwards.
  void exportNamesEveryToolAndFitsItsLegend() {
    LobeChartView chart;
    chart.resize(1100, 650);
    chart.setSeries(vSeries(20), 0.05, 0.95);
    chart.setToolVisible("T20", false);
    QCOMPARE(chart.exportHeight(1600, 900), 900);  // room enough
    const int height = chart.exportHeight(1600, 600);
    QCOMPARE_GT(height, 600);
    QTemporaryDir dir;
    const QString png = dir.filePath("lobes.png");
    QVERIFY(chart.saveImage(png, 1600, 600));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1600, height));
    QCOMPARE(chart.legendNames().size(), 4);
    // With the tools in, the legend needs 4 + 19 entries in 3 columns: 8 rows.
    auto* plot = plotOf(chart);
    for (int i = 0; i < plot->graphCount(); ++i)
      if (QRegularExpression("^T(1?[0-9])$").match(plot->graph(i)->name()).hasMatch()) plot->graph(i)->addToLegend();
    QCOMPARE(chart.legendNames().size(), 4 + 19);
    plot->legend->setWrap(3);
    plot->legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    QCOMPARE_LE(plot->legend->minimumOuterSizeHint().height(), height - 560);
  }

  void activeToolOnlyHidesTheOthers() {
    LobeChartView chart;
    chart.setSeries(vSeries(3), 0.05, 0.95);
    chart.setActiveTool(1);
    QVERIFY(graphVisible(chart, "T1") && graphVisible(chart, "T3"));
    chart.findChild<QCheckBox*>("activeToolOnly")->setChecked(true);
    QVERIFY(!graphVisible(chart, "T1") && graphVisible(chart, "T2") && !graphVisible(chart, "T3"));
    chart.setActiveTool(2);
    QVERIFY(!graphVisible(chart, "T2") && graphVisible(chart, "T3"));
    chart.findChild<QCheckBox*>("activeToolOnly")->setChecked(false);
    QVERIFY(graphVisible(chart, "T1") && graphVisible(chart, "T2"));
  }

  // The list's check box hides a tool (and says so); a click on a tool asks for it as the active tool.
  void toolListShowsHidesAndActivates() {
    LobeChartView chart;
    QVERIFY(showWithTools(chart, 3));
    QSignalSpy visibility(&chart, &LobeChartView::toolVisibilityChanged);
    QSignalSpy activate(&chart, &LobeChartView::activeToolRequested);
    QListWidget* list = chart.toolPanel()->toolList();
    list->item(1)->setCheckState(Qt::Unchecked);
    QCOMPARE(visibility.count(), 1);
    QCOMPARE(visibility.front()[0].toString(), QString("T2"));
    QVERIFY(!chart.isToolVisible("T2") && !graphVisible(chart, "T2"));
    chart.setToolVisible("T2", true);  // from the View menu: the list follows without a signal
    QCOMPARE(list->item(1)->checkState(), Qt::Checked);
    QCOMPARE(visibility.count(), 1);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(2)).center());
    QCOMPARE(activate.count(), 1);
    QCOMPARE(activate.front()[0].toInt(), 2);
    chart.setActiveTool(2);
    QVERIFY(list->item(2)->font().bold() && !list->item(0)->font().bold());
  }

  // The active tool's pockets of its margined lobe, deepest first; a click moves the point there.
  void pocketListMovesThePoint() {
    LobeChartView chart;
    QVERIFY(showWithTools(chart, 2));
    QListWidget* pockets = chart.toolPanel()->pocketList();
    QCOMPARE(pockets->count(), 2);
    QCOMPARE(pockets->item(0)->text(), QString("best: 2400 rpm, 0.81 mm"));
    QCOMPARE(pockets->item(1)->text(), QString("3575 rpm, 0.79 mm"));
    chart.setActiveTool(1);  // T2 lies 0.01 mm higher: 0.9 (0.91) = 0.819
    QCOMPARE(pockets->item(0)->text(), QString("best: 2400 rpm, 0.82 mm"));
    QSignalSpy released(&chart, &LobeChartView::pointReleased);
    QTest::mouseClick(pockets->viewport(), Qt::LeftButton, {}, pockets->visualItemRect(pockets->item(1)).center());
    QCOMPARE(released.count(), 1);
    QCOMPARE(released.front()[0].toDouble(), 3575.0);
    QCOMPARE_LE(std::abs(released.front()[1].toDouble() - 0.9 * 0.885), 1e-12);
    chart.setLengthUnit(1.0 / 25.4, "in");
    QCOMPARE(pockets->item(0)->text(), QString("best: 2400 rpm, 0.0322 in"));
  }

  // Labels face the middle of the view, so that no edge cuts them; the labels of neighbouring markers
  // stack instead of overprinting.
  void labelsStayInsideAndApart() {
    LobeChartView chart;
    QVERIFY(showWithTools(chart, 1));
    QCustomPlot* plot = plotOf(chart);
    plot->replot();
    chart.setOperatingPoint(4990.0, 0.5, mx::widgets::PointVerdict::Stable);
    chart.setMarker("q* (T1)", 4800.0, 0.6, Qt::blue, "expert");
    chart.setMarker("q**", 4850.0, 0.62, Qt::magenta, "expert");
    plot->replot();
    QVector<QRectF> labels;
    for (int i = 0; i < plot->itemCount(); ++i)
      if (auto* text = qobject_cast<QCPItemText*>(plot->item(i)); text && text->visible())
        labels.push_back(QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition()));
    QCOMPARE(labels.size(), 3);  // the point's and the two markers'
    const QRectF area = plot->axisRect()->rect();
    for (const QRectF& r : labels) QVERIFY2(area.contains(r), "a label crosses the plot's edge");
    QVERIFY(!labels[1].intersects(labels[2]));
  }

  // Under the mouse: the speed and depth there and the active tool's b_lim at that speed; on T1's
  // first lobe flank (1300 rpm) b_lim = 0.5 + 0.001 (2000 - N).
  void cursorReadoutGivesTheLimitUnderTheMouse() {
    LobeChartView chart;
    QVERIFY(showWithTools(chart, 1));
    plotOf(chart)->replot();
    QTest::mouseMove(chart.plotWidget(), chart.pixelFor(1300.0, 0.3));
    const QRegularExpressionMatch m =
        QRegularExpression(
            R"(N = (\d+) rpm, b = ([0-9.]+) mm\nb_lim of T1: ([0-9.]+) mm nominal, ([0-9.]+) mm margined)")
            .match(chart.toolPanel()->cursorText());
    QVERIFY2(m.hasMatch(), qPrintable(chart.toolPanel()->cursorText()));
    const double n = m.captured(1).toDouble();
    QCOMPARE_LE(std::abs(n - 1300.0), 10.0);  // a pixel
    QCOMPARE_LE(std::abs(m.captured(2).toDouble() - 0.3), 0.005);
    const double blim = 0.5 + 0.001 * (2000.0 - n);
    QCOMPARE_LE(std::abs(m.captured(3).toDouble() - blim), 0.0011);  // the shown N is rounded to 1 rpm
    QCOMPARE_LE(std::abs(m.captured(4).toDouble() - 0.9 * blim), 0.0011);
  }
};

MX_REGISTER_TEST(TestLobeChartView)
#include "test_lobe_chart_view.moc"
