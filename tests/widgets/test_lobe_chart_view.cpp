// The lobe chart's markers: each group (the expert's q* and q**, the Pareto choice) is cleared and
// redrawn on its own; clearing every group empties the chart; a change of length unit keeps them, and
// the markers of one change share one queued replot. The model title above the plot.
#include <qcustomplot.h>

#include <QImage>
#include <QSignalSpy>
#include <QStringList>
#include <QTest>

#include "lobe_chart_view.h"
#include "test_registry.h"

using mx::widgets::LobeChartView;

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
};

MX_REGISTER_TEST(TestLobeChartView)
#include "test_lobe_chart_view.moc"
