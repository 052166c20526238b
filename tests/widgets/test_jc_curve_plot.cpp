// JcCurvePlot: the J_c(beta) sweep (non-finite values left out), the unstable-zero region shaded below
// the threshold, the minimum starred, the current beta marked with the J_c its closed-loop run computed
// (never the sweep's interpolation), labelled axes and legend entries; the legend under the plot, the
// region's label inside it above the curve.
#include <qcustomplot.h>

#include <QApplication>
#include <QImage>
#include <QTemporaryDir>
#include <cmath>
#include <limits>

#include "jc_curve_plot.h"
#include "support/plot_layout_checks.h"
#include "support/test_constants.h"
#include "test_registry.h"

using mx::widgets::JcCurvePlot;
using mx::widgets::JcCurveView;

namespace {
using mx::test::kNaN;

// J_c = 2 + 5 (beta + 0.3)^2 on beta = -1, -0.9, ..., 1.
JcCurveView parabola() {
  JcCurveView c;
  for (int i = 0; i <= 20; ++i) {
    const double b = -1.0 + 0.1 * i;
    c.beta << b;
    c.jc_n_s << 2.0 + 5.0 * (b + 0.3) * (b + 0.3);
  }
  c.best_beta = -0.3;
  c.threshold_beta = -0.62;
  return c;
}

// The legend's longest entries: five-digit costs and the current beta in the unstable-zero region.
JcCurvePlot* longestEntries(JcCurvePlot* plot) {
  JcCurveView c = parabola();
  for (double& jc : c.jc_n_s) jc *= 5000.0;
  plot->setCurve(c);
  plot->setCurrentBeta(-0.83);
  plot->setComputedJc(12345.6);
  return plot;
}
}  // namespace

class TestJcCurvePlot : public QObject {
  Q_OBJECT
 private slots:
  void axesAndEmptyState() {
    JcCurvePlot plot;
    QCOMPARE(plot.xAxisLabel(), QString("FROH gain \u03b2 [\u2013]"));
    QCOMPARE(plot.yAxisLabel(), QString("Cost J_c [N\u00b7s]"));
    QCOMPARE(plot.pointCount(), 0);
    QVERIFY(!plot.regionShaded());
    QVERIFY(!plot.bestBeta());
    QVERIFY(!plot.computedJc());
  }

  void curveRegionAndMarkers() {
    JcCurvePlot plot;
    plot.setCurve(parabola());
    plot.setCurrentBeta(0.3);
    QCOMPARE(plot.pointCount(), 21);
    QVERIFY(plot.regionShaded());
    QCOMPARE(plot.shadedRange(), qMakePair(-1.0, -0.62));
    QVERIFY(plot.bestBeta());
    QCOMPARE(*plot.bestBeta(), -0.3);
    plot.setComputedJc(3.8149);  // the closed loop's J_c, not the sweep's 3.8 (2 + 5 * 0.6^2)
    const QStringList legend = plot.legendNames();
    QCOMPARE(legend.size(), 4);
    QCOMPARE(legend[0], QString("J_c(\u03b2) [N\u00b7s]"));
    QCOMPARE(legend[1], QString("Unstable zero of H_\u03b2: \u03b2 < \u22120.62"));
    QCOMPARE(legend[2], QString("Minimum: \u03b2 = \u22120.30, J_c = 2 N\u00b7s"));
    QCOMPARE(legend[3], QString("Current \u03b2 = 0.30, J_c = 3.815 N\u00b7s"));
  }

  // The legend shows the computed J_c of the current beta, or says it is computing: a new beta drops
  // the old value, the same beta keeps it, a non-finite value is none.
  void computedJcFollowsTheBeta_data() {
    QTest::addColumn<double>("next_beta");
    QTest::addColumn<double>("computed");
    QTest::addColumn<QString>("legend");
    QTest::newRow("same beta keeps it") << 0.3 << 3.8149 << "Current \u03b2 = 0.30, J_c = 3.815 N\u00b7s";
    QTest::newRow("new beta drops it") << 0.4 << 3.8149 << "Current \u03b2 = 0.40, J_c: computing";
    QTest::newRow("clamped above 1") << 2.0 << 3.8149 << "Current \u03b2 = 1.00, J_c: computing";
    QTest::newRow("non-finite is none") << 0.3 << qQNaN() << "Current \u03b2 = 0.30, J_c: computing";
  }
  void computedJcFollowsTheBeta() {
    QFETCH(double, next_beta);
    QFETCH(double, computed);
    QFETCH(QString, legend);
    JcCurvePlot plot;
    plot.setCurve(parabola());
    plot.setCurrentBeta(0.3);
    plot.setComputedJc(computed);
    plot.setCurrentBeta(next_beta);
    QCOMPARE(plot.legendNames().last(), legend);
    QCOMPARE(plot.computedJc().has_value(), legend.contains("J_c ="));
  }

