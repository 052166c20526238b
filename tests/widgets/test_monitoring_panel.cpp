// The Rule 17 monitoring panel: values in the C locale with 4 significant digits, "–" for missing and
// non-finite values, the power limit and its alarm, the Rule 15 chip-ratio alarm and verdict, and the
// peak table.
#include <QApplication>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <cmath>
#include <limits>

#include "display_units.h"
#include "indicator_gauge.h"
#include "monitoring_panel.h"
#include "support/optional_double_metatype.h"
#include "support/shown_texts.h"
#include "support/test_constants.h"
#include "test_registry.h"

using mx::widgets::IndicatorGauge;
using mx::widgets::MonitoringPanel;
using mx::widgets::MonitoringPeak;
using mx::widgets::MonitoringValues;

namespace {
using mx::test::kDash;
using mx::test::kInf;
using mx::test::kNaN;
const QStringList kKeys = {
    "peak_force_n", "peak_power_w", "feed_velocity_mm_s", "mrr_cm3_s",           "tol_min", "surf_um", "ros",
    "eta",          "chip_ratio",   "tooth_passing_hz",   "chatter_frequency_hz"};

bool isRed(const QLabel* label) {
  return label->styleSheet().contains(IndicatorGauge::alarmColor().name());
}
}  // namespace

class TestMonitoringPanel : public QObject {
  Q_OBJECT
 private slots:
  void formatNumber_data() {
    QTest::addColumn<OptD>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("missing") << OptD() << kDash;
    QTest::newRow("NaN") << OptD(kNaN) << kDash;
    QTest::newRow("+inf") << OptD(kInf) << kDash;
    QTest::newRow("-inf") << OptD(-kInf) << kDash;
    QTest::newRow("zero") << OptD(0.0) << QString("0");
    QTest::newRow("integer part only") << OptD(12345.4) << QString("12345");
    QTest::newRow("4 digits") << OptD(1234.56) << QString("1235");
    QTest::newRow("decimals") << OptD(1.25) << QString("1.250");
    QTest::newRow("rounds up a digit") << OptD(9999.6) << QString("10000");
    QTest::newRow("rounds to 1") << OptD(0.99996) << QString("1.000");
    QTest::newRow("small") << OptD(0.012346) << QString("0.01235");  // C locale: point, no group separator
    QTest::newRow("negative") << OptD(-0.4321) << QString("-0.4321");
    QTest::newRow("tiny: exponent") << OptD(1.5e-5) << QString("1.5e-05");
    QTest::newRow("huge: exponent") << OptD(2.5e12) << QString("2.5e+12");
  }
  void formatNumber() {
    QFETCH(OptD, value);
    QFETCH(QString, text);
    QCOMPARE(MonitoringPanel::formatNumber(value), text);
  }

  void startsEmpty() {
    MonitoringPanel panel;
    for (const QString& key : kKeys) QCOMPARE(panel.valueText(key), kDash);
    QCOMPARE(panel.valueText("verdict"), kDash);
    QCOMPARE(panel.valueText("no_such_key"), QString());
    QCOMPARE(panel.peakTable()->rowCount(), 0);
  }

