// millexpert-cli sdnrp and override: the fixed JSON keys; the SDNRP loop holds F at F_d
// (2 %) and Ra at the desired value (10 %) with the disturbance, exactly without it; the override
// writes a program that differs from the input only in F/S words and comments, with a header, and the
// CSV table; the adaptive controller is used when the project has a control section; bad input exits 2;
// --no-control holds feed and speed at the initial ones (F = K4 of them without the disturbance) and
// prints the same keys, with "control" and the spreads that show what the loop removes.
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <cmath>

#include "sdnrp/gp_models.h"
#include "support/cli_runner.h"
#include "support/hostile_files.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "support/text_lines.h"
#include "test_registry.h"

namespace {
using mx::test::kSdnrp;
const QString kAdaptive = QStringLiteral(MX_PROJECTS_DIR "/rubio2006-adaptive-control.mxproj");
const QString kPocket = QStringLiteral(MX_TEST_DATA_DIR "/gcode/pocket_mm.nc");
const QString kInch = QStringLiteral(MX_TEST_DATA_DIR "/gcode/inch.nc");

using mx::test::fileLines;

// A block with its F/S words and "(MX: ...)" comment removed: what must stay identical.
QString unchangedBlockPart(QString line) {
  line.remove(QRegularExpression(R"( \(MX: .*\)$)"));
  line.remove(QRegularExpression(R"([FfSs][-+]?[0-9.]+)"));
  return line.simplified();
}
}  // namespace

