// millexpert-cli point: the available spindle power at the point's speed. Rubio et al. Pareto paper,
// Table 4's P column (1696.5, 2273.3, 1894.4 W at 1800, 2412, 2010 rpm) is 0.3 pi N W, the 9 N·m
// torque line of projects/rubio-pareto-case.mxproj (machine.max_torque_Nm = 9, P_max = 2745.3 W).
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
using mx::test::kParetoCase;

mx::test::CliRun point(const QString& project, const QString& speed, const QString& depth, const QString& feed) {
  return mx::test::runCli({"point", project, "--tool", "R1", "--speed", speed, "--depth", depth, "--feed", feed});
}
}  // namespace

class TestCommandPoint : public QObject {
  Q_OBJECT
 private slots:
  // Table 4's working points, s_t = v_f / (n_t N): P_av = 2 pi (N / 60) 9 within the paper's rounding;
  // the peak cutting power (eq. 8) is far below it.
  void table4PowerColumn_data() {
    QTest::addColumn<QString>("speed");
    QTest::addColumn<QString>("depth");
    QTest::addColumn<double>("vf_mm_s");
    QTest::addColumn<double>("paper_W");
    QTest::addColumn<double>("cutting_W");
    QTest::newRow("row 1") << "1800"
                           << "0.3693" << 4.24 << 1696.5 << 29.5;
    QTest::newRow("row 2") << "2412"
                           << "0.3609" << 5.58 << 2273.3 << 38.0;
    QTest::newRow("row 3") << "2010"
                           << "1.5124" << 17.96 << 1894.4 << 512.0;
  }
  void table4PowerColumn() {
    QFETCH(QString, speed);
    QFETCH(QString, depth);
    QFETCH(double, vf_mm_s);
    QFETCH(double, paper_W);
    QFETCH(double, cutting_W);
    const double feed = vf_mm_s / (3.0 * speed.toDouble() / 60.0);
    const mx::test::CliRun r = point(kParetoCase, speed, depth, QString::number(feed, 'g', 10));
    QCOMPARE(r.code, 0);
    const double available = r.json["available_power_W"].toDouble();
    QCOMPARE_LE(std::abs(available - paper_W), 0.05);
    QCOMPARE_LE(std::abs(available - 0.3 * std::numbers::pi * speed.toDouble()), 1e-9 * available);
    const double peak = r.json["peak_power_W"].toDouble();
    QCOMPARE_LE(std::abs(peak - cutting_W), 0.1);
    QCOMPARE_LE(std::abs(r.json["power_fraction"].toDouble() - peak / available), 1e-12);
    QVERIFY(r.json["power_ok"].toBool());
  }

