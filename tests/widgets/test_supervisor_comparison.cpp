// SupervisorComparison: three columns none | SMC I | SMC II, each with its F_Y/power plot
// and its metric texts; the PNG export of the paper-like outcome.
#include <QApplication>
#include <QImage>
#include <QTableWidget>
#include <QTemporaryDir>
#include <cmath>

#include "supervisor_comparison.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
constexpr double kPowerLimit = 745.7;

SupervisionSeries run(double level_n, double chatter_from_s, double hold_s, double end_s) {
  SupervisionSeries s;
  s.power_limit_w = kPowerLimit;
  s.force_reference_n = 600;
  for (double t = 0; t < end_s; t += 0.02) {
    double f = t < 0.5 ? 0.0 : level_n * (1.0 + 0.3 * std::exp(-(t - 0.5) / 0.2) * std::cos(12 * (t - 0.5)));
    if (chatter_from_s >= 0 && t > chatter_from_s && t < hold_s)
      f += 80.0 * std::exp(t - chatter_from_s) * std::sin(45 * t);
    if (t >= hold_s && t < hold_s + 0.2) f = 0;
    s.t_s << t;
    s.force_y_n << std::max(0.0, f);
    s.power_w << std::max(0.0, f) * 1.2;
    s.feed_mm_s << 10;
  }
  return s;
}

SupervisionMetricsView metrics(const QString& c, double power, double overshoot, std::optional<double> chatter,
                               int passes, double cycle) {
  SupervisionMetricsView m;
  m.controller = c;
  m.max_power_pct_of_limit = power;
  m.overshoot_pct = overshoot;
  m.chatter_detected = chatter.has_value() || c == QLatin1String("none");
  m.chatter_time_s = chatter;
  m.passes = passes;
  m.cycle_time_s = cycle;
  return m;
}
}  // namespace

class TestSupervisorComparison : public QObject {
  Q_OBJECT
 private slots:
  void threeColumnsWithMetricTexts() {
    SupervisorComparison view;
    QCOMPARE(view.resultCount(), 0);
    QCOMPARE(view.metricsTable()->columnCount(), 3);
    QCOMPARE(view.metricsTable()->horizontalHeaderItem(1)->text(), QStringLiteral("SMC I (transfer line)"));
    view.setResult("smc2", run(600, 1.5, 2.5, 8), metrics("smc2", 98.4, 113.2, 2.5, 2, 11.73));
    view.setResult("none", run(1390, 0.6, 99, 6), metrics("none", 224.0, 0, std::nullopt, 1, 5.9));
    view.setResult("smc1", run(620, -1, 99, 10), metrics("smc1", 99.6, 28.4, std::nullopt, 2, 10.2));
    QCOMPARE(view.resultCount(), 3);
    QCOMPARE(view.metricText("none", "max_power_pct_of_limit"), QStringLiteral("224"));
    QCOMPARE(view.metricText("smc1", "overshoot_pct"), QStringLiteral("28"));
    QCOMPARE(view.metricText("smc2", "overshoot_pct"), QStringLiteral("113"));
    QCOMPARE(view.metricText("smc1", "chatter_detected"), QStringLiteral("no"));
    QCOMPARE(view.metricText("smc2", "chatter_detected"), QStringLiteral("yes"));
    QCOMPARE(view.metricText("smc2", "chatter_time_s"), QStringLiteral("2.50"));
    QCOMPARE(view.metricText("smc1", "chatter_time_s"), QStringLiteral("\u2013"));
    QCOMPARE(view.metricText("smc2", "passes"), QStringLiteral("2"));
    QCOMPARE(view.metricText("smc2", "cycle_time_s"), QStringLiteral("11.73"));
    QCOMPARE(view.metricText("smc2", "unknown"), QString());
    QCOMPARE(view.metricText("other", "passes"), QString());
    // Table cells: controllers in the fixed order, whatever the arrival order.
    QCOMPARE(view.metricsTable()->item(0, 0)->text(), QStringLiteral("224"));
    QCOMPARE(view.metricsTable()->item(1, 2)->text(), QStringLiteral("113"));
    QCOMPARE(view.metricsTable()->item(0, 0)->foreground().color(), QColor(190, 20, 20));  // over the limit
    QVERIFY(view.plotPointCount("smc1") > 400);
    // Same controller again: replaced, not added.
    view.setResult("smc1", run(620, -1, 99, 10), metrics("smc1", 97.0, 20.0, std::nullopt, 2, 10.2));
    QCOMPARE(view.resultCount(), 3);
    QCOMPARE(view.metricText("smc1", "max_power_pct_of_limit"), QStringLiteral("97"));
    view.clear();
    QCOMPARE(view.resultCount(), 0);
    QCOMPARE(view.plotPointCount("smc1"), -1);
    QCOMPARE(view.metricsTable()->item(0, 1)->text(), QStringLiteral("\u2013"));
  }

  // The force controller's settling: the longest over its restarts; restarts that never settled are
  // counted and shown in red; without a restart (no force controller) a dash.
  void settlingRow_data() {
    QTest::addColumn<QVector<double>>("settlings");  // -1: never settled
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("red");
    QTest::newRow("no restart") << QVector<double>{} << QStringLiteral("\u2013") << false;
    QTest::newRow("two settled") << QVector<double>{0.39, 0.2} << QStringLiteral("0.39") << false;
    QTest::newRow("one never") << QVector<double>{0.39, -1.0} << QStringLiteral("0.39 (1 never)") << true;
    QTest::newRow("all never") << QVector<double>{-1.0, -1.0} << QStringLiteral("never") << true;
  }
  void settlingRow() {
    QFETCH(QVector<double>, settlings);
    QFETCH(QString, text);
    QFETCH(bool, red);
    SupervisionMetricsView m = metrics("smc1", 94.7, 10.5, std::nullopt, 2, 37.1);
    for (double s : settlings) {
      if (s < 0.0) {
        ++m.unsettled;
      } else {
        m.longest_settling_s = std::max(m.longest_settling_s.value_or(0.0), s);
      }
    }
    SupervisorComparison view;
    view.setResult("smc1", run(620, -1, 99, 10), m);
    QCOMPARE(view.metricText("smc1", "settling_s"), text);
    const int row = static_cast<int>(SupervisorComparison::metricKeys().indexOf("settling_s"));
    QCOMPARE(view.metricsTable()->verticalHeaderItem(row)->text(), QStringLiteral("Force settling after contact [s]"));
    QCOMPARE(view.metricsTable()->item(row, 1)->text(), text);
    QCOMPARE(view.metricsTable()->item(row, 1)->foreground().color() == QColor(190, 20, 20), red);
  }

  void exportsAPng() {
    SupervisorComparison view;
    view.setResult("none", run(1390, 0.6, 99, 6), metrics("none", 224.0, 0, std::nullopt, 1, 5.9));
    view.setResult("smc1", run(620, -1, 99, 10), metrics("smc1", 99.6, 28.4, std::nullopt, 2, 10.2));
    view.setResult("smc2", run(600, 1.5, 2.5, 8), metrics("smc2", 98.4, 113.2, 2.5, 2, 11.73));
    const QTemporaryDir dir;
    const QString path = dir.filePath("supervisor_comparison.png");
    QVERIFY(view.saveImage(path, 1500, 800));
    QCOMPARE(QImage(path).size(), QSize(1500, 800));
  }
};

MX_REGISTER_TEST(TestSupervisorComparison)
#include "test_supervisor_comparison.moc"
