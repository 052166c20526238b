// millexpert-cli history: the fixed JSON interface (exact keys), newest first, the --tool and
// --machine filters, the project's material as the default filter, --add-json validation, the default
// database in the application-data folder or the user's setting, exit 2 naming the file for a missing
// or corrupt --db; on a real PostgreSQL server: --db URL, --import of a machine's file (once per
// record), and the errors of a bad URL or an unreachable server.
#include <QDir>
#include <QJsonArray>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include "support/cli_runner.h"
#include "support/postgres_server.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {
using mx::test::kRubio;

using Run = mx::test::CliRun;
using mx::test::cli;

QString point(const QString& tool, const QString& time, const QString& source = "operator", double mrr = 1.5) {
  return QString(R"({"tool":"%1","time":"%2","source":"%3","weights":[0.25,0.25,0.25,0.25],)"
                 R"("q":{"speed_rpm":5800,"depth_mm":0.49,"feed_mm_per_tooth":0.27},)"
                 R"("objectives":{"tol":41.5,"mrr_cm3_s":%4,"surf":1.2,"ros":0.8}})")
      .arg(tool, time, source)
      .arg(mrr);
}

// The Rubio project with machine.name set: the records it writes name their machine.
QString projectOnMachine(const QTemporaryDir& dir, const QString& machine) {
  QFile in(kRubio);
  if (!in.open(QIODevice::ReadOnly)) return {};
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  QJsonObject m = root["machine"].toObject();
  m["name"] = machine;
  root["machine"] = m;
  QString path = dir.filePath(machine + ".mxproj");
  QFile out(path);
  if (!out.open(QIODevice::WriteOnly)) return {};
  out.write(QJsonDocument(root).toJson());
  return path;
}

// Runs the CLI with XDG_DATA_HOME and XDG_CONFIG_HOME in `home`.
mx::test::CliRun runInHome(const QTemporaryDir& home, const QStringList& args) {
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("XDG_DATA_HOME", home.filePath("data"));
  env.insert("XDG_CONFIG_HOME", home.filePath("config"));
  p.setProcessEnvironment(env);
  p.start(MX_CLI_PATH, args);
  p.waitForFinished(60000);
  mx::test::CliRun r;
  r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  r.out = p.readAllStandardOutput();
  r.json = QJsonDocument::fromJson(r.out).object();
  r.err = QString::fromUtf8(p.readAllStandardError());
  return r;
}

QSet<QString> keys(const QJsonObject& o) {
  const QStringList k = o.keys();
  return {k.begin(), k.end()};
}
}  // namespace

