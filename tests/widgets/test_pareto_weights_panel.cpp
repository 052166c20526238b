// The Pareto weights panel: w = (TOL, MRR, SURF, ROS) stays on the simplex; moving one weight rescales
// the others proportionally (equal shares when they are all zero); live and committed signals;
// setWeights() is silent.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <cmath>

#include "pareto_weights_panel.h"
#include "test_registry.h"

using mx::widgets::ParetoWeightsPanel;
using W4 = std::array<double, 4>;

Q_DECLARE_METATYPE(W4)

namespace {

void verifyNear(const W4& got, const W4& want) {
  double sum = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    QVERIFY2(std::abs(got[i] - want[i]) <= 1e-12,
             qPrintable(QString("w[%1] = %2, expected %3").arg(i).arg(got[i], 0, 'g', 17).arg(want[i])));
    QVERIFY(got[i] >= 0.0);
    sum += got[i];
  }
  QVERIFY(std::abs(sum - 1.0) <= 1e-12);
}

}  // namespace

class TestParetoWeightsPanel : public QObject {
  Q_OBJECT
 private slots:
  void simplexRule_data() {
    QTest::addColumn<W4>("start");
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");
    QTest::addColumn<W4>("expected");
    QTest::newRow("w2 -> 0.7 from equal") << W4{0.25, 0.25, 0.25, 0.25} << 1 << 0.7 << W4{0.1, 0.7, 0.1, 0.1};
    QTest::newRow("ratios kept") << W4{0.1, 0.2, 0.3, 0.4} << 3 << 0.1 << W4{0.15, 0.3, 0.45, 0.1};
    QTest::newRow("others zero: equal split") << W4{1.0, 0.0, 0.0, 0.0} << 0 << 0.4 << W4{0.4, 0.2, 0.2, 0.2};
    QTest::newRow("to 1") << W4{0.1, 0.2, 0.3, 0.4} << 2 << 1.0 << W4{0.0, 0.0, 1.0, 0.0};
    QTest::newRow("clamped above 1") << W4{0.1, 0.2, 0.3, 0.4} << 0 << 1.5 << W4{1.0, 0.0, 0.0, 0.0};
    QTest::newRow("to 0") << W4{0.5, 0.5, 0.0, 0.0} << 0 << 0.0 << W4{0.0, 1.0, 0.0, 0.0};
  }
  void simplexRule() {
    QFETCH(W4, start);
    QFETCH(int, index);
    QFETCH(double, value);
    QFETCH(W4, expected);
    W4 w = start;
    ParetoWeightsPanel::moveWeight(w, static_cast<std::size_t>(index), value);
    verifyNear(w, expected);
  }

  void spinBoxMovesAndSignals() {
    ParetoWeightsPanel panel;
    QSignalSpy live(&panel, &ParetoWeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &ParetoWeightsPanel::weightsCommitted);
    verifyNear(panel.weights(), {0.25, 0.25, 0.25, 0.25});
    panel.spinBox(1)->setValue(0.7);
    verifyNear(panel.weights(), {0.1, 0.7, 0.1, 0.1});
    QCOMPARE(live.count(), 1);
    QCOMPARE(committed.count(), 1);
    verifyNear(committed.at(0).at(0).value<W4>(), {0.1, 0.7, 0.1, 0.1});
    // The other controls follow.
    QCOMPARE(panel.slider(0)->value(), 100);
    QCOMPARE(panel.slider(1)->value(), 700);
    QCOMPARE(panel.spinBox(3)->value(), 0.1);
    QCOMPARE(panel.slider(4), nullptr);
  }

  void sliderDragIsLiveThenCommitsOnRelease() {
    ParetoWeightsPanel panel;
    QSignalSpy live(&panel, &ParetoWeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &ParetoWeightsPanel::weightsCommitted);
    QSlider* s = panel.slider(1);
    s->setSliderDown(true);
    s->setValue(500);
    s->setValue(700);
    QCOMPARE(live.count(), 2);
    QCOMPARE(committed.count(), 0);
    s->setSliderDown(false);  // emits sliderReleased
    QCOMPARE(committed.count(), 1);
    verifyNear(panel.weights(), {0.1, 0.7, 0.1, 0.1});
  }

  void setWeightsIsSilentAndProjects() {
    ParetoWeightsPanel panel;
    QSignalSpy live(&panel, &ParetoWeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &ParetoWeightsPanel::weightsCommitted);
    panel.setWeights({0.4, 0.3, 0.2, 0.1});
    verifyNear(panel.weights(), {0.4, 0.3, 0.2, 0.1});
    QCOMPARE(panel.slider(0)->value(), 400);
    QCOMPARE(panel.spinBox(3)->value(), 0.1);
    panel.setWeights({2.0, 1.0, 1.0, 0.0});  // not on the simplex: normalised
    verifyNear(panel.weights(), {0.5, 0.25, 0.25, 0.0});
    QCOMPARE(live.count(), 0);
    QCOMPARE(committed.count(), 0);
  }

  void everyControlHasATooltip() {
    ParetoWeightsPanel panel;
    for (int i = 0; i < 4; ++i) {
      QVERIFY(!panel.slider(i)->toolTip().isEmpty());
      QVERIFY(!panel.spinBox(i)->toolTip().isEmpty());
    }
  }
};

MX_REGISTER_TEST(TestParetoWeightsPanel)
#include "test_pareto_weights_panel.moc"
