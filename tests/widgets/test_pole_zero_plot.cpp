// PoleZeroPlot: poles and zeros of H_beta plotted (non-finite roots left out), zeros outside the unit
// circle counted and shown as unstable, coincident roots labelled with their multiplicity, labelled
// axes, and an equal aspect whatever the plot's shape; the legend under the map, never over it.
#include <qcustomplot.h>

#include <QApplication>
#include <QTemporaryDir>
#include <cmath>
#include <limits>

#include "pole_zero_plot.h"
#include "support/plot_layout_checks.h"
#include "test_registry.h"

using mx::widgets::PoleZeroPlot;
using mx::widgets::PoleZeroView;
using C = std::complex<double>;
Q_DECLARE_METATYPE(QVector<C>)

class TestPoleZeroPlot : public QObject {
  Q_OBJECT
 private slots:
  void axesAndLegend() {
    PoleZeroPlot plot;
    QCOMPARE(plot.xAxisLabel(), QString("Re z [\u2013]"));
    QCOMPARE(plot.yAxisLabel(), QString("Im z [\u2013]"));
    QCOMPARE(plot.legendNames(), QStringList({"Unit circle |z| = 1", "Poles \u00d7", "Zeros \u25cb"}));
    QCOMPARE(plot.poleCount(), 0);
    QCOMPARE(plot.zeroCount(), 0);
  }

  void rootsPlotted_data() {
    QTest::addColumn<QVector<C>>("poles");
    QTest::addColumn<QVector<C>>("zeros");
    QTest::addColumn<int>("n_poles");
    QTest::addColumn<int>("n_zeros");
    QTest::addColumn<int>("n_unstable");
    QTest::addColumn<int>("n_labels");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("beta = 0: 2 poles, 1 zero")
        << QVector<C>{{0.0, 0.0}, {0.6, 0.0}} << QVector<C>{{-0.4, 0.0}} << 2 << 1 << 0 << 0;
    QTest::newRow("beta != 0: double pole at 0")
        << QVector<C>{{0.0, 0.0}, {0.0, 0.0}, {0.6, 0.0}} << QVector<C>{{-0.4, 0.0}, {0.1, 0.0}} << 3 << 2 << 0 << 1;
    QTest::newRow("unstable zero") << QVector<C>{{0.6, 0.0}} << QVector<C>{{-1.8, 0.0}, {0.2, 0.0}} << 1 << 2 << 1 << 0;
    QTest::newRow("zero on the circle is not unstable") << QVector<C>{} << QVector<C>{{-1.0, 0.0}} << 0 << 1 << 0 << 0;
    QTest::newRow("complex pair") << QVector<C>{{0.5, 0.4}, {0.5, -0.4}} << QVector<C>{} << 2 << 0 << 0 << 0;
    QTest::newRow("NaN roots left out") << QVector<C>{{nan, 0.0}, {0.3, 0.0}} << QVector<C>{{0.0, nan}} << 1 << 0 << 0
                                        << 0;
    QTest::newRow("double zero and triple pole")
        << QVector<C>{{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}} << QVector<C>{{-0.5, 0.0}, {-0.5, 0.0}} << 3 << 2 << 0 << 2;
  }
  void rootsPlotted() {
    QFETCH(QVector<C>, poles);
    QFETCH(QVector<C>, zeros);
    QFETCH(int, n_poles);
    QFETCH(int, n_zeros);
    QFETCH(int, n_unstable);
    QFETCH(int, n_labels);
    PoleZeroPlot plot;
    plot.setPoleZero({poles, zeros});
    QCOMPARE(plot.poleCount(), n_poles);
    QCOMPARE(plot.zeroCount(), n_zeros);
    QCOMPARE(plot.unstableZeroCount(), n_unstable);
    QCOMPARE(plot.multiplicityLabelCount(), n_labels);
    QCOMPARE(plot.legendNames().contains("Unstable zeros |z| > 1"), n_unstable > 0);
    // Every root and the unit circle in view.
    const auto [x0, x1] = plot.xRange();
    const auto [y0, y1] = plot.yRange();
    QVERIFY(x0 < -1.0 && x1 > 1.0 && y0 < -1.0 && y1 > 1.0);
    for (const C& z : poles + zeros)
      if (std::isfinite(z.real()) && std::isfinite(z.imag()))
        QVERIFY(z.real() > x0 && z.real() < x1 && z.imag() > y0 && z.imag() < y1);
  }

  void replacingRootsClearsLabels() {
    PoleZeroPlot plot;
    plot.setPoleZero({{{0.0, 0.0}, {0.0, 0.0}}, {}});
    QCOMPARE(plot.multiplicityLabelCount(), 1);
    plot.setPoleZero({{{0.2, 0.0}}, {}});
    QCOMPARE(plot.multiplicityLabelCount(), 0);
    plot.clear();
    QCOMPARE(plot.poleCount(), 0);
  }

  // The legend under the map (the unit circle and every root stay uncovered), in as many columns as the
  // width holds with no name cut; the circle and the roots inside the axes' ranges.
  void legendUnderTheMap_data() {
    QTest::addColumn<QSize>("size");
    QTest::addColumn<int>("columns");
    QTest::newRow("minimum 220x210") << QSize(220, 210) << 1;
    QTest::newRow("dock at 1080p 260x370") << QSize(260, 370) << 1;
    QTest::newRow("stacked 360x300") << QSize(360, 300) << 2;
    QTest::newRow("wide 700x400") << QSize(700, 400) << 4;
  }
  void legendUnderTheMap() {
    QFETCH(QSize, size);
    QFETCH(int, columns);
    PoleZeroPlot plot;
    plot.setCaption("Poles and zeros, \u03b2 = \u22120.80");
    plot.setPoleZero({{{0.0, 0.0}, {0.0, 0.0}, {0.61, 0.0}}, {{-0.4, 0.0}, {-1.3, 0.0}}});
    QVERIFY(size.width() >= plot.minimumWidth() && size.height() >= plot.minimumHeight());
    plot.resize(size);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    auto* custom = plot.findChild<QCustomPlot*>();
    custom->replot();
    QCOMPARE(mx::test::legendProblem(custom), QString());
    QCOMPARE(mx::test::captionProblem(custom), QString());
    QCOMPARE(custom->legend->itemCount() >= 4 ? custom->legend->columnCount() : -1, columns);
    QVERIFY(plot.xRange().first < -1.3 && plot.xRange().second > 1.0);
    QVERIFY(plot.yRange().first < -1.0 && plot.yRange().second > 1.0);
  }

  void equalAspect_data() {
    QTest::addColumn<QSize>("size");
    QTest::newRow("wide") << QSize(800, 300);
    QTest::newRow("tall") << QSize(300, 700);
    QTest::newRow("square") << QSize(500, 500);
  }
  void equalAspect() {
    QFETCH(QSize, size);
    QTemporaryDir dir;
    PoleZeroPlot plot;
    plot.setPoleZero({{{0.6, 0.0}}, {{-1.8, 0.0}}});
    QVERIFY(plot.savePng(dir.filePath("pz.png"), size.width(), size.height()));  // lays the plot out at that size
    QVERIFY2(std::abs(plot.aspectRatio() - 1.0) < 1e-9, qPrintable(QString::number(plot.aspectRatio())));
    QVERIFY(plot.xRange().first < -1.8);  // the unstable zero stays in view
  }
};

MX_REGISTER_TEST(TestPoleZeroPlot)
#include "test_pole_zero_plot.moc"