  void currentBetaOutsideTheSweep() {
    JcCurveView c = parabola();
    c.beta = c.beta.mid(5);  // beta from -0.5
    c.jc_n_s = c.jc_n_s.mid(5);
    JcCurvePlot plot;
    plot.setCurve(c);
    plot.setCurrentBeta(-0.8);
    plot.setComputedJc(7.25);
    QCOMPARE(plot.legendNames().last(), QString("Current \u03b2 = \u22120.80, J_c = 7.25 N\u00b7s (unstable zero)"));
  }

  void nonFinitePointsLeftOut_data() {
    QTest::addColumn<int>("bad_index");
    QTest::addColumn<double>("bad_value");
    QTest::addColumn<bool>("in_beta");
    QTest::newRow("NaN J_c") << 3 << kNaN << false;
    QTest::newRow("inf J_c (unstable run)") << 7 << std::numeric_limits<double>::infinity() << false;
    QTest::newRow("NaN beta") << 0 << kNaN << true;
  }
  void nonFinitePointsLeftOut() {
    QFETCH(int, bad_index);
    QFETCH(double, bad_value);
    QFETCH(bool, in_beta);
    JcCurveView c = parabola();
    (in_beta ? c.beta : c.jc_n_s)[bad_index] = bad_value;
    JcCurvePlot plot;
    plot.setCurve(c);
    QCOMPARE(plot.pointCount(), 20);
  }

  void thresholdEdges_data() {
    QTest::addColumn<double>("threshold");
    QTest::addColumn<bool>("shaded");
    QTest::addColumn<double>("upper");
    QTest::newRow("default -1: none") << -1.0 << false << 0.0;
    QTest::newRow("below -1: none") << -1.5 << false << 0.0;
    QTest::newRow("NaN: none") << kNaN << false << 0.0;
    QTest::newRow("paper -0.6") << -0.6 << true << -0.6;
    QTest::newRow("above 1: all") << 1.5 << true << 1.0;
  }
  void thresholdEdges() {
    QFETCH(double, threshold);
    QFETCH(bool, shaded);
    QFETCH(double, upper);
    JcCurveView c = parabola();
    c.threshold_beta = threshold;
    JcCurvePlot plot;
    plot.setCurve(c);
    QCOMPARE(plot.regionShaded(), shaded);
    if (shaded) QCOMPARE(plot.shadedRange().second, upper);
    QCOMPARE(plot.legendNames().size(), shaded ? 4 : 3);
  }

  void bestBetaOptional() {
    JcCurveView c = parabola();
    c.best_beta.reset();
    JcCurvePlot plot;
    plot.setCurve(c);
    QVERIFY(!plot.bestBeta());
    c.best_beta = kNaN;
    plot.setCurve(c);
    QVERIFY(!plot.bestBeta());
    c.best_beta = 0.42;  // between sweep points: starred at the nearest point's J_c
    plot.setCurve(c);
    QCOMPARE(*plot.bestBeta(), 0.42);
  }

  // The legend under the plot, never over the curve, the region or the markers: at the plot's minimum
  // size in one column with no name cut, two columns when wide. The region's label inside the axis rect
  // and above the curve in the region.
  void legendUnderThePlot_data() {
    QTest::addColumn<QSize>("size");
    QTest::addColumn<int>("columns");
    QTest::newRow("minimum 390x250") << QSize(390, 250) << 1;
    QTest::newRow("dock at 1080p 390x370") << QSize(390, 370) << 1;
    QTest::newRow("wide 1200x500") << QSize(1200, 500) << 2;
  }
  void legendUnderThePlot() {
    QFETCH(QSize, size);
    QFETCH(int, columns);
    JcCurvePlot plot;
    longestEntries(&plot);
    QVERIFY(size.width() >= plot.minimumWidth() && size.height() >= plot.minimumHeight());
    plot.resize(size);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    auto* custom = plot.findChild<QCustomPlot*>();
    custom->replot();
    QCOMPARE(mx::test::legendProblem(custom), QString());
    QCOMPARE(custom->legend->columnCount(), columns);
    QCPItemText* label = nullptr;
    for (int i = 0; i < custom->itemCount(); ++i)
      if (auto* text = qobject_cast<QCPItemText*>(custom->item(i)); text && text->text().contains("unstable"))
        label = text;
    QVERIFY(label && label->visible());
    const QRect data = custom->axisRect()->rect();
    QVERIFY(data.contains(label->topLeft->pixelPosition().toPoint()));
    QVERIFY(data.contains(label->bottomRight->pixelPosition().toPoint()));
    const double highest = 5000.0 * (2.0 + 5.0 * 0.7 * 0.7);  // J_c at beta = -1
    if (size.height() >= 370) QCOMPARE_LT(label->bottom->pixelPosition().y(), custom->yAxis->coordToPixel(highest));
  }

  void savesPng() {
    QTemporaryDir dir;
    JcCurvePlot plot;
    plot.setCurve(parabola());
    QVERIFY(plot.savePng(dir.filePath("jc.png"), 900, 500));
    QCOMPARE(QImage(dir.filePath("jc.png")).size(), QSize(900, 500));
    QVERIFY(!plot.savePng(dir.filePath("jc.png"), 0, 500));
  }
};

MX_REGISTER_TEST(TestJcCurvePlot)
#include "test_jc_curve_plot.moc"
