// Heidenhain AFC settings from a prediction: AFC-LOAD is the mean power, FMAX the tighter of the
// chip-load and spindle-power limits (rounded down, within [100, 999] %), refusals name the field, and
// the table text has the control's columns.
#include <cmath>

#include "core/invalid_input.h"
#include "machining/afc_table.h"
#include "test_registry.h"

using namespace mx;

namespace {
AfcPrediction prediction(double peak_W, double available_W, double fz_mm, double fz_max_mm) {
  AfcPrediction p;
  p.mean_power_W = 0.6 * peak_W;
  p.peak_power_W = peak_W;
  p.available_power_W = available_W;
  p.feed_per_tooth_m = fz_mm * 1e-3;
  p.max_feed_per_tooth_m = fz_max_mm * 1e-3;
  return p;
}
}  // namespace

class TestAfcTable : public QObject {
  Q_OBJECT
 private slots:
  void fmax_data() {
    QTest::addColumn<double>("peak_W");
    QTest::addColumn<double>("available_W");
    QTest::addColumn<double>("fz_mm");
    QTest::addColumn<double>("fz_max_mm");
    QTest::addColumn<double>("fmax");
    QTest::addColumn<QString>("limited_by");
    QTest::newRow("chip load") << 1000.0 << 5000.0 << 0.1 << 0.25 << 250.0 << "chip load";
    QTest::newRow("spindle power") << 4000.0 << 5000.0 << 0.1 << 0.25 << 125.0 << "spindle power";
    QTest::newRow("no limits") << 1000.0 << 0.0 << 0.1 << 0.0 << 100.0 << "none";
    QTest::newRow("capped at 999 %") << 1.0 << 0.0 << 0.01 << 1.0 << 999.0 << "chip load";
    QTest::newRow("point past the limit") << 6000.0 << 5000.0 << 0.1 << 0.25 << 100.0
                                          << "spindle power (the point is already past it: AFC may not raise the feed)";
  }
  void fmax() {
    QFETCH(double, peak_W);
    QFETCH(double, available_W);
    QFETCH(double, fz_mm);
    QFETCH(double, fz_max_mm);
    QFETCH(double, fmax);
    QFETCH(QString, limited_by);
    const AfcTeachIn t = afcFromPrediction(prediction(peak_W, available_W, fz_mm, fz_max_mm), "MX_T1", 'S');
    QCOMPARE(t.setting.fmax_percent, fmax);
    QCOMPARE(QString::fromStdString(t.fmax_limited_by), limited_by);
    QCOMPARE(t.afc_load_W, 0.6 * peak_W);
    QCOMPARE(t.setting.ovld, 'S');
    QCOMPARE(t.setting.fmin_percent, 50.0);
    QCOMPARE(t.setting.pout_percent, 8.0);
    QCOMPARE(t.setting.sens_percent, 100.0);
  }
  void refused_data() {
    QTest::addColumn<double>("mean_W");
    QTest::addColumn<double>("fz_mm");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("ovld");
    QTest::addColumn<QString>("message");
    QTest::newRow("no cut") << 0.0 << 0.1 << "MX_T1"
                            << "E"
                            << "AFC: predicted mean spindle power = 0.0 W: must be > 0 (a cut at the chosen point)";
    QTest::newRow("NaN power") << std::nan("") << 0.1 << "MX_T1"
                               << "E"
                               << "AFC: predicted mean spindle power = nan W: must be > 0 (a cut at the chosen point)";
    QTest::newRow("no feed") << 100.0 << 0.0 << "MX_T1"
                             << "E"
                             << "AFC: feed per tooth = 0.0000 mm: must be > 0";
    QTest::newRow("OVLD") << 100.0 << 0.1 << "MX_T1"
                          << "X"
                          << "AFC: OVLD = 'X': must be one of M, S, F, E, L, -";
    QTest::newRow("long name") << 100.0 << 0.1 << "MX_ABCDEFGHI"
                               << "E"
                               << "AFC: name = 'MX_ABCDEFGHI': must have 1 to 10 characters";
  }
  void refused() {
    QFETCH(double, mean_W);
    QFETCH(double, fz_mm);
    QFETCH(QString, name);
    QFETCH(QString, ovld);
    QFETCH(QString, message);
    AfcPrediction p;
    p.mean_power_W = mean_W;
    p.feed_per_tooth_m = fz_mm * 1e-3;
    QString error;
    try {
      afcFromPrediction(p, name.toStdString(), ovld.toLatin1().at(0));
    } catch (const InvalidInput& e) {
      error = e.what();
    }
    QCOMPARE(error, message);
  }
  void tableText() {
    AfcSetting s;
    s.name = "MX_T1";
    s.fmax_percent = 130;
    QCOMPARE(QString::fromStdString(afcTableText(s)),
             QString("BEGIN AFC .TAB MM\n"
                     "NR   AFC        FMIN  FMAX  FIDL  FENT  OVLD POUT  SENS  PLC\n"
                     "0    MX_T1      50    130   100   100   E    8     100   0\n"
                     "[END]\n"));
    AfcTeachIn t;
    t.setting = s;
    t.afc_load_W = 2345.6;
    QVERIFY(afcToolTableText(3, "D10 rougher", t).find("3     D10 rougher      MX_T1      2.346\n") !=
            std::string::npos);
  }
};

MX_REGISTER_TEST(TestAfcTable)
#include "test_afc_table.moc"
