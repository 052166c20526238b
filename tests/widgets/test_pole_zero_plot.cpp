// PoleZeroPlot: poles and zeros of H_beta plotted (non-finite roots left out), zeros outside the unit
// circle counted and shown as unstable, coincident roots labelled with their multiplicity, labelled
// axes, and an equal aspect whatever the plot's shape.
#include <QApplication>
#include <QTemporaryDir>
#include <cmath>
#include <limits>

#include "pole_zero_plot.h"
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
