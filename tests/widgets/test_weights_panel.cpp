// The weights panel: every group stays on its simplex; moving one slider rescales the others of its
// group proportionally (equal shares when they are all zero); live and committed signals; the ternary
// picker follows the c sliders and moves them.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <cmath>

#include "support/weight_triples.h"
#include "ternary_picker.h"
#include "test_registry.h"
#include "weights_panel.h"

using mx::CostWeights;
using mx::widgets::TernaryPicker;
using mx::widgets::WeightsPanel;
using Group = WeightsPanel::Group;

namespace {

double sum(std::span<const double> w) {
  double s = 0.0;
  for (double v : w) s += v;
  return s;
}

void verifySimplex(std::span<const double> w, const char* what) {
  for (double v : w) QVERIFY2(v >= 0.0 && v <= 1.0, what);
  QVERIFY2(std::abs(sum(w) - 1.0) <= 1e-12, qPrintable(QString("%1: sum - 1 = %2").arg(what).arg(sum(w) - 1.0)));
}

void verifyAll(const CostWeights& w) {
  verifySimplex(w.c, "c");
  verifySimplex(w.cr, "cr");
  verifySimplex(w.ct, "ct");
  verifySimplex(w.cf, "cf");
}

}  // namespace

class TestWeightsPanel : public QObject {
  Q_OBJECT
 private slots:
  void movingOneSlider_data() {
    QTest::addColumn<W3>("start");
    QTest::addColumn<int>("index");
    QTest::addColumn<double>("value");
    QTest::addColumn<W3>("expected");
    QTest::newRow("paper c2 -> 0.8") << W3{0.2, 0.725, 0.075} << 1 << 0.8
                                     << W3{0.2 * 0.2 / 0.275, 0.8, 0.075 * 0.2 / 0.275};
    QTest::newRow("c1 -> 1") << W3{0.2, 0.725, 0.075} << 0 << 1.0 << W3{1.0, 0.0, 0.0};
    QTest::newRow("from corner c2 -> 0.5") << W3{1.0, 0.0, 0.0} << 1 << 0.5 << W3{0.5, 0.5, 0.0};
    QTest::newRow("others zero: equal split") << W3{1.0, 0.0, 0.0} << 0 << 0.4 << W3{0.4, 0.3, 0.3};
    QTest::newRow("c3 -> 0") << W3{0.3, 0.3, 0.4} << 2 << 0.0 << W3{0.5, 0.5, 0.0};
    QTest::newRow("c3 -> 1") << W3{0.3, 0.3, 0.4} << 2 << 1.0 << W3{0.0, 0.0, 1.0};
    QTest::newRow("c1 up, ratio kept") << W3{0.1, 0.6, 0.3} << 0 << 0.55 << W3{0.55, 0.3, 0.15};
  }

  void movingOneSlider() {
    QFETCH(W3, start);
    QFETCH(int, index);
    QFETCH(double, value);
    QFETCH(W3, expected);
    WeightsPanel panel;
    CostWeights w;
    w.c = start;
    panel.setWeights(w);
    QSignalSpy changed(&panel, &WeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &WeightsPanel::weightsCommitted);
    panel.slider(Group::Tool, index)->setValue(int(std::lround(value * WeightsPanel::kSliderSteps)));
    const W3 c = panel.weights().c;
    for (int i = 0; i < 3; ++i)
      QVERIFY2(std::abs(c[i] - expected[i]) <= 1e-9, qPrintable(QString("c%1 = %2").arg(i + 1).arg(c[i], 0, 'g', 17)));
    verifySimplex(c, "c");
    QCOMPARE(changed.count(), 1);
    QCOMPARE(committed.count(), 1);  // not dragged: a keyboard/programmatic move is a finished change
    QCOMPARE(changed.at(0).at(0).value<CostWeights>().c, c);
    QCOMPARE(committed.at(0).at(0).value<CostWeights>().c, c);
    // The other controls follow, and the ternary marker too.
    for (int i = 0; i < 3; ++i) {
      QCOMPARE(panel.slider(Group::Tool, i)->value(), int(std::lround(c[i] * WeightsPanel::kSliderSteps)));
      QVERIFY(std::abs(panel.spinBox(Group::Tool, i)->value() - c[i]) <= 0.0005);
      QVERIFY(std::abs(panel.ternaryPicker()->weights()[i] - c[i]) <= 1e-12);
    }
    QCOMPARE(panel.weights().cr, w.cr);  // other groups untouched
  }

  void cornerThenHalf() {  // the edge case as a sequence: c1 -> 1 gives (1,0,0), then c2 -> 0.5 gives (0.5,0.5,0)
    WeightsPanel panel;
    panel.setWeights(CostWeights{});
    panel.slider(Group::Tool, 0)->setValue(1000);
    QCOMPARE(panel.weights().c, (W3{1.0, 0.0, 0.0}));
    panel.slider(Group::Tool, 1)->setValue(500);
    QCOMPARE(panel.weights().c, (W3{0.5, 0.5, 0.0}));
  }

  void setWeightsEmitsNothing() {
    WeightsPanel panel;
    QSignalSpy changed(&panel, &WeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &WeightsPanel::weightsCommitted);
    CostWeights w;
    w.c = {0.1, 0.2, 0.7};
    w.cr = {0.6, 0.3, 0.1};
    w.ct = {0.25, 0.75};
    w.cf = {0.9, 0.1};
    panel.setWeights(w);
    QCOMPARE(changed.count(), 0);
    QCOMPARE(committed.count(), 0);
    QCOMPARE(panel.weights().c, w.c);
    QCOMPARE(panel.weights().ct, w.ct);
    QCOMPARE(panel.slider(Group::Tool, 2)->value(), 700);
    QCOMPARE(panel.spinBox(Group::Frequency, 0)->value(), 0.9);
    QCOMPARE(panel.ternaryPicker()->weights(), w.c);
  }