class TestCliHistory : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void entriesHaveTheFixedKeys() {
    const QString db = dir_.filePath("h.sqlite");
    QCOMPARE(cli({"history", kRubio, "--db", db, "--add-json", point("R1", "2024-05-01T08:00:00.000Z")}).code, 0);
    QCOMPARE(cli({"history", kRubio, "--db", db, "--add-json", point("R2", "2024-05-01T09:00:00.000Z", "rule")}).code,
             0);
    const Run r =
        cli({"history", kRubio, "--db", db, "--add-json", point("R1", "2024-05-01T10:00:00.000Z", "feedback", 2.5)});
    QCOMPARE(r.code, 0);
    QCOMPARE(keys(r.json), (QSet<QString>{"entries"}));
    const QJsonArray entries = r.json["entries"].toArray();
    QCOMPARE(entries.size(), 3);
    const QJsonObject e = entries[0].toObject();
    QCOMPARE(keys(e), (QSet<QString>{"time", "tool", "material", "machine", "weights", "q", "objectives", "source"}));
    QVERIFY(e["machine"].isNull());  // the project's machine has no name
    QCOMPARE(keys(e["q"].toObject()), (QSet<QString>{"speed_rpm", "depth_mm", "feed_mm_per_tooth"}));
    QCOMPARE(e["time"].toString(), QString("2024-05-01T10:00:00.000Z"));  // newest first
    QCOMPARE(e["tool"].toString(), QString("R1"));
    QCOMPARE(e["material"].toString(), QString("Aluminium"));
    QCOMPARE(e["source"].toString(), QString("feedback"));
    QCOMPARE(e["weights"].toArray().size(), 4);
    QCOMPARE(e["q"].toObject()["speed_rpm"].toDouble(), 5800.0);
    QCOMPARE(e["objectives"].toObject()["mrr_cm3_s"].toDouble(), 2.5);
    QCOMPARE(entries[1].toObject()["source"].toString(), QString("rule"));
    QCOMPARE(entries[2].toObject()["time"].toString(), QString("2024-05-01T08:00:00.000Z"));
  }

  void toolFilter() {
    const QString db = dir_.filePath("h.sqlite");  // filled by the previous slot
    const Run r1 = cli({"history", kRubio, "--db", db, "--tool", "R1"});
    QCOMPARE(r1.code, 0);
    const QJsonArray entries = r1.json["entries"].toArray();
    QCOMPARE(entries.size(), 2);
    for (const QJsonValue v : entries) QCOMPARE(v.toObject()["tool"].toString(), QString("R1"));
    QCOMPARE(cli({"history", kRubio, "--db", db, "--tool", "R2"}).json["entries"].toArray().size(), 1);
    QCOMPARE(cli({"history", kRubio, "--db", db, "--tool", "R9"}).json["entries"].toArray().size(), 0);
    QCOMPARE(cli({"history", kRubio, "--db", db, "--limit", "1"}).json["entries"].toArray().size(), 1);
  }

  void materialOfTheProjectFilters() {
    const QString db = dir_.filePath("h.sqlite");
    QFile in(kRubio);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
    QJsonObject material = root["material"].toObject();
    material["name"] = "Steel";
    root["material"] = material;
    const QString steel = dir_.filePath("steel.mxproj");
    QFile out(steel);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(root).toJson());
    out.close();
    QCOMPARE(cli({"history", steel, "--db", db}).json["entries"].toArray().size(), 0);
    QCOMPARE(cli({"history", steel, "--db", db, "--all-materials"}).json["entries"].toArray().size(), 3);
  }

  void missingOrCorruptDatabaseIsExit2() {
    const QString missing = dir_.filePath("missing.sqlite");
    const Run r = cli({"history", kRubio, "--db", missing});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(missing) && r.err.contains("no such file"), qPrintable(r.err));
    QVERIFY(!QFile::exists(missing));

    const QString corrupt = dir_.filePath("corrupt.sqlite");
    QFile f(corrupt);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(8192, '#'));
    f.close();
    const Run c = cli({"history", kRubio, "--db", corrupt});
    QCOMPARE(c.code, 2);
    QVERIFY2(c.err.contains(corrupt) && c.err.contains("not a database"), qPrintable(c.err));
  }

  void badRecordIsExit2() {
    const QString db = dir_.filePath("bad.sqlite");
    const Run source = cli({"history", kRubio, "--db", db, "--add-json", point("R1", "2024-05-01T08:00:00Z", "robot")});
    QCOMPARE(source.code, 2);
    QVERIFY2(source.err.contains("source 'robot'"), qPrintable(source.err));
    const Run tool = cli({"history", kRubio, "--db", db, "--add-json", point("R9", "2024-05-01T08:00:00Z")});
    QCOMPARE(tool.code, 2);
    QVERIFY2(tool.err.contains("tool 'R9'"), qPrintable(tool.err));
    QString offSimplex = point("R1", "2024-05-01T08:00:00Z");
    offSimplex.replace("[0.25,0.25,0.25,0.25]", "[0.5,0.5,0.5,0.5]");
    const Run weights = cli({"history", kRubio, "--db", db, "--add-json", offSimplex});
    QCOMPARE(weights.code, 2);
    QVERIFY2(weights.err.contains(db) && weights.err.contains("must sum to 1"), qPrintable(weights.err));
    QCOMPARE(cli({"history", kRubio, "--db", db, "--add-json", "{not json"}).code, 2);
  }

  void defaultDatabaseInAppData() {
    QTemporaryDir home;
    auto runWithHome = [&](const QStringList& args) {
      QProcess p;
      QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
      env.insert("XDG_DATA_HOME", home.path());
      p.setProcessEnvironment(env);
      p.start(MX_CLI_PATH, args);
      p.waitForFinished(60000);
      return std::make_pair(p.exitCode(), QJsonDocument::fromJson(p.readAllStandardOutput()).object());
    };
    const auto empty = runWithHome({"history", kRubio});  // no database yet: no entries, nothing created
    QCOMPARE(empty.first, 0);
    QCOMPARE(empty.second["entries"].toArray().size(), 0);
    const QString expected = home.filePath("MillExpert/MillExpert/learning.sqlite");
    QVERIFY(!QFile::exists(expected));
    QCOMPARE(runWithHome({"history", kRubio, "--add-json", point("R2", "2024-05-01T08:00:00Z")}).first, 0);
    QVERIFY(QFile::exists(expected));
    QCOMPARE(runWithHome({"history", kRubio}).second["entries"].toArray().size(), 1);
  }

  // The user's setting learning/database (what Settings > Learning database writes) is the default.
  void settingChoosesTheDatabase() {
    QTemporaryDir home;
    const QString chosen = home.filePath("shop.sqlite");
    QVERIFY(QDir().mkpath(home.filePath("config/MillExpert")));
    QFile conf(home.filePath("config/MillExpert/MillExpert.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write(QString("[learning]\ndatabase=%1\n").arg(chosen).toUtf8());
    conf.close();
    QCOMPARE(runInHome(home, {"history", kRubio, "--add-json", point("R1", "2024-05-01T08:00:00Z")}).code, 0);
    QVERIFY(QFile::exists(chosen));
    QVERIFY(!QFile::exists(home.filePath("data/MillExpert/MillExpert/learning.sqlite")));
    QCOMPARE(runInHome(home, {"history", kRubio}).json["entries"].toArray().size(), 1);
  }

  void machineFilter() {
    const QString db = dir_.filePath("machines.sqlite");
    const QString dmu = projectOnMachine(dir_, "DMU-50");
    const QString hermle = projectOnMachine(dir_, "HERMLE-C42");
    QCOMPARE(cli({"history", dmu, "--db", db, "--add-json", point("R1", "2024-05-01T08:00:00Z")}).code, 0);
    QCOMPARE(cli({"history", hermle, "--db", db, "--add-json", point("R1", "2024-05-01T09:00:00Z")}).code, 0);
    QCOMPARE(cli({"history", dmu, "--db", db, "--add-json", point("R2", "2024-05-01T10:00:00Z")}).code, 0);
    const Run all = cli({"history", dmu, "--db", db});
    QCOMPARE(all.json["entries"].toArray().size(), 3);
    QCOMPARE(all.json["entries"].toArray()[1].toObject()["machine"].toString(), QString("HERMLE-C42"));
    const QJsonArray mine = cli({"history", dmu, "--db", db, "--machine", "DMU-50"}).json["entries"].toArray();
    QCOMPARE(mine.size(), 2);
    for (const QJsonValue v : mine) QCOMPARE(v.toObject()["machine"].toString(), QString("DMU-50"));
  }

  void sharedServerAndImport() {
    mx::test::PostgresServer server;
    const QString why = server.start();
    QVERIFY2(why.isEmpty(), qPrintable("the PostgreSQL server did not start: " + why));
    QVERIFY(server.createDatabase("shop"));
    const QString url = server.url("shop");
    const QString dmu = projectOnMachine(dir_, "DMU-50");
    const Run added = cli({"history", dmu, "--db", url, "--add-json", point("R1", "2024-05-01T08:00:00Z")});
    QCOMPARE(added.code, 0);
    QCOMPARE(added.json["entries"].toArray().size(), 1);
    QCOMPARE(added.json["entries"].toArray()[0].toObject()["machine"].toString(), QString("DMU-50"));

    // A machine's own file joins the shop's server; importing it again copies nothing twice.
    const QString local = dir_.filePath("machine-local.sqlite");
    const QString hermle = projectOnMachine(dir_, "HERMLE-C42");
    for (int i = 0; i < 3; ++i)
      QCOMPARE(
          cli({"history", hermle, "--db", local, "--add-json", point("R2", QString("2024-05-02T0%1:00:00Z").arg(i))})
              .code,
          0);
    const Run first = cli({"history", dmu, "--db", url, "--import", local});
    QCOMPARE(first.code, 0);
    QCOMPARE(first.json["imported"].toObject()["records"].toInt(), 3);
    QCOMPARE(first.json["imported"].toObject()["new"].toInt(), 3);
    QCOMPARE(first.json["imported"].toObject()["from"].toString(), local);
    QCOMPARE(first.json["entries"].toArray().size(), 4);
    const Run again = cli({"history", dmu, "--db", url, "--import", local});
    QCOMPARE(again.json["imported"].toObject()["new"].toInt(), 0);
    QCOMPARE(again.json["entries"].toArray().size(), 4);
    QCOMPARE(cli({"history", dmu, "--db", url, "--machine", "HERMLE-C42"}).json["entries"].toArray().size(), 3);

    const Run password = cli({"history", dmu, "--db", "postgresql://postgres:hunter2@127.0.0.1/shop"});
    QCOMPARE(password.code, 2);
    QVERIFY2(password.err.contains("password is not accepted") && !password.err.contains("hunter2"),
             qPrintable(password.err));
    const QString closed = QString("postgresql://postgres@127.0.0.1:%1/shop").arg(mx::test::freeLoopbackPort());
    const Run refused = cli({"history", dmu, "--db", closed});
    QCOMPARE(refused.code, 2);
    QVERIFY2(refused.err.contains(closed) && refused.err.contains("cannot open"), qPrintable(refused.err));
  }
};

MX_REGISTER_TEST(TestCliHistory)
#include "test_command_history.moc"
