// millexpert-cli history: the fixed JSON interface (exact keys), newest first, the --tool filter,
// the project's material as the default filter, --add-json validation, the default database in the
// application-data folder, and exit 2 naming the file for a missing or corrupt --db.
#include <QJsonArray>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include "support/cli_runner.h"
#include "test_registry.h"

namespace {
const QString kRubio = QStringLiteral(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj");  // Aluminium; R1, R2

using Run = mx::test::CliRun;
Run cli(const QStringList& args) {
  return mx::test::runCli(args);
}

QString point(const QString& tool, const QString& time, const QString& source = "operator", double mrr = 1.5) {
  return QString(R"({"tool":"%1","time":"%2","source":"%3","weights":[0.25,0.25,0.25,0.25],)"
                 R"("q":{"speed_rpm":5800,"depth_mm":0.49,"feed_mm_per_tooth":0.27},)"
                 R"("objectives":{"tol":41.5,"mrr_cm3_s":%4,"surf":1.2,"ros":0.8}})")
      .arg(tool, time, source)
      .arg(mrr);
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
    QCOMPARE(keys(e), (QSet<QString>{"time", "tool", "material", "weights", "q", "objectives", "source"}));
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
};

MX_REGISTER_TEST(TestCliHistory)
#include "test_command_history.moc"