  void values() {
    MonitoringPanel panel;
    MonitoringValues v;
    v.peak_force_n = 812.345;
    v.peak_power_w = 1520.0;
    v.power_limit_w = 15000.0;
    v.feed_velocity_mm_s = 23.2;
    v.mrr_cm3_s = 2.0412;
    v.tol_min = 38.71;
    v.surf_um = 0.8123;
    v.ros = 0.3456;
    v.eta = 1.0;
    v.chip_ratio = 1.012;
    v.tooth_passing_hz = 193.333;
    v.chatter_frequency_hz = std::nullopt;
    panel.setValues(v);
    QCOMPARE(panel.valueText("peak_force_n"), QString("812.3"));
    QCOMPARE(panel.valueText("peak_power_w"), QString("1520 of 15000 W"));
    QCOMPARE(panel.valueText("feed_velocity_mm_s"), QString("1392"));  // 23.2 mm/s in mm/min
    QCOMPARE(panel.valueText("mrr_cm3_s"), QString("122.5"));          // 2.0412 cm³/s in cm³/min
    QCOMPARE(panel.valueText("tol_min"), QString("38.71"));
    QCOMPARE(panel.valueText("surf_um"), QString("0.8123"));
    QCOMPARE(panel.valueText("ros"), QString("0.3456"));
    QCOMPARE(panel.valueText("eta"), QString("1.000"));
    QCOMPARE(panel.valueText("chip_ratio"), QString("1.012"));
    QCOMPARE(panel.valueText("tooth_passing_hz"), QString("193.3"));
    QCOMPARE(panel.valueText("chatter_frequency_hz"), kDash);
    QCOMPARE(panel.valueText("verdict"), QString("Stable"));
    QVERIFY(panel.valueLabel("verdict")->styleSheet().contains(IndicatorGauge::okColor().name()));
    QVERIFY(!isRed(panel.valueLabel("peak_power_w")));
    QVERIFY(!isRed(panel.valueLabel("chip_ratio")));
    QCOMPARE(panel.valueLabel("peak_force_n")->objectName(), QString("monitoring_peak_force_n"));
  }

  void missingAndNonFinite_data() {
    QTest::addColumn<OptD>("value");
    QTest::newRow("missing") << OptD();
    QTest::newRow("NaN") << OptD(kNaN);
    QTest::newRow("inf") << OptD(kInf);
    QTest::newRow("-inf") << OptD(-kInf);
  }
  void missingAndNonFinite() {
    QFETCH(OptD, value);
    MonitoringPanel panel;
    MonitoringValues v;
    v.peak_force_n = v.peak_power_w = v.feed_velocity_mm_s = v.mrr_cm3_s = v.tol_min = v.surf_um = v.ros = v.eta =
        v.chip_ratio = v.tooth_passing_hz = v.chatter_frequency_hz = value;
    v.power_limit_w = value;
    panel.setValues(v);
    for (const QString& key : kKeys) {
      const QString text = panel.valueText(key);
      QCOMPARE(text, kDash);
      QVERIFY(!text.contains("nan", Qt::CaseInsensitive) && !text.contains("inf", Qt::CaseInsensitive));
    }
    QCOMPARE(panel.valueText("verdict"), kDash);  // no chatter indicator: no verdict
    QVERIFY(!isRed(panel.valueLabel("peak_power_w")));
  }

  void verdictNeedsAnIndicator_data() {
    QTest::addColumn<OptD>("eta");
    QTest::addColumn<OptD>("chipRatio");
    QTest::addColumn<bool>("chatter");
    QTest::addColumn<QString>("verdict");
    QTest::newRow("no simulation") << OptD() << OptD() << false << kDash;
    QTest::newRow("NaN indicators") << OptD(kNaN) << OptD(kNaN) << false << kDash;
    QTest::newRow("eta only") << OptD(1.0) << OptD() << false << QString("Stable");
    QTest::newRow("chip ratio only") << OptD() << OptD(1.01) << false << QString("Stable");
    QTest::newRow("chatter flag alone") << OptD() << OptD() << true << QString("Chatter (Rule 15)");
  }
  void verdictNeedsAnIndicator() {
    QFETCH(OptD, eta);
    QFETCH(OptD, chipRatio);
    QFETCH(bool, chatter);
    QFETCH(QString, verdict);
    MonitoringPanel panel;
    MonitoringValues v;
    v.eta = eta;
    v.chip_ratio = chipRatio;
    v.chatter = chatter;
    panel.setValues(v);
    QCOMPARE(panel.valueText("verdict"), verdict);
  }

