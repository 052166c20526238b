// Test-cut files: the mean-forces CSV and a dynamometer record averaged over whole revolutions.
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/invalid_input.h"
#include "cutting_data/force_measurement_csv.h"
#include "test_registry.h"

using namespace mx;

namespace {
// F(t) = mean + amplitude sin(2 pi t / revolution) sampled every dt from 0 to `revolutions` revolutions.
std::string record(double revolution_s, double revolutions, double dt, double mean, double amplitude) {
  std::ostringstream os;
  os.precision(17);
  os << "time_s,Fx_N,Fy_N,Fz_N\n";
  const int n = static_cast<int>(std::round(revolutions * revolution_s / dt));
  for (int i = 0; i <= n; ++i) {
    const double t = i * dt, s = amplitude * std::sin(2.0 * std::numbers::pi * t / revolution_s);
    os << t << ',' << -mean + s << ',' << 2 * mean + s << ',' << 0.5 * mean << '\n';
  }
  return os.str();
}
}  // namespace

class TestForceMeasurementCsv : public QObject {
  Q_OBJECT
 private slots:
  void meanForces() {
    const std::string csv =
        "\xEF\xBB\xBF feed_mm_per_tooth , Fx_N,Fy_N ,Fz_N\r\n0.05,-120.5,310,40\r\n\r\n 0.1 , -180, 520.25 ,55\n";
    const std::vector<TestCut> cuts = readMeanForcesCsv(csv, "cuts.csv");
    QCOMPARE(cuts.size(), std::size_t(2));
    QCOMPARE(cuts[0].feed_per_tooth_m, 0.05e-3);
    QCOMPARE(cuts[0].fx_n, -120.5);
    QCOMPARE(cuts[1].fy_n, 520.25);
    QCOMPARE(cuts[1].fz_n, 55.0);
  }

  void badFilesNameTheLine_data() {
    QTest::addColumn<QString>("csv");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << ""
                           << "cuts.csv: line 0: the file is empty";
    QTest::newRow("header") << "feed,Fx,Fy,Fz\n0.1,1,2,3\n"
                            << "cuts.csv: line 1: header 'feed,Fx,Fy,Fz': expected feed_mm_per_tooth,Fx_N,Fy_N,Fz_N";
    QTest::newRow("no rows") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n"
                             << "cuts.csv: line 0: no cut";
    QTest::newRow("fields") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0.1,1,2\n"
                            << "line 2: 3 fields: expected 4";
    QTest::newRow("text") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0.1,1,two,3\n"
                          << "line 2: Fy_N = 'two': expected a finite number";
    QTest::newRow("nan") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0.1,nan,2,3\n"
                         << "line 2: Fx_N = 'nan'";
    QTest::newRow("feed 0") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0,1,2,3\n"
                            << "line 2: feed_mm_per_tooth = 0: must be in [1e-06, 10] mm";
    QTest::newRow("force") << "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0.1,1,2,3e9\n"
                           << "line 2: Fz_N = 3e9: must be within ±1e7 N";
  }
  void badFilesNameTheLine() {
    QFETCH(QString, csv);
    QFETCH(QString, message);
    try {
      readMeanForcesCsv(csv.toStdString(), "cuts.csv");
      QFAIL("accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(message), e.what());
    }
  }

  // 2.5 revolutions of a once-per-revolution ripple: whole revolutions give the mean exactly; the half
  // revolution left over would bias it by amplitude / (2.5 pi) = 25 N.
  void recordAveragedOverWholeRevolutions() {
    const double rpm = 1200.0, revolution = 60.0 / rpm;
    const ForceRecord r = readForceRecordCsv(record(revolution, 2.5, 1e-4, 100.0, 200.0), "cut1.csv");
    QCOMPARE(r.t_s.size(), std::size_t(1251));
    const TestCut m = meanOverRevolutions(r, rpm, 0.1e-3, "cut1.csv");
    QCOMPARE(m.feed_per_tooth_m, 0.1e-3);
    QVERIFY2(std::abs(m.fx_n + 100.0) < 1e-9, qPrintable(QString::number(m.fx_n)));
    QVERIFY(std::abs(m.fy_n - 200.0) < 1e-9);
    QVERIFY(std::abs(m.fz_n - 50.0) < 1e-9);
    // The end of the second revolution falls between samples: interpolated.
    const ForceRecord coarse = readForceRecordCsv(record(revolution, 2.5, 3e-3, 100.0, 200.0), "cut2.csv");
    QVERIFY(std::abs(meanOverRevolutions(coarse, rpm, 0.1e-3, "cut2.csv").fy_n - 200.0) < 1.0);
  }

  void recordErrors() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, readForceRecordCsv("time_s,Fx_N,Fy_N,Fz_N\n0,1,2,3\n", "r.csv"));
    try {
      readForceRecordCsv("time_s,Fx_N,Fy_N,Fz_N\n0,1,2,3\n0.1,1,2,3\n0.1,1,2,3\n", "r.csv");
      QFAIL("accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains("r.csv: line 4: time_s = 0.1: must be after the previous sample's"),
               e.what());
    }
    const ForceRecord short_record = readForceRecordCsv("time_s,Fx_N,Fy_N,Fz_N\n0,1,2,3\n0.01,1,2,3\n", "r.csv");
    try {
      meanOverRevolutions(short_record, 1000.0, 0.1e-3, "r.csv");
      QFAIL("accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains("less than one revolution (0.06 s at 1000 rpm)"), e.what());
    }
    QVERIFY_THROWS_EXCEPTION(InvalidInput, meanOverRevolutions(short_record, 0.0, 0.1e-3, "r.csv"));
  }
};

MX_REGISTER_TEST(TestForceMeasurementCsv)
#include "test_force_measurement_csv.moc"