  void dragIsLiveThenCommittedOnRelease() {
    WeightsPanel panel;
    panel.setWeights(CostWeights{});
    QSignalSpy changed(&panel, &WeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &WeightsPanel::weightsCommitted);
    QSlider* s = panel.slider(Group::Tool, 2);
    s->setSliderDown(true);
    for (int v : {100, 200, 300}) s->setValue(v);
    QCOMPARE(changed.count(), 3);
    QCOMPARE(committed.count(), 0);
    QVERIFY(std::abs(changed.last().at(0).value<CostWeights>().c[2] - 0.3) <= 1e-12);
    s->setSliderDown(false);  // release
    QCOMPARE(committed.count(), 1);
    QVERIFY(std::abs(committed.at(0).at(0).value<CostWeights>().c[2] - 0.3) <= 1e-12);
    verifyAll(panel.weights());
    s->setSliderDown(true);  // press and release without a move: nothing to commit
    s->setSliderDown(false);
    QCOMPARE(committed.count(), 1);
  }

  void otherGroupsStayOnTheirSimplex() {
    WeightsPanel panel;
    panel.setWeights(CostWeights{});  // cr (0.8, 0.1, 0.1), ct (0.5, 0.5), cf (0.5, 0.5)
    panel.slider(Group::Resultant, 0)->setValue(500);
    QVERIFY(std::abs(panel.weights().cr[1] - 0.25) <= 1e-12);
    QVERIFY(std::abs(panel.weights().cr[2] - 0.25) <= 1e-12);
    panel.spinBox(Group::Resultant, 2)->setValue(0.9);
    QVERIFY(std::abs(panel.weights().cr[0] - 0.1 * 2.0 / 3.0) <= 1e-12);  // 0.5 : 0.25 kept
    QVERIFY(std::abs(panel.weights().cr[1] - 0.1 / 3.0) <= 1e-12);
    panel.slider(Group::Time, 1)->setValue(800);
    QCOMPARE(panel.weights().ct[1], 0.8);
    QVERIFY(std::abs(panel.weights().ct[0] - 0.2) <= 1e-15);
    panel.spinBox(Group::Frequency, 0)->setValue(0.123);
    QVERIFY(std::abs(panel.weights().cf[1] - 0.877) <= 1e-15);
    verifyAll(panel.weights());
    // A long random walk over every control keeps every group on its simplex.
    quint32 seed = 12345;
    auto next = [&] { return (seed = seed * 1664525u + 1013904223u) >> 8; };
    for (int k = 0; k < 2000; ++k) {
      const Group g = Group(next() % 4);
      const int n = g == Group::Tool || g == Group::Resultant ? 3 : 2;
      panel.slider(g, int(next() % n))->setValue(int(next() % 1001));
      verifyAll(panel.weights());
    }
  }

  void ternaryDragMovesTheSliders() {
    WeightsPanel panel;
    panel.resize(400, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setWeights(CostWeights{});
    QSignalSpy changed(&panel, &WeightsPanel::weightsChanged);
    QSignalSpy committed(&panel, &WeightsPanel::weightsCommitted);
    TernaryPicker* t = panel.ternaryPicker();
    const QPoint centre = t->pointFor({1.0 / 3, 1.0 / 3, 1.0 / 3}).toPoint();
    QTest::mousePress(t, Qt::LeftButton, {}, centre);
    QVERIFY(changed.count() >= 1);
    QCOMPARE(committed.count(), 0);
    QTest::mouseRelease(t, Qt::LeftButton, {}, centre);
    QCOMPARE(committed.count(), 1);
    const W3 c = panel.weights().c;
    verifySimplex(c, "c");
    for (int i = 0; i < 3; ++i) {
      QVERIFY2(std::abs(c[i] - 1.0 / 3) < 0.02, qPrintable(QString::number(c[i])));
      QCOMPARE(panel.slider(Group::Tool, i)->value(), int(std::lround(c[i] * 1000)));
    }
  }

  void tooltipsAndReset() {
    WeightsPanel panel;
    for (Group g : {Group::Tool, Group::Resultant, Group::Time, Group::Frequency})
      for (int i = 0; i < 3; ++i) {
        if (!panel.slider(g, i)) {
          QVERIFY(i == 2 && (g == Group::Time || g == Group::Frequency));
          continue;
        }
        QVERIFY(!panel.slider(g, i)->toolTip().isEmpty());
        QVERIFY(!panel.spinBox(g, i)->toolTip().isEmpty());
        QCOMPARE(panel.spinBox(g, i)->decimals(), 3);
      }
    QVERIFY(!panel.ternaryPicker()->toolTip().isEmpty());
    QVERIFY(!panel.resetButton()->toolTip().isEmpty());
    QSignalSpy reset(&panel, &WeightsPanel::resetRequested);
    panel.resetButton()->click();
    QCOMPARE(reset.count(), 1);
  }

  void moveWeightRule() {
    std::array<double, 2> pair{0.5, 0.5};
    WeightsPanel::moveWeight(pair, 0, 0.3);
    QCOMPARE(pair[0], 0.3);
    QCOMPARE(pair[1], 0.7);
    std::array<double, 3> c{0.2, 0.725, 0.075};
    WeightsPanel::moveWeight(c, 1, 1.7);  // clamped
    QCOMPARE(c, (W3{0.0, 1.0, 0.0}));
    WeightsPanel::moveWeight(c, 1, -0.5);  // clamped, equal split of the remainder
    QCOMPARE(c, (W3{0.5, 0.0, 0.5}));
  }
};

MX_REGISTER_TEST(TestWeightsPanel)
#include "test_weights_panel.moc"
