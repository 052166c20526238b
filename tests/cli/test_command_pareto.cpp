// millexpert-cli pareto: the fixed JSON interface on projects/rubio-pareto-case.mxproj, the flags
// (--w, --fine, --require, --auto-weights) and the exit-2 messages for a bad "pareto" section or flag.
// Pareto modules VI/VII: the project's operator_rules (Rule 18) in the selection and the "rules" key;
// --feedback (Rules 15/16 and a re-selection) and --db recording a "feedback" entry.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "support/postgres_server.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
using mx::test::kParetoCase;

QString caseWith(const QTemporaryDir& dir, const QStringList& mutations) {
  QFile in(kParetoCase);
  in.open(QIODevice::ReadOnly);
  const QJsonObject root = mx::test::mutated(QJsonDocument::fromJson(in.readAll()).object(), mutations);
  QString path = dir.filePath("p.mxproj");
  QFile out(path);
  out.open(QIODevice::WriteOnly);
  out.write(QJsonDocument(root).toJson());
  return path;
}

double sum(const QJsonArray& a) {
  double s = 0.0;
  for (const auto& v : a) s += v.toDouble();
  return s;
}
}  // namespace

class TestCliPareto : public QObject {
  Q_OBJECT
 private slots:
  void interface_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::newRow("project weights") << QStringList{};
    QTest::newRow("--w") << QStringList{"--w", "0.1,0.6,0.1,0.2"};
    QTest::newRow("--fine") << QStringList{"--fine"};
    QTest::newRow("--require") << QStringList{"--require", "mrr_cm3_s=0.3:0.6"};
    QTest::newRow("--auto-weights") << QStringList{"--auto-weights"};
  }
  void interface() {
    QFETCH(QStringList, flags);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"pareto", kParetoCase} + flags);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    for (const char* key :
         {"q", "feed_velocity_mm_s", "mrr_cm3_s", "tol", "surf", "ros", "eta", "power_W", "weights", "pareto_set"})
      QVERIFY2(r.json.contains(key), key);
    const QJsonObject q = r.json["q"].toObject();
    for (const char* key : {"speed_rpm", "depth_mm", "feed_mm_per_tooth"}) QVERIFY2(q.contains(key), key);
    const QJsonArray w = r.json["weights"].toArray();
    QCOMPARE(w.size(), 4);
    QVERIFY(std::abs(sum(w) - 1.0) < 1e-6);
    for (const auto& v : w) QVERIFY(v.toDouble() >= -1e-12);
    QVERIFY(r.json["power_W"].toDouble() <= 2745.3 * (1 + 1e-6));
    QVERIFY(r.json["feed_velocity_mm_s"].toDouble() <= 25.0 * (1 + 1e-6));
    QVERIFY(r.json["j"].toDouble() >= r.json["coarse_j"].toDouble());
    QVERIFY(r.json["eta"].toDouble() > 0.0);
    const QJsonArray set = r.json["pareto_set"].toArray();
    QVERIFY(!set.isEmpty());
    const QJsonObject first = set.first().toObject();
    for (const char* key : {"q", "tol", "mrr_cm3_s", "surf", "ros"}) QVERIFY2(first.contains(key), key);
    if (flags.contains("--require")) {
      const double mrr = r.json["mrr_cm3_s"].toDouble();
      QVERIFY2(mrr >= 0.3 && mrr <= 0.6, qPrintable(QString::number(mrr)));
      QVERIFY(r.json["requirement"].toObject()["satisfied"].toBool());
    }
  }

  void errors_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("no pareto section") << QStringList{"-pareto"} << QStringList{} << "section 'pareto' is missing";
    QTest::newRow("taylor K") << QStringList{"pareto/taylor/K=-1"} << QStringList{}
                              << "pareto.taylor.K = -1: must be a finite number > 0";
    QTest::newRow("roughness exponent") << QStringList{"pareto/roughness/feed_exponent=12"} << QStringList{}
                                        << "pareto.roughness.feed_exponent = 12: must be in [-10, 10]";
    QTest::newRow("missing exponent") << QStringList{"-pareto/taylor/depth_exponent"} << QStringList{}
                                      << "pareto.taylor.depth_exponent is missing";
    QTest::newRow("weights sum") << QStringList{"pareto/weights=[0.5,0.5,0.5,0.5]"} << QStringList{}
                                 << "pareto.weights: w = [0.5, 0.5, 0.5, 0.5]: the weights";
    QTest::newRow("fine divisions") << QStringList{"pareto/fine/divisions=0"} << QStringList{}
                                    << "pareto.fine.divisions = 0: must be an integer in [1, 100]";
    QTest::newRow("ascent step") << QStringList{"pareto/auto_weights/step=2"} << QStringList{}
                                 << "pareto.auto_weights.step = 2: must be in (0, 1]";
    QTest::newRow("unknown tool") << QStringList{"pareto/tool=\"X\""} << QStringList{}
                                  << "pareto.tool = 'X': no tool with that id";
    QTest::newRow("--w count") << QStringList{} << QStringList{"--w", "0.5,0.5"} << "expected 4 weights";
    QTest::newRow("--w simplex") << QStringList{} << QStringList{"--w", "0.5,0.5,0.5,-0.5"} << ">= 0";
    QTest::newRow("--require form") << QStringList{} << QStringList{"--require", "mrr_cm3_s=2"} << "--require = ";
    QTest::newRow("--require key") << QStringList{} << QStringList{"--require", "speed=1:2"}
                                   << "--require key = 'speed': must be one of mrr_cm3_s, tol, surf, ros";
    QTest::newRow("--require order") << QStringList{} << QStringList{"--require", "mrr_cm3_s=2:1"} << "LO <= HI";
    QTest::newRow("--chatter-hz") << QStringList{} << QStringList{"--chatter-hz", "-5"} << "--chatter-hz";
    QTest::newRow("--front-limit") << QStringList{} << QStringList{"--front-limit", "-3"}
                                   << "--front-limit = -3: must be an integer >= 0";
    QTest::newRow("--objective") << QStringList{} << QStringList{"--objective", "cheap"}
                                 << "--objective = 'cheap': must be one of weighted, min_cost, max_rate";
    QTest::newRow("--normalisation") << QStringList{} << QStringList{"--normalisation", "z"}
                                     << "--normalisation = 'z': must be one of minmax, max, log";
    QTest::newRow("normalisation field") << QStringList{"pareto/normalisation=\"linear\""} << QStringList{}
                                         << "pareto.normalisation = 'linear': must be one of minmax, max, log";
    QTest::newRow("objective field") << QStringList{"pareto/objective=\"fast\""} << QStringList{}
                                     << "pareto.objective = 'fast': must be one of weighted, min_cost, max_rate";
    QTest::newRow("min_cost without economics")
        << QStringList{"-pareto/economics", "pareto/objective=\"min_cost\""} << QStringList{}
        << "pareto.objective = 'min_cost' needs pareto.economics";
    QTest::newRow("machine rate") << QStringList{"pareto/economics/machine_rate_per_h=-1"} << QStringList{}
                                  << "pareto.economics.machine_rate_per_h = -1: must be in [0, 1e6]";
    QTest::newRow("removal volume") << QStringList{"pareto/economics/removal_volume_cm3=0"} << QStringList{}
                                    << "pareto.economics.removal_volume_cm3 = 0: must be in (0, 1e9]";
    QTest::newRow("fraction") << QStringList{"pareto/requirements/min_mrr_fraction=1.5"} << QStringList{}
                              << "pareto.requirements.min_mrr_fraction = 1.5: must be in [0, 1]";
    QTest::newRow("two requirements") << QStringList{"pareto/requirements/min_mrr_cm3_s=0.1"} << QStringList{}
                                      << "pareto.requirements: give one of min_mrr_cm3_s, min_mrr_fraction";
  }
  void errors() {
    QFETCH(QStringList, mutations);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mutations.isEmpty() ? kParetoCase : caseWith(dir, mutations);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"pareto", path} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }

  // The project's weights with its minimum MRR (25 % of Q's largest): a cut away from the grid's
  // lower corner, the requirement named as binding; without it (--no-requirement), the lower corner.
  void defaultRequirement() {
    const mx::test::CliRun r = mx::test::runCli({"pareto", kParetoCase, "--front-limit", "1"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json["normalisation"].toString(), QString("log"));
    QCOMPARE(r.json["objective"].toString(), QString("weighted"));
    const QJsonObject req = r.json["requirement"].toObject();
    QCOMPARE(req["source"].toString(), QString("pareto.requirements.min_mrr_fraction"));
    QVERIFY(req["binding"].toBool() && req["satisfied"].toBool() && !req["weights_changed"].toBool());
    QVERIFY(req["hi"].isNull());
    QCOMPARE_GE(r.json["mrr_cm3_s"].toDouble(), req["lo"].toDouble());
    QCOMPARE_GT(r.json["q"].toObject()["depth_mm"].toDouble(), 3 * 0.0721329);
    QStringList keys;
    for (const auto& b : r.json["binding"].toArray()) keys << b.toObject()["key"].toString();
    QVERIFY2(keys.contains("requirement"), qPrintable(keys.join(',')));
    const QJsonObject e = r.json["economics"].toObject();
    // 150 cm^3 at the selected MRR.
    QCOMPARE_LE(std::abs(e["machining_time_min"].toDouble() - 150.0 / r.json["mrr_cm3_s"].toDouble() / 60.0), 1e-9);

    const mx::test::CliRun free = mx::test::runCli({"pareto", kParetoCase, "--front-limit", "1", "--no-requirement"});
    QCOMPARE(free.code, 0);
    QVERIFY(!free.json.contains("requirement"));
    QCOMPARE(free.json["q"].toObject()["depth_mm"].toDouble(), 0.0721329100458);
    QCOMPARE(free.json["q"].toObject()["speed_rpm"].toDouble(), 1000.0);
  }

  // min_cost never costs more per part than the weighted choice, max_rate never takes longer.
  void economicObjectives() {
    QJsonObject economics[3];
    const QString objectives[3] = {"weighted", "min_cost", "max_rate"};
    for (int i = 0; i < 3; ++i) {
      const mx::test::CliRun r =
          mx::test::runCli({"pareto", kParetoCase, "--front-limit", "1", "--objective", objectives[i]});
      QVERIFY2(r.code == 0, qPrintable(r.err));
      QCOMPARE(r.json["objective"].toString(), objectives[i]);
      economics[i] = r.json["economics"].toObject();
    }
    const QJsonObject &weighted = economics[0], &cheap = economics[1], &fast = economics[2];
    // Gilbert (Taylor exponent -3.02, 2 min tool change, 45 per tool, 60 per hour): 2.02 (2 + 45) min,
    // and 2.02 x 2 min for the maximum rate.
    QCOMPARE_LE(std::abs(cheap["gilbert_tool_life_min"].toDouble() - 2.02 * 47.0), 1e-9);
    QCOMPARE_LE(std::abs(fast["gilbert_tool_life_min"].toDouble() - 2.02 * 2.0), 1e-9);
    QCOMPARE_LE(cheap["cost_per_part"].toDouble(), weighted["cost_per_part"].toDouble());
    QCOMPARE_LE(cheap["cost_per_part"].toDouble(), fast["cost_per_part"].toDouble());
    QCOMPARE_LE(fast["time_per_part_min"].toDouble(), cheap["time_per_part_min"].toDouble());
    QCOMPARE_LE(fast["time_per_part_min"].toDouble(), weighted["time_per_part_min"].toDouble());
  }

  // Module VI, reported by the operator: Rule 16 speed N_s = 60 f_c / (n_t k) nearest q, and a
  // re-selection within +-2 % of it.
  void operatorReportedChatter() {
    const mx::test::CliRun r = mx::test::runCli({"pareto", kParetoCase, "--chatter-hz", "668", "--front-limit", "1"});
    QCOMPARE(r.code, 0);
    const QJsonObject fb = r.json["feedback"].toObject();
    QCOMPARE(fb["reported_by"].toString(), QString("operator"));
    QVERIFY(fb["chatter"].toBool());
    const int k = fb["k"].toInt();
    const double ns = fb["suggested_speed_rpm"].toDouble();
    QCOMPARE_LE(std::abs(ns - 60.0 * 668.0 / (3.0 * k)), 1e-9 * ns);
    // nearest to q's speed among the lobe speeds
    const double n = r.json["q"].toObject()["speed_rpm"].toDouble();
    QVERIFY(std::abs(ns - n) <= std::abs(60.0 * 668.0 / (3.0 * (k + 1)) - n) + 1e-9);
    const double reselected = fb["reselected"].toObject()["q"].toObject()["speed_rpm"].toDouble();
    QCOMPARE_LE(std::abs(reselected - ns), 0.02 * ns);
  }

  // --front-limit keeps the N points of the whole set with the best J; 0 lists the whole set.
  void frontLimit() {
    const mx::test::CliRun all = mx::test::runCli({"pareto", kParetoCase, "--front-limit", "0"});
    QCOMPARE(all.code, 0);
    const qint64 size = all.json["pareto_set_size"].toInteger();
    QCOMPARE(all.json["pareto_set"].toArray().size(), size);
    QCOMPARE(all.json["pareto_set_truncated"].toBool(), false);
    const mx::test::CliRun few = mx::test::runCli({"pareto", kParetoCase, "--front-limit", "10", "--no-requirement"});
    QCOMPARE(few.code, 0);
    QCOMPARE(few.json["pareto_set_size"].toInteger(), size);
    QCOMPARE(few.json["pareto_set"].toArray().size(), 10);
    QVERIFY(few.json["pareto_set_truncated"].toBool());
    // Without a requirement the chosen q (the best J of Q, a front point) is among the 10 kept.
    bool found = false;
    for (const auto& p : few.json["pareto_set"].toArray()) found = found || p.toObject()["q"] == few.json["q"];
    QVERIFY(found);
  }

  // Rule 18: a fired speed constraint restricts q and is named in rules.fired; advice is listed.
  void operatorRulesRestrictSpeed() {
    QTemporaryDir dir, free_dir;
    const QStringList weights{"--w", "0.1,0.6,0.1,0.2"};
    QJsonArray rules_json{"# shop rules", "# (speed rule)",
                          "if material.name == \"Aluminium\" then advise \"use coolant\"",
                          "if machine.max_spindle_rpm < 3000 then depth_mm <= 0.1", "weight.ros >= 0.3"};
    auto rulesMutation = [&] {
      return "operator_rules=" + QString::fromUtf8(QJsonDocument(rules_json).toJson(QJsonDocument::Compact));
    };
    // The same rules without the speed constraint: the speed it would choose.
    const mx::test::CliRun unrestricted =
        mx::test::runCli(QStringList{"pareto", caseWith(free_dir, {rulesMutation()})} + weights);
    QVERIFY2(unrestricted.code == 0, qPrintable(unrestricted.err));
    const double limit = unrestricted.json["q"].toObject()["speed_rpm"].toDouble() - 500.0;
    QVERIFY2(limit >= 1000.0, qPrintable(QString::number(limit)));
    rules_json[1] = QString("if tool.diameter_mm > 10 then speed_rpm <= %1 because \"spindle wear\"").arg(limit);
    const QString path = caseWith(dir, {rulesMutation()});
    for (const QStringList& flags : {QStringList{}, QStringList{"--fine"}}) {
      const mx::test::CliRun r = mx::test::runCli(QStringList{"pareto", path} + weights + flags);
      QVERIFY2(r.code == 0, qPrintable(r.err));
      const double speed = r.json["q"].toObject()["speed_rpm"].toDouble();
      QVERIFY2(speed <= limit * (1 + 1e-9), qPrintable(QString::number(speed)));
      QVERIFY(r.json["j"].toDouble() >= r.json["coarse_j"].toDouble());
      const QJsonObject rules = r.json["rules"].toObject();
      const QJsonArray fired = rules["fired"].toArray();
      bool named = false, coolant = false;
      for (const auto& v : fired) {
        const QJsonObject f = v.toObject();
        if (f["line"].toInt() == 2 && f["kind"].toString() == "constraint" &&
            f["text"].toString().contains("speed_rpm <=") && f["reason"].toString().contains("spindle wear"))
          named = true;
        if (f["line"].toInt() == 3 && f["kind"].toString() == "advice") coolant = true;
      }
      QVERIFY2(named, qPrintable(QJsonDocument(rules).toJson()));
      QVERIFY(coolant);
      QCOMPARE(rules["advice"].toArray().size(), 1);
      QCOMPARE(rules["advice"].toArray()[0].toObject()["message"].toString(), QString("use coolant"));
      // machine.max_spindle_rpm is absent from the case: the rule on line 4 is undetermined.
      QCOMPARE(rules["undetermined"].toArray().size(), 1);
      QCOMPARE(rules["undetermined"].toArray()[0].toObject()["line"].toInt(), 4);
      // weight.ros >= 0.3 clamps the project's 0.2, the weights stay on the simplex.
      const QJsonArray w = r.json["weights"].toArray();
      QVERIFY(w[3].toDouble() >= 0.3 - 1e-12);
      QVERIFY(std::abs(sum(w) - 1.0) < 1e-9);
      for (const auto& v : w) QVERIFY(v.toDouble() >= 0.0);
    }
  }

  void operatorRuleErrors_data() {
    QTest::addColumn<QString>("rules");
    QTest::addColumn<QStringList>("messages");
    QTest::newRow("syntax") << R"(["speed_rpm <= 9000", "if tool.diameter_mm < 10 speed_rpm <= 8000"])"
                            << QStringList{"operator_rules[1]: line 2, column 26: expected 'then'"};
    QTest::newRow("contradiction") << R"(["speed_rpm <= 3000", "if tool.teeth >= 3 then speed_rpm >= 4000"])"
                                   << QStringList{
                                          "operator_rules[0] (line 1) 'speed_rpm <= 3000'",
                                          "operator_rules[1] (line 2) 'if tool.teeth >= 3 then speed_rpm >= 4000'",
                                          "no speed_rpm satisfies both"};
    QTest::newRow("not an array") << R"("speed_rpm <= 9000")" << QStringList{"operator_rules: must be an array"};
  }
  void operatorRuleErrors() {
    QFETCH(QString, rules);
    QFETCH(QStringList, messages);
    QTemporaryDir dir;
    const mx::test::CliRun r = mx::test::runCli({"pareto", caseWith(dir, {"operator_rules=" + rules})});
    QCOMPARE(r.code, 2);
    for (const QString& m : messages) QVERIFY2(r.err.contains(m), qPrintable(r.err));
  }

  // Module VI: a light-damped, 10 % immersion variant at alpha = 1 chatters at the MRR optimum
  // (chip ratio ~1.45); the Smith-Tlusty speed is 60 f_c / (n_t k) and the re-selection is recorded.
  void feedbackOnChatter() {
    QTemporaryDir dir;
    const QString path =
        caseWith(dir, {"tools/0/modes_x/0/damping_pct=1.0", "tools/0/modes_y/0/damping_pct=1.0", "expert/alpha=1.0",
                       "expert/delta_per_s=0.0", "operation/radial_immersion=0.1"});
    const QString db = dir.filePath("learning.sqlite");
    const mx::test::CliRun r = mx::test::runCli({"pareto", path, "--w", "0,1,0,0", "--feedback", "--db", db}, 600000);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QJsonObject fb = r.json["feedback"].toObject();
    QVERIFY2(fb["chatter"].toBool(), qPrintable(QJsonDocument(fb).toJson()));
    QVERIFY(fb["chip_ratio"].toDouble() >= 1.25);
    const double fc = fb["chatter_frequency_Hz"].toDouble();
    const double ns = fb["suggested_speed_rpm"].toDouble();
    QVERIFY(fc > 0.0 && ns > 0.0);
    const double k = 60.0 * fc / (3.0 * ns);
    QVERIFY2(std::abs(k - std::round(k)) < 1e-6 && std::round(k) >= 1.0, qPrintable(QString::number(k)));
    QCOMPARE(fb["k"].toInt(), static_cast<int>(std::round(k)));
    QVERIFY(fb["reselected"].isObject());
    const double speed = fb["reselected"].toObject()["q"].toObject()["speed_rpm"].toDouble();
    QVERIFY2(std::abs(speed - ns) <= 0.02 * ns || fb["speed_window"].toString() == "nearest grid speed",
             qPrintable(QString::number(speed)));
    QCOMPARE(r.json["recorded"].toArray().size(), 2);

    const mx::test::CliRun h = mx::test::runCli({"history", path, "--db", db});
    QVERIFY2(h.code == 0, qPrintable(h.err));
    QStringList sources;
    for (const auto& e : h.json["entries"].toArray()) sources << e.toObject()["source"].toString();
    QVERIFY2(sources.contains("feedback") && sources.contains("automatic"), qPrintable(sources.join(',')));

    // Without chatter the feedback is reported, nothing re-selected; without --db nothing is recorded.
    const mx::test::CliRun s = mx::test::runCli({"pareto", kParetoCase, "--feedback"});
    QVERIFY2(s.code == 0, qPrintable(s.err));
    QVERIFY(!s.json["feedback"].toObject()["chatter"].toBool());
    QVERIFY(s.json["feedback"].toObject()["reselected"].isNull());
    QVERIFY(!s.json.contains("recorded"));
  }

  // Unknown sections survive: the pareto section is preserved by the project loader (check passes).
  void projectChecks() {
    const mx::test::CliRun r = mx::test::runCli({"check", kParetoCase});
    QVERIFY2(r.code == 0, qPrintable(r.err));
  }

  // --db takes the shop's PostgreSQL server as well as a file: the point is recorded there.
  void recordsOnASharedServer() {
    mx::test::PostgresServer server;
    const QString why = server.start();
    QVERIFY2(why.isEmpty(), qPrintable("the PostgreSQL server did not start: " + why));
    QVERIFY(server.createDatabase("shop"));
    const mx::test::CliRun r = mx::test::runCli({"pareto", kParetoCase, "--db", server.url("shop")});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json["recorded"].toArray().size(), 1);
    const mx::test::CliRun h = mx::test::runCli({"history", kParetoCase, "--db", server.url("shop")});
    QVERIFY2(h.code == 0, qPrintable(h.err));
    const QJsonArray entries = h.json["entries"].toArray();
    QCOMPARE(entries.size(), 1);
    QCOMPARE(entries[0].toObject()["source"].toString(), QString("automatic"));
    QCOMPARE(entries[0].toObject()["q"].toObject()["speed_rpm"].toDouble(),
             r.json["q"].toObject()["speed_rpm"].toDouble());
  }
};

MX_REGISTER_TEST(TestCliPareto)
#include "test_command_pareto.moc"
