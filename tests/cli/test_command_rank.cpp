// millexpert-cli rank / weights-sweep: the fixed JSON interface, the 2006 example through the project
// file, and the exit codes (2: weights off the simplex; 1: empty admissible space, naming the constraint).
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
using mx::test::kRubio;

using Run = mx::test::CliRun;
using mx::test::cli;

// The Rubio project after `edit` of its root object, written to dir as `name`.
template <class Edit>
QString rubioEdited(const QTemporaryDir& dir, const QString& name, Edit edit) {
  QFile in(kRubio);
  in.open(QIODevice::ReadOnly);
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  edit(root);
  QString path = dir.filePath(name);
  QFile out(path);
  out.open(QIODevice::WriteOnly);
  out.write(QJsonDocument(root).toJson());
  return path;
}

// The Rubio project with one key of `section` replaced.
QString rubioWithKey(const QTemporaryDir& dir, const QString& section, const QString& key, const QJsonValue& value) {
  return rubioEdited(dir, section + ".mxproj", [&](QJsonObject& root) {
    QJsonObject object = root[section].toObject();
    object[key] = value;
    root[section] = object;
  });
}

QString rubioWith(const QTemporaryDir& dir, const QString& key, double value) {
  return rubioWithKey(dir, "machine", key, value);
}

QString rubioWithExpert(const QTemporaryDir& dir, const QString& key, const QJsonValue& value) {
  return rubioWithKey(dir, "expert", key, value);
}

QString rubioWithRules(const QTemporaryDir& dir, const QStringList& rules) {
  return rubioEdited(dir, "rules.mxproj",
                     [&](QJsonObject& root) { root["operator_rules"] = QJsonArray::fromStringList(rules); });
}
// The --chatter-at rows of badWeights (the same check: exit 2, the message, no JSON).
void addBadChatterAtRows() {
  QTest::newRow("no depth") << QStringList{"--chatter-at", "5800"} << "SPEED_RPM:DEPTH_MM";
  QTest::newRow("negative depth") << QStringList{"--chatter-at", "5800:-1"} << "depth [mm] '-1'";
  // the project field's range (expert.reported_chatter[].depth_mm)
  QTest::newRow("depth below 1e-6") << QStringList{"--chatter-at", "5800:1e-7"}
                                    << "depth [mm] '1e-7' must be a number in [1e-6, 1000]";
  QTest::newRow("text speed") << QStringList{"--chatter-at", "fast:0.5"} << "speed [rpm] 'fast'";
  QTest::newRow("zero frequency") << QStringList{"--chatter-at", "5800:0.5:0"} << "frequency [Hz] '0'";
  QTest::newRow("four fields") << QStringList{"--chatter-at", "1:2:3:4"} << "SPEED_RPM:DEPTH_MM";
  QTest::newRow("unknown tool") << QStringList{"--chatter-at", "5800:0.5", "--chatter-tool", "R9"}
                                << "--chatter-tool = 'R9': must be one of R1, R2";
}
}  // namespace