  // "verdict": stable below alpha b_lim, marginal up to 1.05 b_lim / alpha (the lobe itself), unstable
  // beyond; "stable" stays the strict test b < alpha b_lim.
  void verdictBands_data() {
    QTest::addColumn<double>("factor");  // of the lobe b_lim / alpha
    QTest::addColumn<QString>("verdict");
    QTest::newRow("half alpha b_lim") << -0.5 << "stable";
    QTest::newRow("on the lobe") << 1.0 << "marginal";
    QTest::newRow("4 % above the lobe") << 1.04 << "marginal";
    QTest::newRow("6 % above the lobe") << 1.06 << "unstable";
  }
  void verdictBands() {
    QFETCH(double, factor);
    QFETCH(QString, verdict);
    const mx::test::CliRun probe = point(kParetoCase, "2400", "0.1", "0.05");
    QCOMPARE(probe.code, 0);
    const double alpha_blim = probe.json["blim_mm"].toDouble();
    const double alpha = 0.95;  // expert.alpha of the case
    const double depth = factor < 0.0 ? -factor * alpha_blim : factor * alpha_blim / alpha;
    const mx::test::CliRun r = point(kParetoCase, "2400", QString::number(depth, 'g', 10), "0.05");
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["verdict"].toString(), verdict);
    QCOMPARE(r.json["stable"].toBool(), verdict == "stable");
  }

  // Above the corner speed 2745.3 / (2 pi 9) rev/s = 2912.85 rpm, P_max binds; without the torque
  // P_av = P_max at every speed, and a cut of 4 mm at 0.3 mm/tooth, 1800 rpm (2035.8 W) passes only then.
  void torqueLineAgainstPmax() {
    QCOMPARE_LE(std::abs(point(kParetoCase, "4000", "0.5", "0.1").json["available_power_W"].toDouble() - 2745.3), 1e-9);
    const mx::test::CliRun limited = point(kParetoCase, "1800", "4", "0.3");
    QCOMPARE_LE(std::abs(limited.json["peak_power_W"].toDouble() - 2035.8), 0.5);
    QVERIFY(!limited.json["power_ok"].toBool());
    QCOMPARE_LE(std::abs(limited.json["power_fraction"].toDouble() - 2035.8 / 1696.46), 1e-3);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString plain =
        mx::test::writeMutatedProject(kParetoCase, {"-machine/max_torque_Nm"}, dir.filePath("plain.mxproj"));
    const mx::test::CliRun r = point(plain, "1800", "4", "0.3");
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["available_power_W"].toDouble(), 2745.3);
    QVERIFY(r.json["power_ok"].toBool());
  }

  // A power curve and the torque line together: the minimum of the three at the speed.
  void curveAndTorqueTakeTheMinimum() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString project = mx::test::writeMutatedProject(
        kParetoCase,
        {"machine/spindle_curve=[{\"speed_rpm\": 1000, \"power_W\": 500}, {\"speed_rpm\": 3000, \"power_W\": 2500}]"},
        dir.filePath("curve.mxproj"));
    // 2000 rpm: curve 1500 W, torque 1885.0 W, P_max 2745.3 W; 500 rpm: constant torque of the first
    // row, 250 W (the 9 N·m line gives 471.2 W).
    QCOMPARE_LE(std::abs(point(project, "2000", "0.5", "0.1").json["available_power_W"].toDouble() - 1500.0), 1e-9);
    QCOMPARE_LE(std::abs(point(project, "500", "0.5", "0.1").json["available_power_W"].toDouble() - 250.0), 1e-9);
  }

  // Rule 3 (Module II): Table 4 row 3 (2010 rpm, 1.5124 mm, 17.96 mm/s) peaks at K_t sqrt(1 + K_r^2) b s_t
  // = 169.3 N, under the case tool's 600 N. With tools[0].max_force_N = 150 it is refused; with no tool
  // limit the control section's safety_factor * breakage_force_N (0.5 * 1000 N) is used; with neither
  // there is no limit key.
  void toolForceLimit() {
    const QString feed = QString::number(17.96 / (3.0 * 2010.0 / 60.0), 'g', 10);
    const mx::test::CliRun own = point(kParetoCase, "2010", "1.5124", feed);
    QCOMPARE(own.code, 0);
    const double expected = 600.0 * std::sqrt(1.0 + 0.3 * 0.3) * 1.5124 * feed.toDouble();
    QCOMPARE_LE(std::abs(own.json["peak_force_N"].toDouble() - expected), 1e-3 * expected);
    QCOMPARE_LE(std::abs(expected - 169.3), 0.05);
    QCOMPARE(own.json["max_force_N"].toDouble(), 600.0);
    QVERIFY(own.json["force_ok"].toBool());
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString none =
        mx::test::writeMutatedProject(kParetoCase, {"-tools/0/max_force_N"}, dir.filePath("none.mxproj"));
    const mx::test::CliRun free = point(none, "2010", "1.5124", feed);
    QCOMPARE(free.code, 0);
    QVERIFY(!free.json.contains("max_force_N") && !free.json.contains("force_ok"));
    const QString limited =
        mx::test::writeMutatedProject(kParetoCase, {"tools/0/max_force_N=150"}, dir.filePath("limited.mxproj"));
    const mx::test::CliRun r = point(limited, "2010", "1.5124", feed);
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["max_force_N"].toDouble(), 150.0);
    QVERIFY(!r.json["force_ok"].toBool());
    QCOMPARE_LE(std::abs(r.json["force_fraction"].toDouble() - r.json["peak_force_N"].toDouble() / 150.0), 1e-12);
    const QString breakage = mx::test::writeMutatedProject(
        kParetoCase, {"-tools/0/max_force_N", "control/breakage_force_N=1000", "control/safety_factor=0.5"},
        dir.filePath("breakage.mxproj"));
    const mx::test::CliRun b = point(breakage, "2010", "1.5124", feed);
    QCOMPARE(b.json["max_force_N"].toDouble(), 500.0);
    QVERIFY(b.json["force_ok"].toBool());
  }

  // Every speed of the flag's range is answered: outside the project's grid (1000-5000 rpm) the lobes
  // are computed +-50 % around the point (up to 1e5 rpm) on a lattice through it (step max(10, N / 1000)
  // rpm), and
  // b_lim there is the `lobes` command's on the same speeds.
  void speedsOutsideTheGrid_data() {
    QTest::addColumn<double>("speed");
    QTest::newRow("just above the grid, off its lattice") << 5005.0;
    QTest::newRow("12005 rpm") << 12005.0;
    QTest::newRow("the flag's top") << 100000.0;
    QTest::newRow("below the grid") << 333.3;
  }
  void speedsOutsideTheGrid() {
    QFETCH(double, speed);
    const mx::test::CliRun r = point(kParetoCase, QString::number(speed, 'g', 10), "0.1", "0.05");
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["speed_rpm"].toDouble(), speed);
    const double step = std::max(10.0, speed / 1000.0);
    const double half = std::floor(0.5 * speed / step) * step;
    const double above = std::floor(std::min(0.5 * speed, 1e5 - speed) / step) * step;
    const mx::test::CliRun lobes =
        mx::test::runCli({"lobes", kParetoCase, "--tool", "R1", "--from", QString::number(speed - half, 'g', 17),
                          "--to", QString::number(speed + above, 'g', 17), "--step", QString::number(step, 'g', 17)});
    QCOMPARE(lobes.code, 0);
    const QJsonArray speeds = lobes.json["speed_rpm"].toArray();
    const qsizetype at = static_cast<qsizetype>(std::llround(half / step));
    QCOMPARE_LE(std::abs(speeds.at(at).toDouble() - speed), 1e-9 * speed);
    const QJsonValue expected = lobes.json["blim_mm"].toArray().at(at);
    const QJsonValue got = r.json["blim_mm"];
    QCOMPARE(got.isNull(), expected.isNull());
    if (!got.isNull()) QCOMPARE_LE(std::abs(got.toDouble() - expected.toDouble()), 1e-9 * expected.toDouble());
  }

  // The grid's top speed is inside its lobes (rubio2006-adaptive-control: 400-3000 rpm; q* of its tool
  // is at 3000 rpm).
  void theGridsTopSpeed() {
    const mx::test::CliRun r = mx::test::runCli({"point", mx::test::projectsPath("rubio2006-adaptive-control.mxproj"),
                                                 "--tool", "C1", "--speed", "3000", "--depth", "0.5", "--feed", "0.3"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY(r.json["blim_mm"].toDouble() > 0.0);
  }

  // The semi-discretization's work is bounded by speeds x steps: refused by the flag, before any work.
  void sdmWorkIsBounded() {
    const mx::test::CliRun r = mx::test::runCli({"point", kParetoCase, "--tool", "R1", "--speed", "3000", "--depth",
                                                 "0.1", "--feed", "0.05", "--method", "sdm", "--steps", "2000"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("--method sdm: 401 speeds (expert.grid 1000 to 5000 rpm by 10 rpm) x --steps 2000 = "
                            "8.02e+05 speed-steps, at most 3e+05 (about 20 s)"),
             qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
  }

  // The point flags left out are the project's operating_point, the ones given win; without a stored
  // point each is required. simulate reads them alike.
  void flagsDefaultToTheStoredPoint_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("depth");
    QTest::addColumn<double>("feed");
    QTest::newRow("none") << QStringList{} << 2010.0 << 1.5124 << 0.1787;
    QTest::newRow("speed") << QStringList{"--speed", "2400"} << 2400.0 << 1.5124 << 0.1787;
    QTest::newRow("depth and feed") << QStringList{"--depth", "0.3", "--feed", "0.05"} << 2010.0 << 0.3 << 0.05;
    QTest::newRow("all four") << QStringList{"--tool", "R1", "--speed", "1800", "--depth", "0.3693", "--feed", "0.05"}
                              << 1800.0 << 0.3693 << 0.05;
  }
  void flagsDefaultToTheStoredPoint() {
    QFETCH(QStringList, flags);
    QFETCH(double, speed);
    QFETCH(double, depth);
    QFETCH(double, feed);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString project =
        mx::test::writeMutatedProject(kParetoCase,
                                      {"operating_point={\"tool\": \"R1\", \"speed_rpm\": 2010, \"depth_mm\": 1.5124, "
                                       "\"feed_mm_per_tooth\": 0.1787}"},
                                      dir.filePath("stored.mxproj"));
    const mx::test::CliRun r = mx::test::runCli(QStringList{"point", project} + flags);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json["tool"].toString(), QString("R1"));
    QCOMPARE(r.json["speed_rpm"].toDouble(), speed);
    QCOMPARE(r.json["depth_mm"].toDouble(), depth);
    QCOMPARE(r.json["feed_per_tooth_mm"].toDouble(), feed);
    const mx::test::CliRun flagged =
        mx::test::runCli({"point", kParetoCase, "--tool", "R1", "--speed", QString::number(speed, 'g', 17), "--depth",
                          QString::number(depth, 'g', 17), "--feed", QString::number(feed, 'g', 17)});
    QCOMPARE(r.json["peak_power_W"].toDouble(), flagged.json["peak_power_W"].toDouble());
    QCOMPARE(r.json["blim_mm"].toDouble(), flagged.json["blim_mm"].toDouble());
    const mx::test::CliRun simulated =
        mx::test::runCli(QStringList{"simulate", project, "--revolutions", "21"} + flags);
    QVERIFY2(simulated.code == 0, qPrintable(simulated.err));
    QCOMPARE(simulated.json["tool"].toString(), QString("R1"));
  }

  void flagsAreRequiredWithoutAStoredPoint_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("missing");
    QTest::newRow("point, no flag") << "point" << QStringList{} << "--tool";
    QTest::newRow("point, no depth") << "point" << QStringList{"--tool", "R1", "--speed", "2000", "--feed", "0.1"}
                                     << "--depth";
    QTest::newRow("simulate, no feed") << "simulate" << QStringList{"--tool", "R1", "--speed", "2000", "--depth", "0.1"}
                                       << "--feed";
  }
  void flagsAreRequiredWithoutAStoredPoint() {
    QFETCH(QString, command);
    QFETCH(QStringList, flags);
    QFETCH(QString, missing);
    const mx::test::CliRun r = mx::test::runCli(QStringList{command, kParetoCase} + flags);
    QCOMPARE(r.code, 2);
    QCOMPARE(r.err.trimmed(),
             QString("millexpert-cli: %1 is required: the project has no operating_point to default to").arg(missing));
  }

  // The cutting data used, after the tool's overrides, and the process-damping note: the ZOA leaves the
  // material's C_i out and says so, the SDM includes it (its limit rises at 600 rpm); peak_axial_force_N is 0
  // without axial coefficients.
  void cuttingDataAndProcessDampingNote() {
    QTemporaryDir dir;  // the lobe chart's grid narrowed to 560-640 rpm, so that the SDM takes a second
    const QString project = mx::test::writeMutatedProject(
        MX_PROJECTS_DIR "/process-damping-low-speed.mxproj",
        {"expert/grid/speed_from_rpm=560", "expert/grid/speed_to_rpm=640"}, dir.filePath("pd.mxproj"));
    const QStringList args{"point", project, "--tool", "EM10-4F", "--speed", "600", "--depth", "0.2", "--feed", "0.05"};
    const mx::test::CliRun zoa = mx::test::runCli(args);
    QCOMPARE(zoa.code, 0);
    const QJsonObject data = zoa.json["cutting_data"].toObject();
    QCOMPARE(data["Kt_N_mm2"].toDouble(), 1648.0);
    QCOMPARE(data["Kte_N_mm"].toDouble(), 46.0);
    QCOMPARE(data["process_damping_N_per_m"].toDouble(), 1e5);
    QCOMPARE(zoa.json["peak_axial_force_N"].toDouble(), 0.0);
    const QJsonArray notes = zoa.json["notes"].toArray();
    QCOMPARE(notes.size(), 1);
    QVERIFY(notes[0].toString().contains("leaves out the process damping"));
    const mx::test::CliRun sdm = mx::test::runCli(args + QStringList{"--method", "sdm"});
    QCOMPARE(sdm.code, 0);
    QVERIFY(!sdm.json.contains("notes"));
    QVERIFY2(sdm.json["blim_mm"].isNull() || sdm.json["blim_mm"].toDouble() > 1.5 * zoa.json["blim_mm"].toDouble(),
             sdm.out);
  }
};

MX_REGISTER_TEST(TestCommandPoint)
#include "test_command_point.moc"
