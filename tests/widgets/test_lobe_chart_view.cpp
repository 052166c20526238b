// The lobe chart's markers: each group (the expert's q* and q**, the Pareto choice) is cleared and
// redrawn on its own; clearing every group empties the chart; a change of length unit keeps them. The
// model title above the plot.
#include <QImage>
#include <QStringList>

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