class TestCliRank : public QObject {
  Q_OBJECT
 private slots:
  void rankReproducesPaper() {
    const Run r = cli({"rank", kRubio});
    QCOMPARE(r.code, 0);
    for (const char* key : {"selected", "ranking", "q_star", "q_star_star", "malfunction_iterations"})
      QVERIFY2(r.json.contains(key), key);
    QCOMPARE(r.json["selected"].toString(), QString("R1"));
    const QJsonArray ranking = r.json["ranking"].toArray();
    QCOMPARE(ranking.size(), 2);
    const QJsonObject first = ranking[0].toObject();
    for (const char* key : {"tool", "min_cost", "q", "power_W", "mrr_mm3_min", "dNs_rpm"})
      QVERIFY2(first.contains(key), key);
    QCOMPARE(first["tool"].toString(), QString("R1"));
    QCOMPARE(ranking[1].toObject()["tool"].toString(), QString("R2"));
    QVERIFY(first["min_cost"].toDouble() < ranking[1].toObject()["min_cost"].toDouble());
    const QJsonObject q = r.json["q_star"].toObject();
    QCOMPARE(q["speed_rpm"].toDouble(), 5800.0);
    QCOMPARE_LE(std::abs(q["depth_mm"].toDouble() * q["feed_mm_per_tooth"].toDouble() / (0.4924 * 0.2722) - 1), 0.02);
    QCOMPARE_LE(std::abs(first["power_W"].toDouble() / 745.3 - 1.0), 0.02);
    QVERIFY(first["power_W"].toDouble() <= 745.3);
    QCOMPARE(first["q"].toObject(), q);
    // mm^3/min = a b s_t n_t N
    QCOMPARE_LE(std::abs(first["mrr_mm3_min"].toDouble() /
                             (30.0 * q["depth_mm"].toDouble() * q["feed_mm_per_tooth"].toDouble() * 3 * 5800.0) -
                         1),
                1e-9);
    const QJsonObject qss = r.json["q_star_star"].toObject();
    for (const char* key : {"speed_rpm", "depth_mm", "feed_mm_per_tooth"}) QVERIFY2(qss.contains(key), key);
    // Rule 5 pattern search: ours (5800 rpm, 0.2885 mm, 0.4725 mm); the paper's q** = (5680, 0.457, 0.265).
    QCOMPARE(qss["speed_rpm"].toDouble(), 5800.0);
    QCOMPARE_LE(std::abs(qss["depth_mm"].toDouble() - 0.28846), 1e-5);
    QCOMPARE_LE(std::abs(qss["feed_mm_per_tooth"].toDouble() - 0.4725), 1e-6);
    const QJsonObject rule5 = r.json["rule5"].toObject();
    for (const char* key : {"candidates", "seeds", "iterations", "converged", "simulations", "c_resultant"})
      QVERIFY2(rule5.contains(key), key);
    QCOMPARE(rule5["seeds"].toInt(), 12);
    QVERIFY(rule5["candidates"].toInt() > 12);
    QCOMPARE(rule5["simulations"].toInt(), rule5["candidates"].toInt());
    QVERIFY(rule5["converged"].toBool());
    QCOMPARE(r.json["malfunction_iterations"].toInt(), 0);
  }