  void powerLimit_data() {
    QTest::addColumn<OptD>("power");
    QTest::addColumn<OptD>("limit");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("red");
    QTest::newRow("below") << OptD(1500.0) << OptD(2000.0) << QString("1500 of 2000 W") << false;
    QTest::newRow("at the limit") << OptD(2000.0) << OptD(2000.0) << QString("2000 of 2000 W") << false;
    QTest::newRow("above") << OptD(2001.0) << OptD(2000.0) << QString("2001 of 2000 W") << true;
    QTest::newRow("no limit") << OptD(2500.0) << OptD() << QString("2500") << false;
    QTest::newRow("zero limit = none") << OptD(2500.0) << OptD(0.0) << QString("2500") << false;
    QTest::newRow("infinite limit = none") << OptD(2500.0) << OptD(kInf) << QString("2500") << false;
    QTest::newRow("power missing") << OptD() << OptD(2000.0) << QString("\u2013 of 2000 W") << false;
  }
  void powerLimit() {
    QFETCH(OptD, power);
    QFETCH(OptD, limit);
    QFETCH(QString, text);
    QFETCH(bool, red);
    MonitoringPanel panel;
    MonitoringValues v;
    v.peak_power_w = power;
    v.power_limit_w = limit;
    panel.setValues(v);
    QCOMPARE(panel.valueText("peak_power_w"), text);
    QCOMPARE(isRed(panel.valueLabel("peak_power_w")), red);
  }

  void chatterVerdict_data() {
    QTest::addColumn<double>("chipRatio");
    QTest::addColumn<bool>("chatter");
    QTest::addColumn<bool>("chipRed");
    QTest::newRow("stable") << 1.01 << false << false;
    QTest::newRow("just below 1.25") << 1.2499 << false << false;
    QTest::newRow("at 1.25") << 1.25 << true << true;
    QTest::newRow("well above") << 1.45 << true << true;
  }
  void chatterVerdict() {
    QFETCH(double, chipRatio);
    QFETCH(bool, chatter);
    QFETCH(bool, chipRed);
    MonitoringPanel panel;
    MonitoringValues v;
    v.chip_ratio = chipRatio;
    v.chatter = chatter;
    v.chatter_frequency_hz = chatter ? OptD(668.04) : OptD();
    panel.setValues(v);
    QCOMPARE(isRed(panel.valueLabel("chip_ratio")), chipRed);
    QCOMPARE(panel.valueText("verdict"), chatter ? QString("Chatter (Rule 15)") : QString("Stable"));
    const QColor want = chatter ? IndicatorGauge::alarmColor() : IndicatorGauge::okColor();
    QVERIFY(panel.valueLabel("verdict")->styleSheet().contains(want.name()));
    QCOMPARE(panel.valueText("chatter_frequency_hz"), chatter ? QString("668.0") : kDash);
  }

  void peaks() {
    MonitoringPanel panel;
    QTableWidget* t = panel.peakTable();
    QCOMPARE(t->columnCount(), 4);
    const QStringList headers = {"Frequency [Hz]", "Amplitude [N]", "Kind", "Harmonic [\u2013]"};
    for (int c = 0; c < 4; ++c) QCOMPARE(t->horizontalHeaderItem(c)->text(), headers[c]);
    panel.setPeaks({{668.04, 152.31, "non-harmonic (chatter)", 0},
                    {193.333, 80.0, "tooth passing (forced)", 1},
                    {386.667, 12.346, "tooth passing (forced)", 2},
                    {96.6667, 0.5, "spindle (run-out)", 1}});
    QCOMPARE(t->rowCount(), 4);
    QCOMPARE(t->item(0, 0)->text(), QString("668.0"));
    QCOMPARE(t->item(0, 1)->text(), QString("152.3"));
    QCOMPARE(t->item(0, 2)->text(), QString("non-harmonic (chatter)"));
    QCOMPARE(t->item(0, 3)->text(), kDash);
    QCOMPARE(t->item(2, 0)->text(), QString("386.7"));
    QCOMPARE(t->item(2, 1)->text(), QString("12.35"));
    QCOMPARE(t->item(2, 3)->text(), QString("2"));
    QCOMPARE(t->item(3, 0)->text(), QString("96.67"));
    QCOMPARE(t->item(3, 2)->text(), QString("spindle (run-out)"));
    QVERIFY(!(t->item(1, 1)->flags() & Qt::ItemIsEditable));
    panel.setPeaks({{100.0, 1.0, "spindle (run-out)", 3}});
    QCOMPARE(t->rowCount(), 1);
    QCOMPARE(t->item(0, 3)->text(), QString("3"));
    panel.setPeaks({});
    QCOMPARE(t->rowCount(), 0);
  }

