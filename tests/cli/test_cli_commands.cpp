// millexpert-cli lobes / simulate / point: the fixed JSON interface, flag handling and exit codes
// (0 ok, 1 computation failed, 2 bad input), driven through the real executable.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
using mx::test::kRubio;
const QString kInsperger = QStringLiteral(MX_PROJECTS_DIR "/benchmark-insperger-1dof.mxproj");

using Run = mx::test::CliRun;
using mx::test::cli;
}  // namespace

class TestCliCommands : public QObject {
  Q_OBJECT
 private slots:
  void lobesJsonInterface() {
    const Run r = cli({"lobes", kRubio, "--tool", "R1", "--from", "4000", "--to", "6000", "--step", "500"});
    QCOMPARE(r.code, 0);
    for (const char* key : {"tool", "method", "speed_rpm", "blim_mm"}) QVERIFY2(r.json.contains(key), key);
    QCOMPARE(r.json["tool"].toString(), QString("R1"));
    QCOMPARE(r.json["method"].toString(), QString("zoa"));
    const QJsonArray speeds = r.json["speed_rpm"].toArray();
    QCOMPARE(speeds.size(), 5);
    QCOMPARE(speeds[0].toDouble(), 4000.0);
    QCOMPARE(speeds[4].toDouble(), 6000.0);
    // Defaults from the project: delta 0.05, alpha 0.95.
    QCOMPARE(r.json["alpha"].toDouble(), 0.95);
  }

  // alpha scales the envelope; delta 0 / alpha 1 are the nominal lobes (>= the margined ones).
  void lobesMarginsAndNulls() {
    const QStringList base{"lobes", kRubio, "--tool", "R1", "--from", "3000", "--to", "12000", "--step", "250"};
    const Run nominal = cli(base + QStringList{"--delta", "0", "--alpha", "1"});
    const Run half = cli(base + QStringList{"--delta", "0", "--alpha", "0.5"});
    const Run margined = cli(base + QStringList{"--delta", "100", "--alpha", "1"});
    QCOMPARE(nominal.code, 0);
    const QJsonArray n = nominal.json["blim_mm"].toArray(), h = half.json["blim_mm"].toArray(),
                     m = margined.json["blim_mm"].toArray();
    int nulls = 0;
    for (qsizetype i = 0; i < n.size(); ++i) {
      if (n[i].isNull()) {
        ++nulls;
        continue;
      }
      QCOMPARE_LE(std::abs(h[i].toDouble() - 0.5 * n[i].toDouble()), 1e-12);
      QVERIFY(m[i].toDouble() < n[i].toDouble());
    }
    QCOMPARE(nulls, 0);
    // Above --max-depth there is no instability: null entries.
    const Run capped = cli(base + QStringList{"--max-depth", "1.0", "--delta", "0", "--alpha", "1"});
    int capped_nulls = 0;
    for (const auto& v : capped.json["blim_mm"].toArray()) capped_nulls += v.isNull() ? 1 : 0;
    QVERIFY(capped_nulls > 0);
  }

  void lobesSdmMatchesZoaAtFullImmersion() {
    const QStringList base{"lobes", kRubio,   "--tool", "R1",      "--from", "7000",    "--to",
                           "8500",  "--step", "100",    "--delta", "0",      "--alpha", "1"};
    const Run zoa = cli(base);
    const Run sdm = cli(base + QStringList{"--method", "sdm", "--steps", "40"});
    QCOMPARE(sdm.code, 0);
    QCOMPARE(sdm.json["method"].toString(), QString("sdm"));
    const double zmin = zoa.json["minima"].toArray()[0].toObject()["blim_mm"].toDouble();
    const double smin = sdm.json["minima"].toArray()[0].toObject()["blim_mm"].toDouble();
    QCOMPARE_LE(std::abs(smin / zmin - 1.0), 0.05);
  }

