// millexpert-cli control: the fixed JSON keys; the paper's four betas keep the feed within
// [0, f_max] and the force bounded; the unstable-zero threshold agrees with the first-order formula
// of the reading notes; the sweep flags exactly the betas below the threshold and its best beta is
// the argmin of J_c over the others; --csv has one row per sample; bad input exits 2 naming the field; the
// spindle sampling period reproduces the figure 9 run key by key, Rule 4 saves samples, and the Pareto case's
// programme (Fig. 6) reports each point's settled feed beside the analytic 600 N feed and Table 4's; --beta-study
// prints one row per tau_c with both readings of eq. 34.
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
const QString kAdaptiveControl = QStringLiteral(MX_PROJECTS_DIR "/rubio2006-adaptive-control.mxproj");
using mx::test::kParetoCase;
}  // namespace

class TestCliControl : public QObject {
  Q_OBJECT
 private slots:
  void closedLoop_data() {
    QTest::addColumn<double>("beta");
    for (double b : {-0.3, 0.0, 0.3, 1.0}) QTest::newRow(qPrintable(QString("beta %1").arg(b))) << b;
  }
  void closedLoop() {
    QFETCH(double, beta);
    const mx::test::CliRun r = mx::test::runCli({"control", kAdaptiveControl, "--beta", QString::number(beta)});
    QCOMPARE(r.code, 0);
    for (const char* key : {"beta", "overshoot_pct", "settling_time_s", "Jc", "unstable_zero", "max_force_N",
                            "min_feed_mm_s", "max_feed_mm_s"})
      QVERIFY2(r.json.contains(key), key);
    QCOMPARE(r.json["beta"].toDouble(), beta);
    QCOMPARE(r.json["overshoot_pct"].toArray().size(), 3);  // three depth steps (figure 7)
    QVERIFY(r.json["min_feed_mm_s"].toDouble() >= 0.0);
    QVERIFY(r.json["max_feed_mm_s"].toDouble() <= 30.0 + 1e-9);  // feed_max_mm_s of the project
    // The force stays below K_p(5 mm) f_max = K_c b a f_max / (n_t N) with a = 4/pi (full immersion).
    const double kp5 = 1200e6 * 5e-3 * (4.0 / M_PI) / (4.0 * 715.0 / 60.0);
    QVERIFY(r.json["max_force_N"].toDouble() <= kp5 * 0.030);
    QVERIFY(!r.json["unstable_zero"].toBool());
    QVERIFY(r.json["completed"].toBool());
    QVERIFY(r.json["Jc"].toDouble() > 0.0);
    // Poles of H_beta at exp(-T/tau): tau_c (10.49 ms) and the drive (0, underflow).
    const double T = r.json["sampling_period_s"].toDouble();
    QCOMPARE_LE(std::abs(T - 60.0 / 715.0), 1e-12);
    const double tau_c = r.json["tau_c_ms"].toDouble() * 1e-3;
    bool found = false;
    for (const auto& p : r.json["poles"].toArray())
      found = found || std::abs(p.toArray()[0].toDouble() - std::exp(-T / tau_c)) < 1e-12;
    QVERIFY(found);
  }

  // First-order formula of the reading notes: beta* = -(1 - a) / (2 (1 - c)), a = e^{-T/tau_c},
  // c = tau_c (1 - a) / T; the 0.1 ms drive moves it by less than 1e-3.
  void thresholdAgreesWithFirstOrderFormula() {
    const mx::test::CliRun r = mx::test::runCli({"control", kAdaptiveControl, "--beta", "0"});
    const double T = r.json["sampling_period_s"].toDouble(), tau = r.json["tau_c_ms"].toDouble() * 1e-3;
    const double a = std::exp(-T / tau), c = tau * (1 - a) / T;
    QCOMPARE_LE(std::abs(r.json["threshold_beta"].toDouble() + (1 - a) / (2 * (1 - c))), 1e-3);
  }

