// GrafcetChartView: the automatic layout gives every step and transition a rect, steps never
// overlap, levels follow the BFS from the initial step, upward arcs are back arcs; the initial step is
// drawn double; tokens round trip; clicks emit the element's id; fit mode shrinks the drawing no
// further than its labels stay readable (>= 9 pt), then scrolls; the PNG export draws the chart.
#include <QApplication>
#include <QFontInfo>
#include <QImage>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "grafcet_chart_view.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
// SMC II as rebuilt from the paper's rules and Table 2 (states 1-6, receptivities a-e).
GrafcetChartData smc2Chart() {
  GrafcetChartData c;
  c.name = QStringLiteral("SMC II (job shop)");
  c.steps = {{1, "Initialize modules", true, {"E*", "K*"}},
             {2, "No contact and no chatter", false, {"A", "B", "I", "J"}},
             {3, "Reset modules", false, {"A", "B", "E*", "K*"}},
             {4, "Contact and no chatter", false, {"A", "B", "D", "E", "H", "I", "J", "K"}},
             {5, "Operator feed hold active", false, {"A", "B", "C"}},
             {6, "Chatter suppression routine active", false, {"A", "G"}}};
  c.transitions = {{1, {1}, {2}, "1", 1},      {2, {2}, {5}, "a", 1},     {3, {2}, {3}, "b", 2},
                   {4, {3}, {4}, "1", 1},      {5, {4}, {5}, "a", 1},     {7, {4}, {2}, "not b", 2},
                   {6, {4}, {6}, "c or d", 3}, {8, {5}, {2}, "not a", 1}, {9, {6}, {2}, "e", 1}};
  return c;
}
}  // namespace

class TestGrafcetChartView : public QObject {
  Q_OBJECT
 private slots:
  void everyElementHasARectAndStepsDoNotOverlap() {
    GrafcetChartView view;
    view.setChart(smc2Chart());
    const GrafcetChartData c = smc2Chart();
    for (const auto& s : c.steps) QVERIFY2(!view.stepRect(s.id).isNull(), qPrintable(QString::number(s.id)));
    for (const auto& t : c.transitions)
      QVERIFY2(!view.transitionRect(t.id).isNull(), qPrintable(QString::number(t.id)));
    for (const auto& a : c.steps)
      for (const auto& b : c.steps)
        if (a.id < b.id) QVERIFY(!view.stepRect(a.id).adjusted(-4, -4, 4, 4).intersects(view.stepRect(b.id)));
    // Levels of the BFS from the initial step: 1, 2, {3, 5}, 4, 6.
    QVERIFY(view.stepRect(1).bottom() < view.stepRect(2).top());
    QVERIFY(view.stepRect(2).bottom() < view.stepRect(3).top());
    QCOMPARE(view.stepRect(3).top(), view.stepRect(5).top());
    QVERIFY(view.stepRect(3).bottom() < view.stepRect(4).top());
    QVERIFY(view.stepRect(4).bottom() < view.stepRect(6).top());
    // Transitions under a step in priority order, left first: the feed hold (2) under step 2, then (3).
    QCOMPARE(view.stepRect(1).center().x(), view.stepRect(2).center().x());
    QCOMPARE(view.stepRect(5).center().x(), view.stepRect(2).center().x());
    QVERIFY(view.stepRect(3).left() > view.stepRect(5).right());
    QCOMPARE(view.stepRect(4).center().x(), view.stepRect(3).center().x());
    // Bars between their source and the next level, in priority order from the left.
    for (const auto& t : c.transitions)
      QVERIFY(view.transitionRect(t.id).top() > view.stepRect(t.from.front()).bottom());
    QVERIFY(view.transitionRect(5).center().x() < view.transitionRect(7).center().x());
    QVERIFY(view.transitionRect(7).center().x() < view.transitionRect(6).center().x());
    // Upward arcs are back arcs.
    for (int id : {5, 7, 8, 9}) QVERIFY(view.isBackArc(id));
    for (int id : {1, 2, 3, 4, 6}) QVERIFY(!view.isBackArc(id));
    QVERIFY(view.stepDrawnAsInitial(1));
    QVERIFY(!view.stepDrawnAsInitial(2));
    QVERIFY(view.stepRect(42).isNull());
    // The widget is as large as the drawing.
    for (const auto& s : c.steps) QVERIFY(QRectF(QPointF(0, 0), view.minimumSize()).contains(view.stepRect(s.id)));
  }

  void incompleteTransitionsStillHaveABar() {
    GrafcetChartData c = smc2Chart();
    c.transitions.push_back({20, {6}, {}, "x", 2});  // no target
    c.transitions.push_back({21, {}, {4}, "y", 1});  // no source
    c.steps.push_back({7, "Unreachable", false, {}});
    GrafcetChartView view;
    view.setChart(c);
    QVERIFY(!view.transitionRect(20).isNull());
    QVERIFY(!view.transitionRect(21).isNull());
    QVERIFY(!view.stepRect(7).isNull());
    for (const auto& s : c.steps)
      if (s.id != 7) QVERIFY(!view.stepRect(7).intersects(view.stepRect(s.id)));
    view.setChart({});
    QVERIFY(view.stepRect(1).isNull());
  }

