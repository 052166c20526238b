// SupervisionTimeline: streamed F_Y / power chunks add up, the power limit and F_ref lines
// span the data, module spans fill the A-L rows, events are counted and answer a tooltip; the PNG
// export of a synthetic SMC II run.
#include <QApplication>
#include <QImage>
#include <QTemporaryDir>
#include <cmath>

#include "display_units.h"
#include "supervision_timeline.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
constexpr double kLimit = 745.7, kReferenceForceN = 600.0;

// A synthetic SMC II-like run: contact at 1 s, chatter growing until detected at 3.2 s, a 200 ms hold,
// a re-planned pass under adaptive force control, a 1 s operator feed hold at 6 s.
SupervisionSeries series(double from, double to, double dt = 0.02) {
  SupervisionSeries s;
  s.power_limit_w = kLimit;
  s.force_reference_n = kReferenceForceN;
  for (double t = from; t < to - 1e-9; t += dt) {
    double f = 0;
    if (t >= 1.0 && t < 3.2)
      f = 900.0 + 60.0 * std::exp(1.2 * (t - 1.0)) * std::sin(40.0 * t);
    else if ((t >= 3.4 && t < 6.0) || (t >= 7.0 && t < 11.0))
      f = kReferenceForceN * (1.0 + 0.9 * std::exp(-(t - 3.4) / 0.3) * std::cos(9.0 * (t - 3.4))) +
          15.0 * std::sin(31.0 * t);
    s.t_s << t;
    s.force_y_n << std::max(0.0, f);
    s.power_w << std::max(0.0, f) * 1.15;
    s.feed_mm_s << (f > 0 ? 10.0 : 0.0);
  }
  return s;
}

QVector<ModuleSpan> spans() {
  return {{"A", 0, 12},    {"B", 0, 3.2}, {"B", 3.4, 12}, {"I", 0, 3.2},   {"I", 3.4, 6},
          {"I", 7, 12},    {"J", 0, 3.2}, {"J", 3.4, 6},  {"J", 7, 12},    {"D", 1, 3.2},
          {"E", 1, 3.2},   {"H", 1, 3.2}, {"K", 1, 3.2},  {"G", 3.2, 3.4}, {"F", 3.2, 3.21},
          {"C", 3.2, 3.4}, {"C", 6, 7},   {"D", 3.5, 6},  {"E", 3.5, 6},   {"H", 3.5, 6},
          {"K", 3.5, 6},   {"D", 7, 11},  {"E", 7, 11},   {"H", 7, 11},    {"K", 7, 11}};
}

QVector<SupervisionEventView> events() {
  return {{1.0, "contact", "F_Y > 50 N (J)"},      {3.2, "chatter_detected", "automatic detector (E)"},
          {3.21, "replan", "2 passes of 1.00 mm"}, {6.0, "feed_hold_on", "operator"},
          {7.0, "feed_hold_off", "operator"},      {11.0, "contact_lost", ""}};
}
}  // namespace

class TestSupervisionTimeline : public QObject {
  Q_OBJECT
 private slots:
  void streamingChunksAddUp() {
    SupervisionTimeline view;
    QCOMPARE(view.pointCount(), 0);
    const SupervisionSeries a = series(0, 4), b = series(4, 12);
    view.appendSeries(a);
    QCOMPARE(view.pointCount(), a.t_s.size());
    view.appendSeries(b);
    QCOMPARE(view.pointCount(), a.t_s.size() + b.t_s.size());
    QVERIFY(std::abs(view.timeRange().first - 0.0) < 1e-9);
    QVERIFY(view.timeRange().second >= b.t_s.back());
    view.setSeries(a);  // replaces
    QCOMPARE(view.pointCount(), a.t_s.size());
    view.clear();
    QCOMPARE(view.pointCount(), 0);
  }

  void spansFillTheModuleRows() {
    SupervisionTimeline view;
    view.setModuleSpans(spans());
    QCOMPARE(view.spanCount(), spans().size());
    QCOMPARE(view.moduleRows().size(), 12);
    QCOMPARE(view.moduleRows().front(), QStringLiteral("A  feedrate routine"));
    QCOMPARE(view.moduleRows().back(), QStringLiteral("L  model-based ctrl"));
    QVERIFY(std::abs(view.activeTimeOf("A") - 12.0) < 1e-9);
    QVERIFY(std::abs(view.activeTimeOf("C") - 1.2) < 1e-9);
    QCOMPARE(view.activeTimeOf("L"), 0.0);
    view.setModuleSpans({{"Z", 0, 1}});  // an unknown module gets a row of its own
    QCOMPARE(view.spanCount(), 1);
    QCOMPARE(view.moduleRows().size(), 13);
  }

  void eventsAreCountedAndExplained() {
    SupervisionTimeline view;
    view.appendEvents(events().mid(0, 2));
    view.appendEvents(events().mid(2));
    QCOMPARE(view.eventCount(), 6);
    QVERIFY(view.eventToolTipAt(3.2, 0.005).contains(QStringLiteral("chatter_detected: automatic detector (E)")));
    QVERIFY(view.eventToolTipAt(3.2, 0.005).contains(QStringLiteral("t = 3.200 s")));
    QVERIFY(view.eventToolTipAt(5.0, 0.05).isEmpty());
    view.clear();
    QCOMPARE(view.eventCount(), 0);
    QCOMPARE(view.spanCount(), 0);
  }

  void exportsAPng() {
    SupervisionTimeline view;
    view.appendSeries(series(0, 6));
    view.appendSeries(series(6, 12));
    view.setModuleSpans(spans());
    view.appendEvents(events());
    const QTemporaryDir dir;
    const QString path = dir.filePath("supervision_timeline.png");
    QVERIFY(view.saveImage(path, 1400, 900));
    QCOMPARE(QImage(path).size(), QSize(1400, 900));
  }

  // Shop units: the force and power axes relabel and their data scale in place, both ways.
  void followsShopUnits() {
    DisplayUnits units;
    SupervisionTimeline view;
    view.setUnits(&units);
    view.setSeries(series(0.0, 12.0));
    QCOMPARE(view.valueAxisLabel(false), QString("Force F_Y [N]"));
    QCOMPARE(view.valueAxisLabel(true), QString("Spindle power P [W]"));
    const double force_top = view.valueAxisUpper(false), power_top = view.valueAxisUpper(true);
    units.setShop(ShopUnits::inch());
    QCOMPARE(view.valueAxisLabel(false), QString("Force F_Y [lbf]"));
    QCOMPARE(view.valueAxisLabel(true), QString("Spindle power P [hp]"));
    QCOMPARE(view.valueAxisUpper(false), force_top / 4.4482216152605);
    QCOMPARE(view.valueAxisUpper(true), power_top / 745.699872);
    view.appendSeries(series(12.0, 13.0));  // a streamed chunk in N and W joins in lbf and hp
    units.setShop(ShopUnits::metric());
    QCOMPARE(view.valueAxisUpper(false), force_top);
    QCOMPARE(view.valueAxisUpper(true), power_top);
  }
};

MX_REGISTER_TEST(TestSupervisionTimeline)
#include "test_supervision_timeline.moc"
