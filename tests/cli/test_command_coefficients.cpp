// millexpert-cli coefficients: test cuts written from the model's own mean forces come back as the
// material fields (K_tc, K_rc/K_tc and the edge coefficients, in N/mm^2 and N/mm) with R^2 = 1; records of
// whole and partial revolutions, CSV or universal file, with --speed once and --feed per record; bad files
// and flags exit 2.
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

#include "cutting_data/coefficient_fit.h"
#include "support/cli_runner.h"
#include "support/force_record_uff_samples.h"
#include "test_registry.h"

namespace {
const mx::TestCutSetup kSetup{3, 12e-3, 1.5e-3, 0.5, mx::MillingDirection::Down};
const mx::CuttingCoefficients kTrue{1800e6, 720e6, 500e6, 40e3, 35e3, 10e3};  // a steel

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
  QFile f(dir.filePath(name));
  if (!f.open(QIODevice::WriteOnly)) return {};
  f.write(text);
  return f.fileName();
}

QByteArray meanForces(std::initializer_list<double> feeds_mm) {
  QByteArray csv = "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n";
  for (double f : feeds_mm) {
    const mx::TestCut c = mx::meanCutForces(kSetup, kTrue, f * 1e-3);
    csv += QByteArray::number(f, 'g', 17) + ',' + QByteArray::number(c.fx_n, 'g', 17) + ',' +
           QByteArray::number(c.fy_n, 'g', 17) + ',' + QByteArray::number(c.fz_n, 'g', 17) + '\n';
  }
  return csv;
}

// One cut at 1500 rpm: the mean forces plus a tooth-passing ripple, sampled at 10 kHz over 3.3 revolutions.
mx::ForceRecord cut(double feed_mm) {
  const mx::TestCut c = mx::meanCutForces(kSetup, kTrue, feed_mm * 1e-3);
  mx::ForceRecord r;
  for (int i = 0; i <= 1320; ++i) {
    const double t = i * 1e-4, ripple = 50.0 * std::sin(2.0 * std::numbers::pi * 75.0 * t);
    r.t_s.push_back(t);
    r.fx_n.push_back(c.fx_n + ripple);
    r.fy_n.push_back(c.fy_n - ripple);
    r.fz_n.push_back(c.fz_n + ripple);
  }
  return r;
}

QByteArray record(double feed_mm) {
  return QByteArray::fromStdString(mx::test::forceRecordCsv(cut(feed_mm)));
}

QByteArray uffRecord(double feed_mm, const mx::test::ForceUffLayout& layout = {}) {
  return QByteArray::fromStdString(mx::test::forceRecordUff(cut(feed_mm), layout));
}

const QStringList kGeometry{"--diameter", "12", "--teeth", "3", "--depth", "1.5", "--immersion", "0.5"};
}  // namespace

