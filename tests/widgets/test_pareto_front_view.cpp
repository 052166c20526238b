// The Pareto-front view: the axes show the objectives chosen in the combo boxes (with units), the
// colour scale the third one; clicking a point's pixel activates that point; far clicks do nothing.
#include <QApplication>
#include <QComboBox>
#include <QSignalSpy>
#include <cstdlib>

#include "pareto_front_view.h"
#include "test_registry.h"

using mx::widgets::ParetoFrontView;
using mx::widgets::ParetoPointView;
using Axis = ParetoFrontView::Axis;

namespace {

QVector<ParetoPointView> samplePoints() {
  QVector<ParetoPointView> pts;
  for (int i = 0; i < 5; ++i) {
    ParetoPointView p;
    p.speed_rpm = 6000.0 + 1000.0 * i;
    p.depth_mm = 0.5 + 0.25 * i;
    p.feed_mm_per_tooth = 0.05 + 0.01 * i;
    p.tol = 60.0 - 10.0 * i;
    p.mrr_cm3_s = 1.0 + 2.0 * i;
    p.surf = 0.8 + 0.3 * i * i;
    p.ros = 0.9 - 0.15 * i;
    if (i == 2) p.weights = std::array<double, 4>{0.1, 0.7, 0.1, 0.1};
    pts.push_back(p);
  }
  return pts;
}

void settle(ParetoFrontView& view) {
  for (int k = 0; k < 5; ++k) QCoreApplication::processEvents();
  QTest::qWait(20);
  QCoreApplication::processEvents();
  Q_UNUSED(view);
}

}  // namespace

class TestParetoFrontView : public QObject {
  Q_OBJECT
 private slots:
  void axesFollowTheCombos() {
    ParetoFrontView view;
    view.setPoints(samplePoints());
    QCOMPARE(view.xAxis(), Axis::Mrr);
    QCOMPARE(view.yAxis(), Axis::Tol);
    QCOMPARE(view.plottedValue(3), QPointF(420.0, 30.0));  // 7 cm³/s in cm³/min
    QVERIFY(view.xAxisLabel().contains(QString::fromUtf8("[cm³/min]")));
    QVERIFY(view.yAxisLabel().contains("[min]"));
    QVERIFY(view.colourScaleLabel().contains(QString::fromUtf8("[µm]")));

    view.xCombo()->setCurrentIndex(static_cast<int>(Axis::Surf));
    QCOMPARE(view.xAxis(), Axis::Surf);
    QCOMPARE(view.plottedValue(3).x(), 0.8 + 0.3 * 9);
    QCOMPARE(view.plottedValue(3).y(), 30.0);
    QVERIFY(view.xAxisLabel().contains(QString::fromUtf8("[µm]")));

    view.yCombo()->setCurrentIndex(static_cast<int>(Axis::Ros));
    QCOMPARE(view.plottedValue(4), QPointF(0.8 + 0.3 * 16, 0.9 - 0.6));
    QVERIFY(view.yAxisLabel().contains(QString::fromUtf8("[\u2013]")));

    view.colourCombo()->setCurrentIndex(static_cast<int>(Axis::Mrr));
    QVERIFY(view.colourScaleLabel().contains(QString::fromUtf8("[cm³/min]")));

    view.setAxes(Axis::Tol, Axis::Mrr, Axis::Ros);
    QCOMPARE(view.xCombo()->currentIndex(), 0);
    QCOMPARE(view.plottedValue(1), QPointF(50.0, 180.0));
    QCOMPARE(view.plottedValue(7), QPointF());
  }

  void axisSwitchMovesThePixels() {
    ParetoFrontView view;
    view.resize(640, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setPoints(samplePoints());
    settle(view);
    const QPoint before = view.pixelFor(4);
    view.yCombo()->setCurrentIndex(static_cast<int>(Axis::Surf));  // TOL falls with i, SURF rises
    settle(view);
    const QPoint after = view.pixelFor(4);
    QVERIFY2(after.y() < before.y() - 50, qPrintable(QString("%1 -> %2").arg(before.y()).arg(after.y())));
    // Same x data; only the y tick labels' width may shift the axis rect by a few pixels.
    QVERIFY(std::abs(after.x() - before.x()) <= 30);
  }

  void clickingAPointActivatesIt() {
    ParetoFrontView view;
    view.resize(640, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QVector<ParetoPointView> pts = samplePoints();
    view.setPoints(pts);
    settle(view);
    QSignalSpy spy(&view, &ParetoFrontView::pointActivated);
    for (int i = 0; i < pts.size(); ++i) {
      const QPoint p = view.pixelFor(i);
      QVERIFY(view.plotWidget()->rect().contains(p));
      QTest::mouseClick(view.plotWidget(), Qt::LeftButton, {}, p + QPoint(3, -2));
      QCOMPARE(spy.count(), i + 1);
      const auto got = spy.at(i).at(0).value<ParetoPointView>();
      QCOMPARE(got.speed_rpm, pts[i].speed_rpm);
      QCOMPARE(got.depth_mm, pts[i].depth_mm);
      QCOMPARE(got.weights.has_value(), i == 2);
      QCOMPARE(view.selectedIndex(), i);
    }
    // Hovering a point shows its values; elsewhere the general tool tip.
    QTest::mouseMove(view.plotWidget(), view.pixelFor(2));
    QVERIFY2(view.plotWidget()->toolTip().contains("N = 8000 rpm"), qPrintable(view.plotWidget()->toolTip()));
    QVERIFY(view.plotWidget()->toolTip().contains("weights (TOL, MRR, SURF, ROS) = (0.1, 0.7, 0.1, 0.1)"));
    // Far from every point (> 10 px): nothing.
    const QPoint a = view.pixelFor(0), b = view.pixelFor(1);
    QTest::mouseClick(view.plotWidget(), Qt::LeftButton, {}, (a + b) / 2 + QPoint(0, 40));
    QCOMPARE(spy.count(), pts.size());
    QVERIFY(!view.xCombo()->toolTip().isEmpty() && !view.yCombo()->toolTip().isEmpty());
    QVERIFY(!view.colourCombo()->toolTip().isEmpty() && !view.plotWidget()->toolTip().isEmpty());
  }

  void emptyAndSinglePoint() {
    ParetoFrontView view;
    view.setPoints({});
    QCOMPARE(view.pixelFor(0), QPoint(-1, -1));
    view.setPoints({samplePoints().front()});
    view.setSelectedIndex(0);
    QCOMPARE(view.selectedIndex(), 0);
    view.setPoints({});
    QCOMPARE(view.selectedIndex(), -1);
  }
};

MX_REGISTER_TEST(TestParetoFrontView)
#include "test_pareto_front_view.moc"