  void rankWithoutSimulation() {
    const Run r = cli({"rank", kRubio, "--no-simulation", "--c", "0.1,0.8,0.1"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.json["q_star_star"].isNull());
    QCOMPARE(r.json["selected"].toString(), QString("R1"));
    QCOMPARE(r.json["c"].toArray()[1].toDouble(), 0.8);
  }

  // Rule 6 on chatter heard at q* (5800 rpm, 0.5048 mm): the weights take n Rule 6 steps
  // (c2 = 0.99^n 0.725) and q* leaves the reported region.
  void chatterAtMovesTheWeights() {
    const Run r = cli({"rank", kRubio, "--no-simulation", "--chatter-at", "5800:0.5:640"});
    QCOMPARE(r.code, 0);
    const int n = r.json["malfunction_iterations"].toInt();
    QVERIFY(n > 0);
    QCOMPARE(r.json["reported_chatter_iterations"].toInt(), n);
    QCOMPARE(r.json["malfunction_limit_reached"].toBool(), false);
    QCOMPARE_LE(std::abs(r.json["c"].toArray()[1].toDouble() - 0.725 * std::pow(0.99, n)), 1e-12);
    const QJsonArray reports = r.json["reported_chatter"].toArray();
    QCOMPARE(reports.size(), 1);
    const QJsonObject report = reports[0].toObject();
    QCOMPARE(report["tool"].toString(), QString("R1"));
    QCOMPARE(report["freq_Hz"].toDouble(), 640.0);
    QCOMPARE(report["holds_chosen_point"].toBool(), false);
    const QJsonObject region = report["region"].toObject();
    QCOMPARE_LE(std::abs(region["speed_from_rpm"].toDouble() - 5684.0), 1e-9);
    QCOMPARE_LE(std::abs(region["speed_to_rpm"].toDouble() - 5916.0), 1e-9);
    const QJsonObject q = r.json["q_star"].toObject();
    const bool outside = q["depth_mm"].toDouble() < 0.5 || std::abs(q["speed_rpm"].toDouble() / 5800.0 - 1.0) > 0.02;
    QVERIFY(outside);
  }

  // The project's reported chatter and the bound: every depth at 5800 rpm chatters, three steps allowed.
  void reportedChatterStopsAtBound() {
    QTemporaryDir dir;
    const QString bounded = rubioWithExpert(dir, "max_malfunction_iterations", 3);
    const Run r = cli({"rank", bounded, "--no-simulation", "--chatter-at", "5800:0.001"});
    QCOMPARE(r.code, 1);
    QCOMPARE(r.json["malfunction_iterations"].toInt(), 3);
    QCOMPARE(r.json["malfunction_limit_reached"].toBool(), true);
    QVERIFY(r.json["reported_chatter"].toArray()[0].toObject()["holds_chosen_point"].toBool());
    QVERIFY2(r.err.contains("Rule 6 stopped at its bound of 3 iterations") && r.err.contains("5800 rpm, 0.001 mm"),
             qPrintable(r.err));
    const QJsonArray fromFile{QJsonObject{{"tool", "R1"}, {"speed_rpm", 5800}, {"depth_mm", 0.5}}};
    const Run p = cli({"rank", rubioWithExpert(dir, "reported_chatter", fromFile), "--no-simulation"});
    QCOMPARE(p.code, 0);
    QVERIFY(p.json["malfunction_iterations"].toInt() > 0);
    QVERIFY(p.json["reported_chatter"].toArray()[0].toObject()["freq_Hz"].isNull());
  }

  void badWeights_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("c sum") << QStringList{"--c", "0.2,0.7,0.2"} << "must sum to 1";
    QTest::newRow("c negative") << QStringList{"--c", "-0.1,1.0,0.1"} << ">= 0";
    QTest::newRow("c count") << QStringList{"--c", "0.5,0.5"} << "expected 3";
    QTest::newRow("cr sum") << QStringList{"--cr", "0.8,0.1,0.2"} << "--cr";
    QTest::newRow("c text") << QStringList{"--c", "a,b,c"} << "not a finite number";
    addBadChatterAtRows();
  }
  void badWeights() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const Run r = cli(QStringList{"rank", kRubio, "--no-simulation"} + args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.json.isEmpty());
  }

  void emptySpaceIsExit1() {
    QTemporaryDir dir;
    const Run r = cli({"rank", rubioWith(dir, "spindle_power_W", 0.001), "--no-simulation"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("spindle power limit (0.001 W)"), qPrintable(r.err));
    const Run s = cli({"rank", rubioWith(dir, "max_spindle_rpm", 500)});
    QCOMPARE(s.code, 1);
    QVERIFY2(s.err.contains("spindle speed maximum (500 rpm"), qPrintable(s.err));
    const Run w = cli({"weights-sweep", rubioWith(dir, "spindle_power_W", 0.001), "--c3", "0.075"});
    QCOMPARE(w.code, 1);
  }

  // Module II: R1's tools[0].max_force_N = 60 N. Its unlimited q* peaks near 85 N (K_t sqrt(1 + K_r^2)
  // b s_t on the power limit); limited, q* stays under 60 N and the ranking reports both forces. A
  // 1 mN limit excludes R1, naming the limit, and R2 is selected.
  void toolForceLimitBoundsQStar() {
    const Run free = cli({"rank", kRubio, "--no-simulation"});
    QCOMPARE(free.code, 0);
    const QJsonObject free_r1 = free.json["ranking"].toArray()[0].toObject();
    QCOMPARE(free_r1["tool"].toString(), QString("R1"));
    QVERIFY(free_r1["max_force_N"].isNull());
    QCOMPARE_GE(free_r1["peak_force_N"].toDouble(), 80.0);
    QTemporaryDir dir;
    const auto withR1Limit = [&](double limit) {
      return rubioEdited(dir, QString("force-%1.mxproj").arg(limit), [&](QJsonObject& root) {
        QJsonArray tools = root["tools"].toArray();
        QJsonObject r1 = tools[0].toObject();
        r1["max_force_N"] = limit;
        tools[0] = r1;
        root["tools"] = tools;
      });
    };
    const Run r = cli({"rank", withR1Limit(60.0), "--no-simulation"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["selected"].toString(), QString("R1"));
    const QJsonObject r1 = r.json["ranking"].toArray()[0].toObject();
    QCOMPARE(r1["max_force_N"].toDouble(), 60.0);
    QCOMPARE_LE(r1["peak_force_N"].toDouble(), 60.0);
    const QJsonObject q = r.json["q_star"].toObject();
    const double force = 600.0 * std::sqrt(1.09) * q["depth_mm"].toDouble() * q["feed_mm_per_tooth"].toDouble();
    QCOMPARE_LE(std::abs(force - r1["peak_force_N"].toDouble()), 0.01 * force);  // q is rounded in the JSON
    const Run out = cli({"rank", withR1Limit(0.001), "--no-simulation"});
    QCOMPARE(out.code, 0);
    QCOMPARE(out.json["selected"].toString(), QString("R2"));
    const QJsonObject excluded = out.json["excluded"].toArray()[0].toObject();
    QCOMPARE(excluded["tool"].toString(), QString("R1"));
    QVERIFY2(excluded["reason"].toString().contains("tool force limit F_allow (0.001 N"),
             qPrintable(excluded["reason"].toString()));
  }

  // Figure 4: c3 = 0.075, c1 = 0 .. 0.925; R1 cheaper everywhere.
  void sweepC3() {
    const Run r = cli({"weights-sweep", kRubio, "--c3", "0.075"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["c3"].toDouble(), 0.075);
    const QJsonArray c1 = r.json["c1"].toArray();
    QCOMPARE(c1.size(), 38);  // 0, 0.025, ..., 0.925
    QCOMPARE(c1.first().toDouble(), 0.0);
    QCOMPARE_LE(std::abs(c1.last().toDouble() - 0.925), 1e-12);
    const QJsonArray r1 = r.json["min_cost"].toObject()["R1"].toArray();
    const QJsonArray r2 = r.json["min_cost"].toObject()["R2"].toArray();
    QCOMPARE(r1.size(), c1.size());
    for (int i = 0; i < c1.size(); ++i) QVERIFY(r1[i].toDouble() < r2[i].toDouble());
  }

  // Figure 5 over the simplex: R1 everywhere except the power-only corner (1, 0, 0).
  void sweepSimplex() {
    const Run r = cli({"weights-sweep", kRubio, "--simplex", "0.1"});
    QCOMPARE(r.code, 0);
    const QJsonArray points = r.json["points"].toArray();
    QCOMPARE(points.size(), 66);
    for (const auto& v : points) {
      const QJsonObject p = v.toObject();
      const QJsonArray c = p["c"].toArray();
      QCOMPARE_LE(std::abs(c[0].toDouble() + c[1].toDouble() + c[2].toDouble() - 1.0), 1e-12);
      QVERIFY(p["min_cost"].toObject().contains("R1") && p["min_cost"].toObject().contains("R2"));
      const bool corner = c[0].toDouble() > 0.999;
      QCOMPARE(p["selected"].toString(), QString(corner ? "R2" : "R1"));
    }
  }

  void sweepNeedsOneForm() {
    QCOMPARE(cli({"weights-sweep", kRubio}).code, 2);
    QCOMPARE(cli({"weights-sweep", kRubio, "--c3", "0.1", "--simplex", "0.1"}).code, 2);
    QCOMPARE(cli({"weights-sweep", kRubio, "--c3", "1.5"}).code, 2);
  }

  // The sweep's rankings (weight vectors x tools) are bounded: 5151 x 2 pass; 501501 x 2, and 10002 x 20
  // on the line c3 = 0.1, are refused by the flag before the lobes are computed.
  void sweepSizeIsBounded() {
    QCOMPARE(cli({"weights-sweep", kRubio, "--simplex", "0.01"}).code, 0);
    const Run r = cli({"weights-sweep", kRubio, "--simplex", "0.001"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("--simplex = 0.001: 501501 weight vectors x 2 tools = 1e+06 rankings, at most 1.5e+05 "
                            "(about 15 s): raise --simplex"),
             qPrintable(r.err));
    const Run line =
        cli({"weights-sweep", mx::test::projectsPath("library-20-tools.mxproj"), "--c3", "0.1", "--step", "0.0001"});
    QCOMPARE(line.code, 2);
    QVERIFY2(line.err.contains("--step = 0.0001: 10002 weight vectors x 20 tools = 2e+05 rankings"),
             qPrintable(line.err));
  }

  // Module VII in `rank`: a speed constraint on R1 moves its q* below the bound, a weight rule bounds
  // c3, advice is reported with whether q* follows it, and a rule excluding a tool's every point
  // excludes the tool with the reason.
  void operatorRulesInRank() {
    QTemporaryDir dir;
    const QString path = rubioWithRules(
        dir, {"if tool.id == \"R1\" then speed_rpm <= 3000", "if material.name != \"none\" then weight.c3 >= 0.5",
              "if tool.teeth >= 2 then advise depth_mm <= 0.3 because \"light cuts\""});
    const Run r = cli({"rank", path, "--no-simulation"});
    QCOMPARE(r.code, 0);
    const QJsonArray c = r.json["c"].toArray();
    QVERIFY(c[2].toDouble() >= 0.5 - 1e-12);
    QCOMPARE_LE(std::abs(c[0].toDouble() + c[1].toDouble() + c[2].toDouble() - 1.0), 1e-12);
    for (const auto& t : r.json["ranking"].toArray()) {
      const QJsonObject tool = t.toObject();
      if (tool["tool"].toString() == "R1") QVERIFY(tool["q"].toObject()["speed_rpm"].toDouble() <= 3000.0);
    }
    const QJsonObject rules = r.json["rules"].toObject();
    QCOMPARE(rules["fired"].toArray().size(), 3);
    const QJsonObject advice = rules["advice"].toArray()[0].toObject();
    const double depth = r.json["q_star"].toObject()["depth_mm"].toDouble();
    QCOMPARE(advice["followed"].toBool(), depth <= 0.3);

    const Run excluded =
        cli({"rank", rubioWithRules(dir, {"if tool.teeth == 2 then speed_rpm <= 10"}), "--no-simulation"});
    QCOMPARE(excluded.code, 0);
    QCOMPARE(excluded.json["ranking"].toArray().size(), 1);
    QCOMPARE(excluded.json["excluded"].toArray()[0].toObject()["tool"].toString(), QString("R2"));
    QVERIFY(excluded.json["excluded"].toArray()[0].toObject()["reason"].toString().startsWith("operator rules"));

    const Run none = cli({"rank", rubioWithRules(dir, {"speed_rpm <= 10"}), "--no-simulation"});
    QCOMPARE(none.code, 1);
    QVERIFY(none.err.contains("operator rules exclude every admissible point"));
    const Run bad = cli({"rank", rubioWithRules(dir, {"if tool.teeth >= then speed_rpm <= 10"})});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("operator_rules[0]: line 1, column"));
  }

  // With the ZOA the ranking's lobes leave the material's process damping out, and "notes" says so once;
  // with the SDM there is no note.
  void processDampingNote() {
    QTemporaryDir dir;
    const QString project = mx::test::writeMutatedProject(
        MX_PROJECTS_DIR "/process-damping-low-speed.mxproj",
        {"expert/grid/speed_from_rpm=2000", "expert/grid/speed_to_rpm=2400"}, dir.filePath("pd.mxproj"));
    const mx::test::CliRun zoa = mx::test::runCli({"rank", project, "--no-simulation"});
    QCOMPARE(zoa.code, 0);
    QCOMPARE(zoa.json["notes"].toArray().size(), 1);
    QVERIFY(zoa.json["notes"].toArray()[0].toString().contains("process_damping_N_per_m = 100000"));
    const mx::test::CliRun sdm = mx::test::runCli({"rank", project, "--no-simulation", "--method", "sdm"});
    QCOMPARE(sdm.code, 0);
    QVERIFY(!sdm.json.contains("notes"));
  }
};

MX_REGISTER_TEST(TestCliRank)
#include "test_command_rank.moc"