  void sweep() {
    const mx::test::CliRun r = mx::test::runCli({"control", kAdaptiveControl, "--sweep-beta=-1:1:0.1"});
    QCOMPARE(r.code, 0);
    const QJsonArray beta = r.json["beta"].toArray(), jc = r.json["Jc"].toArray(),
                     unstable = r.json["unstable_zero"].toArray();
    QCOMPARE(beta.size(), 21);
    QCOMPARE(jc.size(), 21);
    const double threshold = r.json["threshold_beta"].toDouble();
    double best = INFINITY, best_beta = 0;
    for (qsizetype i = 0; i < beta.size(); ++i) {
      QCOMPARE(unstable[i].toBool(), beta[i].toDouble() < threshold);
      if (!unstable[i].toBool() && jc[i].toDouble() < best) {
        best = jc[i].toDouble();
        best_beta = beta[i].toDouble();
      }
    }
    QCOMPARE(r.json["best_beta"].toDouble(), best_beta);
  }

  void csvHasOneRowPerSample() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("s.csv"), dense = dir.filePath("d.csv");
    const mx::test::CliRun r =
        mx::test::runCli({"control", kAdaptiveControl, "--beta", "0.3", "--csv", csv, "--csv-continuous", dense});
    QCOMPARE(r.code, 0);
    QFile f(csv), g(dense);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(g.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.size() - 1, r.json["samples"].toInt());
    QVERIFY(lines[0].startsWith("t_s,reference_N,model_N,force_N,error_N,feed_mm_s,depth_mm"));
    QVERIFY(g.readAll().count('\n') > 32 * (lines.size() - 2));  // 32 continuous points per period
  }

  // The figure 9 run (beta = -0.3) as it was before Rule 4 existed: every number of its JSON.
  void spindleReproducesTheFigure9Run() {
    const mx::test::CliRun r = mx::test::runCli({"control", kAdaptiveControl, "--sample-period", "spindle"});
    QCOMPARE(r.code, 0);
    const std::pair<const char*, double> expected[] = {{"Jc", 172.28782454282913},
                                                       {"duration_s", 2.7692307692307683},
                                                       {"max_feed_mm_s", 15.893475619690872},
                                                       {"max_force_N", 2482.8646650982573},
                                                       {"min_feed_mm_s", 0.4909373969104549},
                                                       {"settling_time_s", 0.5942980918645104},
                                                       {"samples", 34},
                                                       {"rls_resets", 20}};
    for (const auto& [key, value] : expected)
      QVERIFY2(std::abs(r.json[key].toDouble() - value) <= 1e-9 * std::abs(value),
               qPrintable(QString("%1 = %2").arg(key).arg(r.json[key].toDouble(), 0, 'g', 17)));
    QCOMPARE(r.json["sample_period"].toString(), QString("spindle"));
    QCOMPARE(r.json["sampling_period_min_s"].toDouble(), 60.0 / 715.0);
    QCOMPARE(r.json["sampling_period_max_s"].toDouble(), 60.0 / 715.0);
    QVERIFY(!r.json.contains("programme"));
  }

  void rule4SavesSamples() {
    const mx::test::CliRun spindle = mx::test::runCli({"control", kAdaptiveControl});
    const mx::test::CliRun r =
        mx::test::runCli({"control", kAdaptiveControl, "--sample-period", "rule4", "--rule4-periods", "4"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["sample_period"].toString(), QString("rule4"));
    QCOMPARE(r.json["rule4_periods"].toInt(), 4);
    QCOMPARE(r.json["sampling_period_max_s"].toDouble(), 4 * 60.0 / 715.0);
    QVERIFY(r.json["samples"].toInt() < spindle.json["samples"].toInt());
    QVERIFY(r.json["completed"].toBool());
  }

  void paretoProgramme() {
    const mx::test::CliRun r = mx::test::runCli({"control", kParetoCase});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["force_reference_N"].toDouble(), 600.0);
    QCOMPARE(r.json["sample_period"].toString(), QString("rule4"));
    const QJsonArray segments = r.json["programme"]["segments"].toArray();
    QCOMPARE(segments.size(), 3);
    const double table_feed[3] = {4.24, 5.58, 17.96};
    for (qsizetype i = 0; i < 3; ++i) {
      const QJsonObject seg = segments[i].toObject();
      const double analytic = seg["analytic_feed_mm_s"].toDouble();
      QVERIFY2(std::abs(seg["settled_feed_mm_s"].toDouble() - analytic) < 0.01 * analytic,
               qPrintable(QString::number(i)));
      QVERIFY(std::abs(seg["settled_force_N"].toDouble() - 600.0) < 6.0);
      QCOMPARE(seg["programmed_feed_mm_s"].toDouble(), table_feed[i]);
      QVERIFY(seg["force_at_programmed_feed_N"].toDouble() < 600.0);  // Table 4's feeds give far less than 600 N
      for (const char* key :
           {"speed_rpm", "depth_mm", "start_s", "end_s", "samples", "mean_force_N", "peak_force_N", "overshoot_pct"})
        QVERIFY2(seg.contains(key), key);
    }
    const QJsonObject history = r.json["programme"]["history"].toObject();
    QCOMPARE(history["t_s"].toArray().size(), r.json["samples"].toInt());
    QCOMPARE(history["feed_mm_s"].toArray().size(), r.json["samples"].toInt());
    QCOMPARE(history["force_N"].toArray().size(), r.json["samples"].toInt());
    QVERIFY(r.json["spindle_revolutions"].toDouble() > r.json["samples"].toInt());
  }

  // --beta-study: the keys, one row per tau_c, the paper's -0.6 at tau_c = T/6 (within 0.01), each reading's best
  // beta the argmin of its J_c over the stable-zero betas, and no match with figure 13 at these tau_c.
  void betaStudy() {
    const double T = 60.0 / 715.0;
    const QString taus = QString("%1,%2").arg(T / 8.0 * 1e3, 0, 'g', 17).arg(T / 6.0 * 1e3, 0, 'g', 17);
    const mx::test::CliRun r =
        mx::test::runCli({"control", kAdaptiveControl, "--beta-study", "--tau-c-ms", taus, "--sweep-beta=-1:1:0.1"});
    QCOMPARE(r.code, 0);
    for (const char* key : {"sampling_period_s", "default_tau_c_ms", "paper", "beta", "rows", "matches_paper",
                            "tau_c_at_paper_threshold_ms", "tau_c_near_paper_threshold_ms"})
      QVERIFY2(r.json.contains(key), key);
    QCOMPARE_LE(std::abs(r.json["default_tau_c_ms"].toDouble() - T / 8.0 * 1e3), 1e-9);
    QCOMPARE(r.json["paper"].toObject()["threshold_beta"].toDouble(), -0.6);
    QCOMPARE(r.json["paper"].toObject()["best_beta"].toDouble(), -0.3);
    const QJsonArray beta = r.json["beta"].toArray(), rows = r.json["rows"].toArray();
    QCOMPARE(beta.size(), 21);
    QCOMPARE(rows.size(), 2);
    QCOMPARE_LE(std::abs(rows[0].toObject()["tau_c_over_T"].toDouble() - 0.125), 1e-12);
    QCOMPARE_LE(std::abs(rows[1].toObject()["threshold_beta"].toDouble() - (-0.6)), 0.01);
    for (const auto& row_value : rows) {
      const QJsonObject row = row_value.toObject();
      for (const char* key : {"tau_c_ms", "tau_c_over_T", "threshold_beta", "first_order_threshold_beta",
                              "threshold_near_paper", "unstable_zero", "readings"})
        QVERIFY2(row.contains(key), key);
      QVERIFY(row["threshold_near_paper"].toBool());
      const QJsonArray readings = row["readings"].toArray(), unstable = row["unstable_zero"].toArray();
      QCOMPARE(readings.size(), 2);
      QCOMPARE(readings[0].toObject()["reading"].toString(), QString("plant_samples"));
      QCOMPARE(readings[1].toObject()["reading"].toString(), QString("reference_model"));
      for (const auto& reading_value : readings) {
        const QJsonObject reading = reading_value.toObject();
        for (const char* key : {"best_beta", "best_Jc", "near_paper", "isolated_minimum", "Jc"})
          QVERIFY2(reading.contains(key), key);
        const QJsonArray jc = reading["Jc"].toArray();
        QCOMPARE(jc.size(), beta.size());
        double best = INFINITY, best_beta = 0.0;
        for (qsizetype i = 0; i < beta.size(); ++i) {
          QCOMPARE(unstable[i].toBool(), beta[i].toDouble() < row["threshold_beta"].toDouble());
          if (!unstable[i].toBool() && jc[i].toDouble() < best) {
            best = jc[i].toDouble();
            best_beta = beta[i].toDouble();
          }
        }
        QCOMPARE(reading["best_beta"].toDouble(), best_beta);
        QCOMPARE(reading["best_Jc"].toDouble(), best);
        QCOMPARE(reading["near_paper"].toBool(), std::abs(best_beta - (-0.3)) <= 0.15);
      }
    }
    QVERIFY(r.json["matches_paper"].isArray());
    QVERIFY(r.json["matches_paper"].toArray().isEmpty());
    // the tau_c of -0.6 exactly lies in the interval whose thresholds round to -0.6
    const QJsonArray near = r.json["tau_c_near_paper_threshold_ms"].toArray();
    const double at = r.json["tau_c_at_paper_threshold_ms"].toDouble();
    QVERIFY(near[0].toDouble() < at && at < near[1].toDouble());
  }

  void badInput_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("beta range") << QStringList{} << QStringList{"--beta", "1.5"} << "--beta";
    QTest::newRow("sweep form") << QStringList{} << QStringList{"--sweep-beta", "0:1"} << "--sweep-beta = '0:1'";
    QTest::newRow("sweep order") << QStringList{} << QStringList{"--sweep-beta", "0.5:0:0.1"} << "FROM <= TO";
    QTest::newRow("sweep of 10000 runs") << QStringList{} << QStringList{"--sweep-beta", "-1:1:0.0002"}
                                         << "at most 400 steps (each a closed-loop run)";
    QTest::newRow("tau_c zero") << QStringList{} << QStringList{"--beta-study", "--tau-c-ms", "0"}
                                << "--tau-c-ms = '0': expected a comma-separated list or FROM:TO:STEP of 1 to 50 "
                                   "values, each in (0, 10000] ms";
    QTest::newRow("tau_c without study") << QStringList{} << QStringList{"--tau-c-ms", "10"}
                                         << "--tau-c-ms: needs --beta-study";
    QTest::newRow("study with beta") << QStringList{} << QStringList{"--beta-study", "--beta", "0"}
                                     << "--beta: not allowed with --beta-study";
    QTest::newRow("study too long") << QStringList{}
                                    << QStringList{"--beta-study", "--sweep-beta", "-1:1:0.005", "--tau-c-ms", "1:50:1"}
                                    << "closed-loop runs: at most 4000";
    QTest::newRow("no section") << QStringList{"-control"} << QStringList{} << "section 'control' is missing";
    QTest::newRow("negative depth") << QStringList{"control/workpiece/1/depth_mm=-1"} << QStringList{}
                                    << "control.workpiece[1].depth_mm = -1: must be in [0, 1000]";
    QTest::newRow("lambda") << QStringList{"control/rls/lambda=1.5"} << QStringList{}
                            << "control.rls.lambda = 1.5: must be in [0.5, 1]";
    QTest::newRow("reset rule") << QStringList{"control/rls/reset=\"sometimes\""} << QStringList{}
                                << "control.rls.reset = 'sometimes': must be one of error, trace, none";
    QTest::newRow("unknown tool") << QStringList{"control/tool=\"X\""} << QStringList{} << "control.tool = 'X'";
    QTest::newRow("angles") << QStringList{"control/exit_angle_deg=0"} << QStringList{} << "control.exit_angle_deg";
    QTest::newRow("sample period flag") << QStringList{} << QStringList{"--sample-period", "foo"}
                                        << "--sample-period = 'foo': must be one of spindle, rule4";
    QTest::newRow("rule4 periods flag") << QStringList{} << QStringList{"--rule4-periods", "0"} << "--rule4-periods";
    QTest::newRow("sample period") << QStringList{"control/sample_period=\"foo\""} << QStringList{}
                                   << "control.sample_period = 'foo': must be one of spindle, rule4";
    QTest::newRow("rule4 periods") << QStringList{"control/rule4_periods=1.5"} << QStringList{}
                                   << "control.rule4_periods = 1.5: must be an integer in [1, 100]";
  }
  void badInput() {
    QFETCH(QStringList, mutations);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mx::test::writeMutatedProject(kAdaptiveControl, mutations, dir.filePath("p.mxproj"));
    const mx::test::CliRun r = mx::test::runCli(QStringList{"control", path} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }
};

MX_REGISTER_TEST(TestCliControl)
#include "test_command_control.moc"