  void simulateJsonInterfaceAndCsv() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("trace.csv");
    const Run r = cli(
        {"simulate", kRubio, "--tool", "R1", "--speed", "5800", "--depth", "0.4924", "--feed", "0.2722", "--csv", csv});
    QCOMPARE(r.code, 0);
    for (const char* key : {"eta", "chip_ratio", "chatter", "chatter_frequency_Hz", "tooth_passing_Hz", "peak_force_N",
                            "peak_power_W", "suggested_speed_rpm"})
      QVERIFY2(r.json.contains(key), key);
    QCOMPARE(r.json["chatter"].toBool(), false);
    QVERIFY(r.json["chatter_frequency_Hz"].isNull());
    QVERIFY(r.json["suggested_speed_rpm"].isNull());
    QCOMPARE(r.json["tooth_passing_Hz"].toDouble(), 290.0);
    QCOMPARE_LE(std::abs(r.json["peak_power_W"].toDouble() - 732.66), 0.05);
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readLine().trimmed(), QByteArray("time_s,x_mm,y_mm,Fx_N,Fy_N,F_N,P_W"));
    int rows = 0;
    while (!f.atEnd()) rows += f.readLine().split(',').size() == 7 ? 1 : 0;
    QVERIFY(rows > 1000);
  }

  // A chattering cut: the chatter frequency and a Smith-Tlusty speed N = 60 f_c / (n_t k) come back.
  void simulateChatterSuggestsSpeed() {
    const Run r =
        cli({"simulate", kRubio, "--tool", "R1", "--speed", "5800", "--depth", "3", "--feed", "0.1", "--passes", "4"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.json["chatter"].toBool());
    QVERIFY(r.json["eta"].toDouble() >= 1.3);
    const double fc = r.json["chatter_frequency_Hz"].toDouble();
    const double n = r.json["suggested_speed_rpm"].toDouble();
    const double k = 60.0 * fc / (3.0 * n);
    QCOMPARE_LE(std::abs(k - std::round(k)), 1e-9);
    QVERIFY(n <= 12000.0);  // machine.max_spindle_rpm
  }

  void pointReadouts() {
    const Run r = cli({"point", kRubio, "--tool", "R1", "--speed", "5800", "--depth", "0.4924", "--feed", "0.2722"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.json["stable"].toBool());
    // Below both lobe minima (4786 and 7761 rpm): Delta N_s = 5800 - 4786.
    QCOMPARE_LE(std::abs(r.json["delta_Ns_rpm"].toDouble() - 1014.0), 5.0);
    QVERIFY(r.json["ROS"].toDouble() > 0.0);
    QVERIFY(r.json["power_ok"].toBool());
  }

  void badInputExitsWithTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("names");
    QTest::newRow("unknown tool") << QStringList{"lobes", kRubio, "--tool", "X9"} << "X9";
    QTest::newRow("missing tool flag") << QStringList{"lobes", kRubio} << "--tool";
    QTest::newRow("bad method") << QStringList{"lobes", kRubio, "--tool", "R1", "--method", "fem"} << "--method";
    QTest::newRow("delta above decay rate")
        << QStringList{"lobes", kRubio, "--tool", "R1", "--delta", "500"} << "delta";
    QTest::newRow("alpha > 1") << QStringList{"lobes", kRubio, "--tool", "R1", "--alpha", "1.5"} << "--alpha";
    QTest::newRow("to < from") << QStringList{"lobes", kRubio, "--tool", "R1", "--from", "9000", "--to", "100"}
                               << "--to";
    QTest::newRow("steps too few") << QStringList{"lobes", kRubio, "--tool", "R1", "--method", "sdm", "--steps", "2"}
                                   << "--steps";
    QTest::newRow("delay order 4") << QStringList{"lobes",    kRubio, "--tool",        "R1",
                                                  "--method", "sdm",  "--delay-order", "4"}
                                   << "--delay-order";
    QTest::newRow("nan speed") << QStringList{"simulate", kRubio,    "--tool", "R1",     "--speed",
                                              "nan",      "--depth", "1",      "--feed", "0.1"}
                               << "--speed";
    QTest::newRow("negative depth") << QStringList{"simulate", kRubio,    "--tool", "R1",     "--speed",
                                                   "5000",     "--depth", "-1",     "--feed", "0.1"}
                                    << "--depth";
    QTest::newRow("missing feed") << QStringList{"simulate", kRubio, "--tool", "R1", "--speed", "5000", "--depth", "1"}
                                  << "--feed";
    QTest::newRow("unknown flag") << QStringList{"lobes", kRubio, "--tool", "R1", "--colour", "red"} << "colour";
    QTest::newRow("missing project") << QStringList{"lobes", "/nonexistent.mxproj", "--tool", "R1"} << "nonexistent";
    QTest::newRow("unknown command") << QStringList{"frobnicate", kRubio} << "frobnicate";
    // work past its bound is refused by the flags that set it, before any computation
    const QStringList sim{"simulate", kRubio, "--tool", "R1", "--depth", "0.1", "--feed", "0.1"};
    QTest::newRow("simulate at 1 rpm") << sim + QStringList{"--speed", "1"}
                                       << "--speed = 1 rpm and --revolutions = 60 (3 teeth, 532800 steps per tooth "
                                          "period): 9.59e+07 integration steps, at most 2e+07: raise --speed or lower "
                                          "--revolutions";
    QTest::newRow("simulate 100000 revolutions") << sim + QStringList{"--speed", "3000", "--revolutions", "100000"}
                                                 << "integration steps, at most 2e+07: raise --speed or lower "
                                                    "--revolutions";
    const QStringList lobes{"lobes", kRubio, "--tool", "R1", "--from", "1000", "--to", "100000"};
    QTest::newRow("sdm lobes at 1 rpm steps") << lobes + QStringList{"--method", "sdm", "--step", "1"}
                                              << "--method sdm: 99001 speeds (--from = 1000 to --to = 100000 by --step "
                                                 "= 1 rpm) x the automatic steps (about 60) = 5.94e+06 speed-steps, at "
                                                 "most 3e+05 (about 20 s): lower --steps or use fewer speeds";
    QTest::newRow("zoa lobes at 0.001 rpm steps")
        << lobes + QStringList{"--step", "0.001"} << "gives 99000001 speeds: the zoa lobes take at most 200000";
    QTest::newRow("lobes past the top speed")
        << QStringList{"lobes", kRubio, "--tool", "R1", "--from", "1000", "--to", "200000"} << "--to";
    QTest::newRow("point past the top speed")
        << QStringList{"point", kRubio, "--tool", "R1", "--speed", "1e6", "--depth", "0.1", "--feed", "0.1"}
        << "--speed";
  }
  void badInputExitsWithTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, names);
    const Run r = cli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(names), qPrintable(r.err));
  }

  // The default SDM: cubic delay interpolation, 140 steps per tooth period at a/D = 0.05 (20 in the cut).
  void inspergerLowImmersionSdmRuns() {
    const Run r = cli(
        {"lobes", kInsperger, "--tool", "LOW", "--method", "sdm", "--from", "9000", "--to", "12000", "--step", "500"});
    QCOMPARE(r.code, 0);
    for (const auto& v : r.json["blim_mm"].toArray()) QVERIFY(v.isNull() || v.toDouble() > 0.0);
    QCOMPARE(r.json["sdm_delay_order"].toInt(), 3);
    for (const auto& v : r.json["sdm_steps"].toArray()) QCOMPARE(v.toInt(), 140);
  }

  // Automatic steps follow the speed in the slot (omega T / 0.3: 120 at 5000 rpm, the minimum 60 at
  // 25000 rpm); --steps and --delay-order fix the first-order SDM of earlier versions.
  void sdmStepsAndDelayOrder() {
    const QStringList base{"lobes", kInsperger, "--tool", "FULL", "--method", "sdm", "--step", "20000"};
    const Run automatic = cli(base + QStringList{"--from", "5000", "--to", "25000"});
    QCOMPARE(automatic.code, 0);
    const QJsonArray steps = automatic.json["sdm_steps"].toArray();
    QCOMPARE(steps.size(), 2);
    QCOMPARE(steps[0].toInt(), 120);
    QCOMPARE(steps[1].toInt(), 60);
    // At 5600 rpm the first-order SDM at m = 40 (omega dt = 0.78) lies about 29 % from the default.
    const QStringList at5600{"--from", "5600", "--to", "5600"};
    const Run fixed = cli(base + at5600 + QStringList{"--steps", "40", "--delay-order", "1"});
    QCOMPARE(fixed.code, 0);
    QCOMPARE(fixed.json["sdm_delay_order"].toInt(), 1);
    QCOMPARE(fixed.json["sdm_steps"].toArray()[0].toInt(), 40);
    const Run fine = cli(base + at5600);
    QCOMPARE(fine.json["sdm_steps"].toArray()[0].toInt(), 110);  // 2 pi 922 T / 0.3 = 103.4
    const double a = fine.json["blim_mm"].toArray()[0].toDouble(), b = fixed.json["blim_mm"].toArray()[0].toDouble();
    QVERIFY(a > 0.0 && b > 0.0);
    QCOMPARE_GE(std::abs(b / a - 1.0), 0.2);
  }

  // A real cutter from the project file: tools[].pitch_deg, helix_deg, runout_um reach every command's
  // model. Insperger's FULL tool made a 4-tooth 70/110 deg cutter: the SDM (revolution map) differs from
  // the uniform tool's at 19000 rpm by more than half, the JSON names the cutter, --helix-slices is
  // echoed, and a pitch list that does not sum to 360 is refused with exit code 2.
  void realCutterFromTheProjectFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile in(kInsperger);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject project = QJsonDocument::fromJson(in.readAll()).object();
    QJsonArray tools = project["tools"].toArray();
    QJsonObject tool = tools[0].toObject();
    tool["teeth"] = 4;
    QJsonObject uniform = tool;
    uniform["id"] = "U4";
    tool["id"] = "VP4";
    tool["pitch_deg"] = QJsonArray{70, 110, 70, 110};
    tool["helix_deg"] = 30;
    tool["runout_um"] = QJsonArray{0, 5, 0, -3};
    tools.append(uniform);
    tools.append(tool);
    project["tools"] = tools;
    const QString path = dir.filePath("real-cutter.mxproj");
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(project).toJson());
    out.close();

    const QStringList at19000{"--method", "sdm", "--from", "19000", "--to", "19000", "--step", "100"};
    const Run vp = cli(QStringList{"lobes", path, "--tool", "VP4"} + at19000);
    const Run u = cli(QStringList{"lobes", path, "--tool", "U4"} + at19000);
    QCOMPARE(vp.code, 0);
    QCOMPARE(u.code, 0);
    const QJsonObject cutter = vp.json["cutter"].toObject();
    QCOMPARE(cutter["pitch"].toString(), QString("variable"));
    QCOMPARE(cutter["principal_period"].toString(), QString("revolution"));
    QCOMPARE(cutter["helix_deg"].toDouble(), 30.0);
    QCOMPARE(cutter["pitch_deg"].toArray()[1].toDouble(), 110.0);
    QCOMPARE(cutter["runout_um"].toArray()[3].toDouble(), -3.0);
    QCOMPARE(u.json["cutter"].toObject()["pitch"].toString(), QString("uniform"));
    QCOMPARE(vp.json["sdm_helix_slices"].toInt(), 0);
    const double b_vp = vp.json["blim_mm"].toArray()[0].toDouble(), b_u = u.json["blim_mm"].toArray()[0].toDouble();
    QCOMPARE_GE(b_vp / b_u, 1.5);

    const Run sim = cli({"simulate", path, "--tool", "VP4", "--speed", "19000", "--depth", "0.1", "--feed", "0.05"});
    QCOMPARE(sim.code, 0);
    QCOMPARE(sim.json["chatter"].toBool(), false);
    QCOMPARE_GE(sim.json["axial_slices"].toInt(), 1);

    tool["pitch_deg"] = QJsonArray{70, 110, 70, 111};
    tools[2] = tool;
    project["tools"] = tools;
    QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
    out.write(QJsonDocument(project).toJson());
    out.close();
    const Run bad = cli(QStringList{"lobes", path, "--tool", "VP4"} + at19000);
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains("pitch_deg"), qPrintable(bad.err));
  }
};

MX_REGISTER_TEST(TestCliCommands)
#include "test_cli_commands.moc"