  void tokensRoundTrip() {
    GrafcetChartView view;
    view.setChart(smc2Chart());
    QSignalSpy spy(&view, &GrafcetChartView::activeStepsChanged);
    view.setActiveSteps({4, 2, 99});
    QCOMPARE(view.activeSteps(), (QList<int>{2, 4}));
    QCOMPARE(spy.count(), 1);
    view.setActiveSteps({2, 4});
    QCOMPARE(spy.count(), 1);  // unchanged: no signal
    view.setActiveSteps({6});
    QCOMPARE(view.activeSteps(), (QList<int>{6}));
    QCOMPARE(spy.count(), 2);
  }

  void clicksEmitIds() {
    GrafcetChartView view;
    view.setChart(smc2Chart());
    view.resize(view.minimumSize());
    QSignalSpy steps(&view, &GrafcetChartView::stepClicked);
    QSignalSpy transitions(&view, &GrafcetChartView::transitionClicked);
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.stepRect(4).center().toPoint());
    QCOMPARE(steps.count(), 1);
    QCOMPARE(steps.at(0).at(0).toInt(), 4);
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.transitionRect(6).center().toPoint());
    QCOMPARE(transitions.count(), 1);
    QCOMPARE(transitions.at(0).at(0).toInt(), 6);
    QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(2, 2));  // empty paper
    QCOMPARE(steps.count() + transitions.count(), 2);
    view.setSelected(4, -1);
    QCOMPARE(view.selectedStep(), 4);
  }

  void fitModeScalesGeometryAndClicks() {
    GrafcetChartView view;
    view.setChart(smc2Chart());
    const QRectF full = view.stepRect(4);
    const QSizeF content = view.contentSize();
    QCOMPARE(view.scale(), 1.0);
    view.setFitToWidget(true);
    view.resize((content * 0.95).toSize());
    QVERIFY(std::abs(view.scale() - 0.95) < 0.01);
    const QRectF scaled = view.stepRect(4);
    QVERIFY(std::abs(scaled.width() - view.scale() * full.width()) < 0.5);
    QVERIFY(std::abs(scaled.center().x() - view.scale() * full.center().x()) < 0.5);
    QSignalSpy steps(&view, &GrafcetChartView::stepClicked);
    QTest::mouseClick(&view, Qt::LeftButton, {}, scaled.center().toPoint());
    QCOMPARE(steps.count(), 1);
    QCOMPARE(steps.at(0).at(0).toInt(), 4);
    view.resize((content * 2).toSize());  // never scaled up
    QCOMPARE(view.stepRect(4), full);
  }

  // A small dock: the drawing stops shrinking at the least scale and the widget asks a scroll area for
  // the rest, so that no label falls under 9 pt (the labels were ~6 px at half scale).
  void labelsStayReadableInASmallDock_data() {
    QTest::addColumn<double>("fraction");  // of the drawing's size given to the widget
    QTest::addColumn<double>("scale");
    QTest::newRow("all of it") << 1.0 << 1.0;
    QTest::newRow("the least scale") << GrafcetChartView::kMinFitScale << GrafcetChartView::kMinFitScale;
    QTest::newRow("half") << 0.5 << GrafcetChartView::kMinFitScale;
    QTest::newRow("a sliver") << 0.1 << GrafcetChartView::kMinFitScale;
  }
  void labelsStayReadableInASmallDock() {
    QFETCH(double, fraction);
    QFETCH(double, scale);
    QScrollArea area;
    auto* view = new GrafcetChartView;
    view->setFitToWidget(true);
    view->setChart(smc2Chart());
    area.setWidget(view);
    area.setWidgetResizable(true);
    const QSizeF content = view->contentSize();
    QCOMPARE(view->minimumSize(), (content * GrafcetChartView::kMinFitScale).toSize());
    area.resize((content * fraction).toSize() + QSize(2 * area.frameWidth(), 2 * area.frameWidth()));
    area.show();
    QVERIFY(QTest::qWaitForWindowExposed(&area));
    QVERIFY2(std::abs(view->scale() - scale) < 0.01, qPrintable(QString::number(view->scale())));
    QVERIFY(view->smallestLabelPointSize() >= 9.0);
    QFont smallest = view->font();
    smallest.setPointSizeF(view->smallestLabelPointSize());
    QVERIFY(QFontInfo(smallest).pixelSize() >= 11);
    const bool scrolls = area.verticalScrollBar()->maximum() > 0 || area.horizontalScrollBar()->maximum() > 0;
    QCOMPARE(scrolls, fraction < GrafcetChartView::kMinFitScale);
  }

  void exportsAPng() {
    GrafcetChartView view;
    view.setChart(smc2Chart());
    view.setActiveSteps({4});
    view.setSelected(-1, 6);
    const QTemporaryDir dir;
    const QString path = dir.filePath("grafcet_smc2.png");
    QVERIFY(view.saveImage(path, 1400, 1000));
    QImage image(path);
    QCOMPARE(image.size(), QSize(1400, 1000));
    int ink = 0;
    for (int y = 0; y < image.height(); y += 2)
      for (int x = 0; x < image.width(); x += 2)
        if (qGray(image.pixel(x, y)) < 128) ++ink;
    QVERIFY(ink > 2000);
    QVERIFY(!view.saveImage(QString(), 100, 100));
  }
};

MX_REGISTER_TEST(TestGrafcetChartView)
#include "test_grafcet_chart_view.moc"