class TestCliCoefficients : public QObject {
  Q_OBJECT
 private slots:
  void meanForcesGiveTheMaterialFields() {
    QTemporaryDir dir;
    const QString file = write(dir, "cuts.csv", meanForces({0.04, 0.08, 0.12, 0.16}));
    const mx::test::CliRun r = mx::test::runCli(QStringList{"coefficients", file} + kGeometry);
    QCOMPARE(r.code, 0);
    for (const char* key : {"Kt_N_mm2", "Kr", "Ka_N_mm2", "Kte_N_mm", "Kre_N_mm", "Kae_N_mm", "r2", "residuals_N"})
      QVERIFY2(r.json.contains(key), key);
    QVERIFY(std::abs(r.json["Kt_N_mm2"].toDouble() / 1800.0 - 1.0) < 1e-9);
    QVERIFY(std::abs(r.json["Kr"].toDouble() / 0.4 - 1.0) < 1e-9);
    QVERIFY(std::abs(r.json["Ka_N_mm2"].toDouble() / 500.0 - 1.0) < 1e-9);
    QVERIFY(std::abs(r.json["Kte_N_mm"].toDouble() / 40.0 - 1.0) < 1e-9);
    QVERIFY(std::abs(r.json["Kre_N_mm"].toDouble() / 35.0 - 1.0) < 1e-9);
    QVERIFY(std::abs(r.json["Kae_N_mm"].toDouble() / 10.0 - 1.0) < 1e-9);
    QVERIFY(r.json["r2"].toObject()["x"].toDouble() > 1.0 - 1e-12);
    QCOMPARE(r.json["residuals_N"].toArray().size(), 4);
    QCOMPARE(r.json["cuts"].toInt(), 4);
  }
  void recordsAveragedOverWholeRevolutions() {
    QTemporaryDir dir;
    const QString a = write(dir, "a.csv", record(0.05)), b = write(dir, "b.csv", record(0.1)),
                  c = write(dir, "c.csv", record(0.15));
    const mx::test::CliRun r = mx::test::runCli(
        QStringList{"coefficients", a, b, c, "--speed", "1500", "--feed", "0.05", "--feed", "0.1", "--feed", "0.15"} +
        kGeometry);
    QCOMPARE(r.code, 0);
    QVERIFY2(std::abs(r.json["Kt_N_mm2"].toDouble() / 1800.0 - 1.0) < 1e-6, qPrintable(r.err));
    QVERIFY(std::abs(r.json["Kte_N_mm"].toDouble() / 40.0 - 1.0) < 1e-6);
  }
  // Universal files among the records, told by their content: the same coefficients as the CSVs give.
  void uffRecords() {
    QTemporaryDir dir;
    mx::test::ForceUffLayout binary;
    binary.binary = true;
    const QString a = write(dir, "a.unv", uffRecord(0.05)), b = write(dir, "b.csv", record(0.1)),
                  c = write(dir, "c.txt", uffRecord(0.15, binary));
    const mx::test::CliRun r = mx::test::runCli(
        QStringList{"coefficients", a, b, c, "--speed", "1500", "--feed", "0.05", "--feed", "0.1", "--feed", "0.15"} +
        kGeometry);
    QCOMPARE(r.code, 0);
    for (const char* key : {"Kt_N_mm2", "Kr", "Ka_N_mm2", "Kte_N_mm", "Kre_N_mm", "Kae_N_mm", "r2", "residuals_N"})
      QVERIFY2(r.json.contains(key), key);
    QVERIFY2(std::abs(r.json["Kt_N_mm2"].toDouble() / 1800.0 - 1.0) < 1e-6, qPrintable(r.err));
    QVERIFY(std::abs(r.json["Kr"].toDouble() / 0.4 - 1.0) < 1e-6);
    QVERIFY(std::abs(r.json["Ka_N_mm2"].toDouble() / 500.0 - 1.0) < 1e-6);
    QVERIFY(std::abs(r.json["Kte_N_mm"].toDouble() / 40.0 - 1.0) < 1e-6);
    QVERIFY(std::abs(r.json["Kae_N_mm"].toDouble() / 10.0 - 1.0) < 1e-6);
    QCOMPARE(r.json["cuts"].toInt(), 3);
  }
  void badUffRecords_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    const QStringList speed_feed{"--speed", "1500", "--feed", "0.1"};
    mx::test::ForceUffLayout l;
    l.present = {true, true, false};
    QTest::newRow("no Fz") << uffRecord(0.1, l) << speed_feed << "bad.unv: no time response of Fz";
    l = {};
    l.force_units = "m/s^2";
    QTest::newRow("units") << uffRecord(0.1, l) << speed_feed
                           << "bad.unv: line 11: expected force units N, kN or lbf (record 9), found 'm/s^2'";
    QTest::newRow("no speed") << uffRecord(0.1) << QStringList{"--feed", "0.1"}
                              << "--speed: given 0 times for 1 record file(s)";
  }
  void badUffRecords() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString file = write(dir, "bad.unv", text);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"coefficients", file} + flags + kGeometry);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }
  void badInput_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("no diameter") << QStringList{"--teeth", "3", "--depth", "1"} << "--diameter is required";
    QTest::newRow("teeth") << QStringList{"--diameter", "12", "--teeth", "0", "--depth", "1"} << "--teeth";
    QTest::newRow("immersion") << QStringList{"--diameter", "12", "--teeth", "3", "--depth", "1", "--immersion", "2"}
                               << "--immersion";
    QTest::newRow("milling") << QStringList{"--diameter", "12", "--teeth", "3", "--depth", "1", "--milling", "climb"}
                             << "--milling = climb: must be up or down";
  }
  void badInput() {
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString file = write(dir, "cuts.csv", meanForces({0.04, 0.08}));
    const mx::test::CliRun r = mx::test::runCli(QStringList{"coefficients", file} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }
  void badFiles() {
    QTemporaryDir dir;
    const QString bad = write(dir, "bad.csv", "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N\n0.1,1,2,x\n");
    mx::test::CliRun r = mx::test::runCli(QStringList{"coefficients", bad} + kGeometry);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("bad.csv: line 2: Fz_N = 'x'"), qPrintable(r.err));
    const QString one = write(dir, "one.csv", meanForces({0.1}));
    r = mx::test::runCli(QStringList{"coefficients", one} + kGeometry);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("at least 2 feeds"), qPrintable(r.err));
    const QString a = write(dir, "a.csv", record(0.05)), b = write(dir, "b.csv", record(0.1));
    r = mx::test::runCli(
        QStringList{"coefficients", a, b, "--speed", "1500", "--feed", "0.05", "--feed", "0.1", "--feed", "0.2"} +
        kGeometry);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("--feed: given 3 times for 2 record file(s)"), qPrintable(r.err));
    r = mx::test::runCli(QStringList{"coefficients", dir.filePath("missing.csv")} + kGeometry);
    QCOMPARE(r.code, 2);
  }
};

MX_REGISTER_TEST(TestCliCoefficients)
#include "test_command_coefficients.moc"
