// millexpert-cli supervise on projects/landers-face-milling.mxproj, whose charts are rebuilt
// from the paper's rules: the fixed JSON keys; the paper's claims (the baseline violates the power limit
// and chatters; SMC I never chatters and holds power; SMC II detects chatter, re-plans to two 1 mm
// passes and holds power in steady state; SMC I overshoots at most half as much as SMC II); module L's
// settings and force transients; the operator's feed hold during the second pass; bad charts and flags
// exit 2 naming the element.
#include <QJsonArray>
#include <QTemporaryDir>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "test_registry.h"

namespace {
const QString kFaceMilling = QStringLiteral(MX_PROJECTS_DIR "/landers-face-milling.mxproj");

mx::test::CliRun supervise(const QString& controller) {
  return mx::test::runCli({"supervise", kFaceMilling, "--controller", controller}, 300000);
}

bool hasEvent(const QJsonObject& r, const QString& type) {
  for (const auto& e : r["events"].toArray())
    if (e.toObject()["type"].toString() == type) return true;
  return false;
}
}  // namespace

class TestCliSupervise : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    for (const char* c : {"none", "smc1", "smc2"}) {
      const mx::test::CliRun r = supervise(c);
      QCOMPARE(r.code, 0);
      runs_.insert(c, r.json);
    }
  }
  void fixedKeys() {
    for (const QJsonObject& r : runs_)
      for (const char* key : {"controller", "max_power_pct_of_limit", "overshoot_pct", "chatter_detected",
                              "chatter_time_s", "passes", "cycle_time_s", "events"})
        QVERIFY2(r.contains(key), key);
  }
  void baselineViolatesPowerAndChatters() {
    const QJsonObject r = runs_["none"];
    QVERIFY(r["max_power_pct_of_limit"].toDouble() > 150.0);  // paper: "as much as 224 %"
    QVERIFY(r["chatter_detected"].toBool());
    QCOMPARE(r["passes"].toInt(), 1);
  }
  void smc1NeverChattersAndHoldsPower() {
    const QJsonObject r = runs_["smc1"];
    QVERIFY(!r["chatter_detected"].toBool());
    QVERIFY(r["chatter_time_s"].isNull());
    QVERIFY(r["max_power_pct_of_limit"].toDouble() <= 100.0);
    QCOMPARE(r["passes"].toInt(), 2);
    QVERIFY(hasEvent(r, "operator"));  // the feed hold of the second pass
  }
  void smc2DetectsChatterAndReplans() {
    const QJsonObject r = runs_["smc2"];
    QVERIFY(r["chatter_detected"].toBool());
    QVERIFY(r["chatter_time_s"].toDouble() > 0.0);
    QVERIFY(hasEvent(r, "replan"));
    QCOMPARE(r["final_program_mm"].toArray(), (QJsonArray{1.0, 1.0}));
    QCOMPARE(r["passes"].toInt(), 2);
    QVERIFY(r["steady_max_power_pct_of_limit"].toDouble() <= 110.0);
  }
  // Paper: 28 % (SMC I) against 113 % (SMC II).
  void smc1OvershootsAtMostHalfOfSmc2() {
    QVERIFY(2.0 * runs_["smc1"]["overshoot_pct"].toDouble() <= runs_["smc2"]["overshoot_pct"].toDouble());
  }
  // Module L restarts at each contact: the pass entries and the re-contact after the operator's hold.
  void modelControllerAndTransients() {
    const QJsonObject r = runs_["smc1"];
    QCOMPARE(r["model_controller"].toObject(), (QJsonObject{{"time_constant_ms", 200.0}, {"reset_feed", "model"}}));
    const QJsonArray transients = r["force_transients"].toArray();
    QCOMPARE(transients.size(), 3);
    double peak = 0.0;
    for (const auto& t : transients) {
      const QJsonObject o = t.toObject();
      QVERIFY(o.contains("settling_s"));
      QVERIFY(o["t_s"].toDouble() > 0.0);
      peak = std::max(peak, o["overshoot_pct"].toDouble());
    }
    QCOMPARE(peak, r["overshoot_pct"].toDouble());
    QVERIFY(transients[0].toObject()["settling_s"].toDouble() > 0.0);
  }
  // The bumpless restart takes over at the programmed 10 mm/s, above the model's 7.6 mm/s for F_ref:
  // the re-contact after the hold overshoots more than with the model's feed.
  void bumplessRestartOvershootsMore() {
    const mx::test::CliRun r = mx::test::runCli(
        {"supervise", kFaceMilling, "--controller", "smc1", "--reset-feed", "current", "--time-constant-ms", "400"},
        300000);
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["model_controller"].toObject(),
             (QJsonObject{{"time_constant_ms", 400.0}, {"reset_feed", "current"}}));
    QVERIFY(r.json["overshoot_pct"].toDouble() > runs_["smc1"]["overshoot_pct"].toDouble() + 5.0);
  }
  // The appendix's search: 1 mm (SMC I's passes) stable, 2 mm (one pass) unstable.
  void marginalDepth() {
    const mx::test::CliRun r = mx::test::runCli({"supervise", kFaceMilling, "--marginal-depth"}, 300000);
    QCOMPARE(r.code, 0);
    QVERIFY(r.json["bracketed"].toBool());
    const double d = r.json["marginal_depth_mm"].toDouble();
    QVERIFY(d > 1.0 && d < 2.0);
    QVERIFY(r.json["stable_depth_mm"].toDouble() < r.json["unstable_depth_mm"].toDouble());
    QCOMPARE_LE(r.json["unstable_depth_mm"].toDouble() - r.json["stable_depth_mm"].toDouble(), 0.02 + 1e-9);
  }
  // A chart that never stabilises (a self-loop that is always fireable) is reported, once per
  // episode, and the run still ends.
  void unstableChartIsReported() {
    QTemporaryDir dir;
    const QString path = mx::test::writeMutatedProject(
        kFaceMilling, {R"(supervisor/charts/smc1/transitions/5={"id":6,"from":[4],"to":[4],"receptivity":"true"})"},
        dir.filePath("p.mxproj"));
    const mx::test::CliRun r = mx::test::runCli({"supervise", path, "--controller", "smc1"}, 300000);
    QCOMPARE(r.code, 0);
    int unstable = 0;
    for (const auto& e : r.json["events"].toArray()) unstable += e.toObject()["type"].toString() == "logic_unstable";
    QVERIFY(unstable >= 1);
    QVERIFY(unstable <= 10);
  }
  void badInput_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QString>("controller");
    QTest::addColumn<QString>("message");
    QTest::newRow("controller") << QStringList{} << "pid"
                                << "--controller = 'pid': must be one of none, smc1, smc2";
    QTest::newRow("receptivity") << QStringList{"supervisor/charts/smc1/transitions/2/receptivity=\"(b and\""} << "smc1"
                                 << "supervisor.charts.smc1.transitions[2].receptivity";
    QTest::newRow("unknown signal") << QStringList{"supervisor/charts/smc1/transitions/2/receptivity=\"z\""} << "smc1"
                                    << "supervisor.charts.smc1.transitions[2]";
    QTest::newRow("no target") << QStringList{"supervisor/charts/smc2/transitions/8/to=[]"} << "smc2"
                               << "supervisor.charts.smc2.transitions[8]";
    QTest::newRow("event type") << QStringList{"supervisor/events/0/type=\"lunch\""} << "smc1"
                                << "supervisor.events[0].type = 'lunch'";
    QTest::newRow("no section") << QStringList{"-supervisor"} << "none"
                                << "section 'supervisor' is missing";
    QTest::newRow("pass depth") << QStringList{"supervisor/passes_mm/smc1/0=50"} << "smc1"
                                << "supervisor.passes_mm.smc1[0] = 50: must be a depth in (0, 20] mm";
    QTest::newRow("time constant") << QStringList{"supervisor/model_controller/time_constant_ms=0.5"} << "smc1"
                                   << "supervisor.model_controller.time_constant_ms = 0.5";
    QTest::newRow("reset feed") << QStringList{"supervisor/model_controller/reset_feed=\"warm\""} << "smc1"
                                << "supervisor.model_controller.reset_feed = 'warm'";
  }
  void badFlags_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("time constant 0") << QStringList{"--time-constant-ms", "0"} << "--time-constant-ms";
    QTest::newRow("time constant text") << QStringList{"--time-constant-ms", "fast"} << "--time-constant-ms";
    QTest::newRow("reset feed") << QStringList{"--reset-feed", "warm"}
                                << "--reset-feed = warm: must be current or model";
  }
  void badFlags() {
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"supervise", kFaceMilling, "--controller", "smc1"} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }
  void badInput() {
    QFETCH(QStringList, mutations);
    QFETCH(QString, controller);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mx::test::writeMutatedProject(kFaceMilling, mutations, dir.filePath("p.mxproj"));
    const mx::test::CliRun r = mx::test::runCli({"supervise", path, "--controller", controller});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }

 private:
  QMap<QString, QJsonObject> runs_;
};

MX_REGISTER_TEST(TestCliSupervise)
#include "test_command_supervise.moc"
