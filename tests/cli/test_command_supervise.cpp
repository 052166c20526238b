// millexpert-cli supervise on projects/landers-face-milling.mxproj, whose charts are rebuilt
// from the paper's rules: the fixed JSON keys; the paper's claims (the baseline violates the power limit
// and chatters; SMC I never chatters and holds power; SMC II detects chatter, re-plans to two 1 mm
// passes and holds power in steady state; SMC I overshoots less than SMC II); the operator's feed hold
// during the second pass; bad charts and flags exit 2 naming the element.
#include <QJsonArray>
#include <QTemporaryDir>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "test_registry.h"

namespace {
const QString kProject = QStringLiteral(MX_PROJECTS_DIR "/landers-face-milling.mxproj");

mx::test::CliRun supervise(const QString& controller) {
  return mx::test::runCli({"supervise", kProject, "--controller", controller}, 300000);
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
  void smc1OvershootsLessThanSmc2() {
    QVERIFY(runs_["smc1"]["overshoot_pct"].toDouble() < runs_["smc2"]["overshoot_pct"].toDouble());
  }
  // The appendix's search: 1 mm (SMC I's passes) stable, 2 mm (one pass) unstable.
  void marginalDepth() {
    const mx::test::CliRun r = mx::test::runCli({"supervise", kProject, "--marginal-depth"}, 300000);
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
        kProject, {R"(supervisor/charts/smc1/transitions/5={"id":6,"from":[4],"to":[4],"receptivity":"true"})"},
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
  }
  void badInput() {
    QFETCH(QStringList, mutations);
    QFETCH(QString, controller);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mx::test::writeMutatedProject(kProject, mutations, dir.filePath("p.mxproj"));
    const mx::test::CliRun r = mx::test::runCli({"supervise", path, "--controller", controller});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }

 private:
  QMap<QString, QJsonObject> runs_;
};

MX_REGISTER_TEST(TestCliSupervise)
#include "test_command_supervise.moc"