  void clearResets() {
    MonitoringPanel panel;
    MonitoringValues v;
    v.peak_power_w = 3000.0;
    v.power_limit_w = 2000.0;
    v.chip_ratio = 1.5;
    v.chatter = true;
    panel.setValues(v);
    panel.setPeaks({{668.0, 1.0, "non-harmonic (chatter)", 0}});
    QVERIFY(isRed(panel.valueLabel("peak_power_w")));
    panel.clear();
    for (const QString& key : kKeys) QCOMPARE(panel.valueText(key), kDash);
    QCOMPARE(panel.valueText("verdict"), kDash);
    QVERIFY(!isRed(panel.valueLabel("peak_power_w")));
    QVERIFY(!isRed(panel.valueLabel("chip_ratio")));
    QCOMPARE(panel.peakTable()->rowCount(), 0);
  }

  void labelsCarryUnitsAndTooltips() {
    MonitoringPanel panel;
    QVERIFY(!panel.peakTable()->toolTip().isEmpty());
    QVERIFY(!panel.valueLabel("verdict")->toolTip().isEmpty());
    for (const QString& key : kKeys) QVERIFY2(!panel.valueLabel(key)->toolTip().isEmpty(), qPrintable(key));
    QStringList names;
    for (const QLabel* l : panel.findChildren<QLabel*>())
      if (l->text().endsWith(':')) names << l->text();
    QCOMPARE(names.size(), kKeys.size());
    for (const QString& n : names) QVERIFY2(n.contains('[') && n.contains(']'), qPrintable(n));
  }

  // Shop units: force, power, feed rate and MRR convert, and the peak table names the force unit.
  void followsShopUnits() {
    mx::widgets::DisplayUnits units;
    MonitoringPanel panel;
    panel.setUnits(&units);
    MonitoringValues v;
    v.peak_force_n = 812.3;
    v.peak_power_w = 2745.3;
    v.power_limit_w = 7456.99872;
    v.feed_velocity_mm_s = 25.4;  // 1524 mm/min
    v.mrr_cm3_s = 3.0;            // 180 cm³/min
    panel.setValues(v);
    panel.setPeaks({{668.0, 44.482216152605, "chatter", 0}});
    units.setShop(mx::widgets::ShopUnits::inch());
    QCOMPARE(panel.valueText("peak_force_n"), QString("182.6"));
    QCOMPARE(panel.valueText("peak_power_w"), QString("3.682 of 10.00 hp"));
    QCOMPARE(panel.valueText("feed_velocity_mm_s"), QString("60.00"));
    QCOMPARE(panel.valueText("mrr_cm3_s"), QString("10.98"));
    QCOMPARE(panel.peakTable()->horizontalHeaderItem(1)->text(), QString("Amplitude [lbf]"));
    QCOMPARE(panel.peakTable()->item(0, 1)->text(), QString("10.00"));
    auto* label = qobject_cast<QLabel*>(panel.findChild<QFormLayout*>()->labelForField(panel.valueLabel("mrr_cm3_s")));
    QVERIFY(label);
    QCOMPARE(label->text(), QString::fromUtf8("MRR [in³/min]:"));
  }
};

MX_REGISTER_TEST(TestMonitoringPanel)
#include "test_monitoring_panel.moc"
