// The ternary weight picker: corners and centre map to the simplex vertices and barycentre, a mouse
// press/drag sets the barycentric coordinates of the pointer (clamped onto the triangle outside it),
// live weightsChanged and weightsCommitted on release, setWeights() silent.
#include <QApplication>
#include <QSignalSpy>
#include <cmath>

#include "support/weight_triples.h"
#include "ternary_picker.h"
#include "test_registry.h"

using mx::widgets::TernaryPicker;

namespace {

double pixelDistance(const QPointF& a, const QPointF& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

void verifySimplex(const W3& w) {
  for (double v : w) QVERIFY(v >= 0.0 && v <= 1.0);
  QVERIFY(std::abs(w[0] + w[1] + w[2] - 1.0) <= 1e-12);
}

}  // namespace

class TestTernaryPicker : public QObject {
  Q_OBJECT
 private:
  TernaryPicker* picker_ = nullptr;

 private slots:
  void init() {
    picker_ = new TernaryPicker;
    picker_->resize(300, 280);
    picker_->show();
    QVERIFY(QTest::qWaitForWindowExposed(picker_));
  }
  void cleanup() { delete picker_; }

  void cornersAndCentre() {
    const TernaryPicker& t = *picker_;
    const W3 unit[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
      QVERIFY(pixelDistance(t.pointFor(unit[i]), t.corner(i)) < 1e-9);
      const W3 w = t.weightsAt(t.corner(i));
      for (int j = 0; j < 3; ++j) QVERIFY(std::abs(w[j] - unit[i][j]) <= 1e-9);
    }
    // Equilateral, inside the widget, c3 on top.
    const double ab = pixelDistance(t.corner(0), t.corner(1)), bc = pixelDistance(t.corner(1), t.corner(2)),
                 ca = pixelDistance(t.corner(2), t.corner(0));
    QVERIFY(ab > 100.0);
    QVERIFY(std::abs(ab - bc) < 1e-9 && std::abs(ab - ca) < 1e-9);
    QVERIFY(t.corner(2).y() < t.corner(0).y());
    for (int i = 0; i < 3; ++i) QVERIFY(t.rect().contains(t.corner(i).toPoint()));
    const QPointF centre = (t.corner(0) + t.corner(1) + t.corner(2)) / 3.0;
    QVERIFY(pixelDistance(t.pointFor({1.0 / 3, 1.0 / 3, 1.0 / 3}), centre) < 1e-9);
    const W3 w = t.weightsAt(centre);
    for (double v : w) QVERIFY(std::abs(v - 1.0 / 3.0) <= 1e-9);
    // Round trip of an interior point.
    const W3 q{0.2, 0.725, 0.075};
    const W3 back = t.weightsAt(t.pointFor(q));
    for (int j = 0; j < 3; ++j) QVERIFY(std::abs(back[j] - q[j]) <= 1e-9);
  }

  void pressAndDragInside() {
    TernaryPicker& t = *picker_;
    QSignalSpy changed(&t, &TernaryPicker::weightsChanged);
    QSignalSpy committed(&t, &TernaryPicker::weightsCommitted);
    const W3 first{0.5, 0.3, 0.2}, second{0.1, 0.2, 0.7};
    const QPoint p1 = t.pointFor(first).toPoint(), p2 = t.pointFor(second).toPoint();
    // One pixel of rounding is at most 1 / (triangle height) in each weight.
    const double tol = 1.5 / (pixelDistance(t.corner(0), t.corner(1)) * std::sqrt(3.0) / 2.0);
    QTest::mousePress(&t, Qt::LeftButton, {}, p1);
    QCOMPARE(changed.count(), 1);
    W3 w = changed.last().at(0).value<W3>();
    for (int j = 0; j < 3; ++j) QVERIFY2(std::abs(w[j] - first[j]) <= tol, qPrintable(QString::number(w[j])));
    QCOMPARE(w, t.weights());
    verifySimplex(w);
    QTest::mouseMove(&t, p2);
    QVERIFY(changed.count() >= 2);
    w = t.weights();
    for (int j = 0; j < 3; ++j) QVERIFY2(std::abs(w[j] - second[j]) <= tol, qPrintable(QString::number(w[j])));
    QCOMPARE(w, t.weightsAt(QPointF(p2)));  // exactly the barycentric coordinates of the pointer
    QCOMPARE(committed.count(), 0);
    QTest::mouseRelease(&t, Qt::LeftButton, {}, p2);
    QCOMPARE(committed.count(), 1);
    QCOMPARE(committed.at(0).at(0).value<W3>(), w);
  }

  void pressOutsideClampsOntoTheEdge() {
    TernaryPicker& t = *picker_;
    QSignalSpy changed(&t, &TernaryPicker::weightsChanged);
    // Below the base, under its midpoint: c3 = 0, c1 = c2 = 0.5.
    const QPointF base = (t.corner(0) + t.corner(1)) / 2.0;
    QTest::mousePress(&t, Qt::LeftButton, {}, (base + QPointF(0, 12)).toPoint());
    W3 w = t.weights();
    QCOMPARE(w[2], 0.0);
    QVERIFY(std::abs(w[0] - 0.5) < 0.01 && std::abs(w[1] - 0.5) < 0.01);
    verifySimplex(w);
    // Dragged far beyond the c2 corner: exactly (0, 1, 0).
    QTest::mouseMove(&t, (t.corner(1) + QPointF(30, 30)).toPoint());
    QCOMPARE(t.weights(), (W3{0.0, 1.0, 0.0}));
    // Left of the left edge, halfway up: on the c1-c3 edge.
    const QPointF mid = (t.corner(0) + t.corner(2)) / 2.0;
    QTest::mouseMove(&t, (mid + QPointF(-8, 0)).toPoint());
    w = t.weights();
    QCOMPARE(w[1], 0.0);
    QVERIFY(std::abs(w[0] - 0.5) < 0.03 && std::abs(w[2] - 0.5) < 0.03);
    verifySimplex(w);
    QTest::mouseRelease(&t, Qt::LeftButton, {}, (mid + QPointF(-8, 0)).toPoint());
    QVERIFY(changed.count() >= 3);
  }

  void setWeightsIsSilentAndNormalises() {
    TernaryPicker& t = *picker_;
    QSignalSpy changed(&t, &TernaryPicker::weightsChanged);
    t.setWeights({0.2, 0.725, 0.075});
    QCOMPARE(changed.count(), 0);
    QCOMPARE(t.weights(), (W3{0.2, 0.725, 0.075}));
    t.setWeights({2.0, 2.0, -1.0});  // off the simplex: clamped and renormalised
    QCOMPARE(t.weights(), (W3{0.5, 0.5, 0.0}));
    QVERIFY(t.toolTip().contains("c1 = 0.500"));
    QVERIFY(!t.grab().isNull());  // paints
  }
};

MX_REGISTER_TEST(TestTernaryPicker)
#include "test_ternary_picker.moc"