class TestCliSdnrp : public QObject {
  Q_OBJECT
 private slots:
  void sdnrp_data() {
    QTest::addColumn<double>("ra");
    QTest::addColumn<bool>("disturbance");
    for (double ra : {0.38, 0.81, 1.52}) {
      QTest::newRow(qPrintable(QString("Ra %1 with disturbance").arg(ra))) << ra << true;
      QTest::newRow(qPrintable(QString("Ra %1 without").arg(ra))) << ra << false;
    }
  }
  void sdnrp() {
    QFETCH(double, ra);
    QFETCH(bool, disturbance);
    QStringList args{"sdnrp", kSdnrp, "--ra", QString::number(ra)};
    if (!disturbance) args << "--no-disturbance";
    const mx::test::CliRun r = mx::test::runCli(args);
    QCOMPARE(r.code, 0);
    for (const char* key : {"Ra_desired", "Fd_N", "F_final_N", "feed_final_mm_min", "speed_final_rpm", "Ra_produced"})
      QVERIFY2(r.json.contains(key), key);
    QCOMPARE_LE(std::abs(r.json["Ra_desired"].toDouble() - ra), 1e-12);
    const double fd = r.json["Fd_N"].toDouble(), f = r.json["F_final_N"].toDouble();
    const double tol_f = disturbance ? 0.02 * fd : 1e-6 * fd;
    QCOMPARE_LE(std::abs(f - fd), tol_f);
    // Without the disturbance only K5(K1(Ra)) != Ra remains (the printed GP models are not exact
    // inverses: about 2e-6 relative).
    QCOMPARE_LE(std::abs(r.json["Ra_produced"].toDouble() - ra), (disturbance ? 0.10 : 1e-4) * ra);
  }
  void sdnrpCsvAndErrors() {
    QTemporaryDir dir;
    const mx::test::CliRun r =
        mx::test::runCli({"sdnrp", kSdnrp, "--ra", "0.81", "--seconds", "2", "--csv", dir.filePath("s.csv")});
    QCOMPARE(r.code, 0);
    const QStringList rows = fileLines(dir.filePath("s.csv"));
    QVERIFY(rows[0].startsWith("t_s,Ra_um,Ra_dynamic_um,F_N,F_dynamic_N,feed_mm_min,speed_rpm"));
    QCOMPARE_GE(rows.size(), 200);  // every 10 ms over 2 s
    const mx::test::CliRun bad = mx::test::runCli({"sdnrp", kSdnrp, "--ra", "3"});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("--ra"));
    const QString p = mx::test::writeMutatedProject(kSdnrp, {"sdnrp/disturbance/sigma_N=-1"}, dir.filePath("p.mxproj"));
    const mx::test::CliRun badSection = mx::test::runCli({"sdnrp", p});
    QCOMPARE(badSection.code, 2);
    QVERIFY(badSection.err.contains("sdnrp.disturbance.sigma_N = -1: must be in [0, 1e4]"));
  }

  void sdnrpNoControl() {
    // Sim 5 of the project: f = 430.41 mm/min, n = 1571 rpm held, F = K4(1571, 430.41) = 225.38 N.
    const double F = mx::SdnrpModels::cuttingForce(1571.0, 430.41);
    const mx::test::CliRun exact = mx::test::runCli({"sdnrp", kSdnrp, "--no-control", "--no-disturbance"});
    QCOMPARE(exact.code, 0);
    QCOMPARE(exact.json["control"].toBool(true), false);
    QCOMPARE_LE(std::abs(exact.json["F_final_N"].toDouble() - F), 1e-9 * F);
    QCOMPARE_LE(std::abs(exact.json["Ra_produced"].toDouble() - mx::SdnrpModels::roughness(F)), 1e-9);
    QCOMPARE_LE(std::abs(exact.json["feed_final_mm_min"].toDouble() - 430.41), 1e-9);
    QCOMPARE_LE(std::abs(exact.json["speed_final_rpm"].toDouble() - 1571.0), 1e-9);
    const QJsonObject flat = exact.json["F_spread_N"].toObject();
    QCOMPARE(flat["min"].toDouble(), flat["max"].toDouble());
    QCOMPARE_LE(flat["std"].toDouble(), 1e-6);

    const mx::test::CliRun off = mx::test::runCli({"sdnrp", kSdnrp, "--no-control"});
    const mx::test::CliRun on = mx::test::runCli({"sdnrp", kSdnrp});
    QCOMPARE(off.code, 0);
    QCOMPARE(on.code, 0);
    QCOMPARE(off.json.keys(), on.json.keys());  // the same keys, the controlled ones unchanged
    for (const char* key :
         {"Ra_desired", "Fd_N", "F_final_N", "feed_final_mm_min", "speed_final_rpm", "Ra_produced", "feed_saturated",
          "disturbance", "seed", "seconds", "control", "initial_feed_mm_min", "initial_speed_rpm", "F_spread_N",
          "Ra_spread_um", "F_final_spread_N", "Ra_final_spread_um"})
      QVERIFY2(off.json.contains(key), key);
    for (const char* key : {"F_spread_N", "Ra_spread_um", "F_final_spread_N", "Ra_final_spread_um"})
      QCOMPARE(off.json[key].toObject().keys(), (QStringList{"max", "mean", "min", "rms_error", "std"}));
    QCOMPARE(on.json["control"].toBool(false), true);
    QCOMPARE(off.json["initial_feed_mm_min"].toDouble(), 430.41);
    QCOMPARE(off.json["initial_speed_rpm"].toDouble(), 1571.0);
    QCOMPARE(off.json["feed_saturated"].toBool(true), false);
    // The measured force scatters about K4 of the held point (sigma 3 N), far from F_d = 188 N; the loop
    // brings its rms error about F_d from 37.6 to 3.0 N and Ra's from 1.17 to 0.046 um (final second).
    const QJsonObject f_off = off.json["F_final_spread_N"].toObject(), f_on = on.json["F_final_spread_N"].toObject();
    QCOMPARE_LE(std::abs(off.json["F_spread_N"].toObject()["mean"].toDouble() - F), 0.3);
    QCOMPARE_LT(f_on["rms_error"].toDouble(), f_off["rms_error"].toDouble() / 10.0);
    const QJsonObject ra_off = off.json["Ra_final_spread_um"].toObject();
    const QJsonObject ra_on = on.json["Ra_final_spread_um"].toObject();
    QCOMPARE_LT(ra_on["rms_error"].toDouble(), ra_off["rms_error"].toDouble() / 20.0);
    QCOMPARE_LT(ra_on["max"].toDouble(), ra_off["min"].toDouble());  // the two Ra bands do not overlap
  }

  void overrideChangesOnlyFeedsAndComments_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("project");
    QTest::newRow("mm, model-based") << kPocket << kSdnrp;
    QTest::newRow("inch, model-based") << kInch << kSdnrp;
    QTest::newRow("mm, adaptive") << kPocket << kAdaptive;
  }
  void overrideChangesOnlyFeedsAndComments() {
    QFETCH(QString, program);
    QFETCH(QString, project);
    QTemporaryDir dir;
    const QString out = dir.filePath("out.nc"), csv = dir.filePath("out.csv");
    const mx::test::CliRun r = mx::test::runCli({"override", program, project, "--out", out, "--csv", csv});
    QCOMPARE(r.code, 0);
    for (const char* key : {"controller", "blocks", "changed_blocks", "warnings", "feed_moves"})
      QVERIFY2(r.json.contains(key), key);
    QVERIFY(r.json["changed_blocks"].toInt() >= 1);
    QCOMPARE(r.json.contains("closed_loop"), project == kAdaptive);
    const QStringList in = fileLines(program), res = fileLines(out);
    // Header: four comment lines after a leading '%' line.
    const int header = 4;
    QVERIFY(res.join('\n').contains("(MillExpert optimised part program)"));
    QCOMPARE(res.size(), in.size() + header);
    const int first = in.value(0).trimmed() == "%" ? 1 : 0;
    for (int i = 0; i < in.size(); ++i) {
      const QString& a = in[i];
      const QString& b = res[i < first ? i : i + header];
      QCOMPARE(unchangedBlockPart(b), unchangedBlockPart(a));
    }
    QCOMPARE(fileLines(csv).value(0),
             QString("block,line,original_F_mm_min,new_F_mm_min,S_rpm,reason,predicted_force_N"));
  }
  void overrideErrors_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("no --out") << QStringList{"override", kPocket, kSdnrp} << "--out";
    QTest::newRow("one positional") << QStringList{"override", kSdnrp, "--out", "OUT"}
                                    << "expected PROGRAM.nc and PROJECT";
    QTest::newRow("controller") << QStringList{"override", kPocket, kSdnrp, "--out", "OUT", "--controller", "pid"}
                                << "--controller = 'pid': must be adaptive or model-based";
    QTest::newRow("missing program") << QStringList{"override", "MISSING", kSdnrp, "--out", "OUT"} << "missing.nc";
    QTest::newRow("adaptive without control")
        << QStringList{"override", kPocket, kSdnrp, "--out", "OUT", "--controller", "adaptive"}
        << "section 'control' is missing";
  }
  void overrideErrors() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    // OUT and MISSING stand for paths in this test's temporary folder; neither file exists.
    QTemporaryDir dir;
    const QString out = dir.filePath("x.nc");
    args.replaceInStrings(QRegularExpression("^OUT$"), out);
    args.replaceInStrings(QRegularExpression("^MISSING$"), dir.filePath("missing.nc"));
    const mx::test::CliRun r = mx::test::runCli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
  }
  // A part program is refused before it is read when it is not a regular file or over 16 MB; no
  // output is written.
  void unreadablePrograms_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("/dev/zero") << "/dev/zero"
                               << "a character device, not a regular file: a part program must be a regular file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: a part program must be a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file: a part program must be a regular file";
    QTest::newRow("16 MB + 1 byte") << QString("bytes:%1").arg(16 * mx::test::kMB + 1)
                                    << "16.0 MB (16777217 bytes) is over the 16 MB limit of a part program";
    QTest::newRow("80 MB") << QString("bytes:%1").arg(80 * mx::test::kMB)
                           << "80.0 MB (83886080 bytes) is over the 16 MB limit of a part program";
  }
  void unreadablePrograms() {
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString program = mx::test::hostileInput(dir, kind);
    QVERIFY(!program.isEmpty());
    const QString out = dir.filePath("out.nc");
    const mx::test::CliRun r = mx::test::runCli({"override", program, kSdnrp, "--out", out}, 20000);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(program + ": ") && r.err.contains(expected), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
  }
};

MX_REGISTER_TEST(TestCliSdnrp)
#include "test_command_sdnrp.moc"
