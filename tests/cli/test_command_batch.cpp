// millexpert-cli batch and batch-merge (docs/shop-scale.md): exit 2 with the field, value and range
// for a bad manifest (before any case runs), results equal to the single commands', resume after a
// torn last line, --jobs 2 equal to --jobs 1, and the merged table.
#include <QFile>
#include <QProcess>
#include <QSet>

#include "support/batch_manifests.h"
#include "support/cli_runner.h"
#include "test_registry.h"

namespace {

using mx::test::CliRun;

CliRun batch(const QString& manifest, const QString& out, const QStringList& extra = {}) {
  return mx::test::runCli(QStringList{"batch", manifest, "--out", out} + extra);
}

// The raw text of a line's "result": keys are sorted, so "tool" follows it.
QByteArray rawResult(const QByteArray& line) {
  const qsizetype from = line.indexOf("\"result\":") + 9;
  return line.mid(from, line.lastIndexOf(",\"tool\":") - from);
}

QByteArray lineOfCase(const QString& path, qint64 index) {
  for (const QString& line : mx::test::sortedLines(path))
    if (QJsonDocument::fromJson(line.toUtf8()).object()["case"].toInteger() == index) return line.toUtf8();
  return {};
}

// The Rubio project with the manifest's sections of one case written in, as a file of its own.
QString caseProject(const QTemporaryDir& dir, const QString& name, qsizetype machine, qsizetype material) {
  QJsonObject root = mx::test::readJson(dir.filePath("rubio.mxproj"));
  root["machine"] = mx::test::batchMachines()[machine];
  root["material"] = mx::test::batchMaterials()[material];
  root["operation"] = mx::test::batchOperations()[0];
  return mx::test::writeText(dir, name, QJsonDocument(root).toJson());
}

}  // namespace

class TestCliBatch : public QObject {
  Q_OBJECT
 private slots:
  void badManifests_data() {
    QTest::addColumn<QByteArray>("edit");  // a JSON object merged over lobesManifest()
    QTest::addColumn<QString>("message");
    QTest::newRow("computation") << QByteArray(R"({"computation":"volume"})")
                                 << "computation = 'volume': must be one of lobes, rank, pareto, point";
    QTest::newRow("unknown key") << QByteArray(R"({"machine":[]})") << "machine = an array: unknown key; allowed:";
    QTest::newRow("no projects") << QByteArray(R"({"projects":[]})")
                                 << "projects = an array: must hold 1 to 100000 non-empty strings, holds 0";
    QTest::newRow("empty project") << QByteArray(R"({"projects":[""]})")
                                   << "projects[0] = '': must be a non-empty string";
    QTest::newRow("missing project") << QByteArray(R"({"projects":["nope.mxproj"]})")
                                     << "nope.mxproj: project file not found";
    QTest::newRow("tool twice") << QByteArray(R"({"tools":["R1","R1"]})") << "tools[1] = 'R1': appears twice in tools";
    QTest::newRow("tool missing") << QByteArray(R"({"tools":["R1","T12"]})")
                                  << "tools: 'T12' is not a tool of projects[0] = 'rubio.mxproj'";
    QTest::newRow("machines not array") << QByteArray(R"({"machines":5})")
                                        << "machines = 5: must be an array of objects";
    QTest::newRow("machine power 0") << QByteArray(R"({"machines":[{"name":"A","spindle_power_W":0}]})")
                                     << "machines[0].spindle_power_W = 0: must be in (0, 1e+06]";
    QTest::newRow("machine unknown key") << QByteArray(R"({"machines":[{"spindle_power_W":1000,"max_rpm":5}]})")
                                         << "machines[0].max_rpm = 5: not a key of the project's machine section";
    QTest::newRow("material Kt") << QByteArray(R"({"materials":[{"name":"x","Kt_N_mm2":-1,"Kr":0.3}]})")
                                 << "materials[0].Kt_N_mm2 = -1: must be in (0, 1e+05]";
    QTest::newRow("immersion 1.5")
        << QByteArray(R"({"operations":[{"milling":"down","radial_immersion":1.5,"max_feed_per_tooth_mm":0.1}]})")
        << "operations[0].radial_immersion = 1.5: must be in (0, 1]";
    QTest::newRow("milling")
        << QByteArray(R"({"operations":[{"milling":"side","radial_immersion":0.5,"max_feed_per_tooth_mm":0.1}]})")
        << "operations[0].milling = \"side\": must be \"up\" or \"down\"";
    QTest::newRow("unknown option")
        << QByteArray(R"({"options":{"frm":4000}})")
        << "options.frm: not a flag of `millexpert-cli lobes`; its flags: tool, method, from";
    QTest::newRow("option with dashes") << QByteArray(R"({"options":{"max-depth":5}})")
                                        << "options.max-depth = 5: a flag name is written without dashes";
    QTest::newRow("tool option") << QByteArray(R"({"options":{"tool":"R1"}})")
                                 << "options.tool: each case sets it: list the tools in \"tools\"";
    QTest::newRow("option object") << QByteArray(R"({"options":{"from":{}}})")
                                   << "options.from = an object: must be a string, a number, true/false";
    QTest::newRow("option value") << QByteArray(R"({"computation":"rank","options":{"c":"1,1,1"}})")
                                  << "options: --c = [1, 1, 1]: weights must sum to 1 (within 1e-6), sum = 3";
    QTest::newRow("pareto db") << QByteArray(R"({"computation":"pareto","options":{"db":"x.db"}})")
                               << "options.db: a batch records into no learning database";
  }

  void badManifests() {
    QFETCH(QByteArray, edit);
    QFETCH(QString, message);
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject manifest = mx::test::lobesManifest();
    const QJsonObject changes = QJsonDocument::fromJson(edit).object();
    for (auto it = changes.begin(); it != changes.end(); ++it) manifest[it.key()] = it.value();
    const QString out = dir.filePath("out.jsonl");
    const CliRun r = batch(mx::test::writeManifest(dir, manifest), out);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));  // nothing ran
  }

  // 2 tools x 1000 machines x 1000 materials x 100 operations = 2e8 cases: refused before any is listed.
  void caseCountIsBounded() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject manifest = mx::test::lobesManifest();
    const auto repeated = [](const QJsonValue& item, int n) {
      QJsonArray out;
      for (int i = 0; i < n; ++i) out.append(item);
      return out;
    };
    manifest["machines"] = repeated(mx::test::batchMachines()[0], 1000);
    manifest["materials"] = repeated(mx::test::batchMaterials()[0], 1000);
    manifest["operations"] = repeated(mx::test::batchOperations()[0], 100);
    const CliRun r = batch(mx::test::writeManifest(dir, manifest), dir.filePath("out.jsonl"));
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("the manifest gives 2e+08 cases (projects x tools x machines x materials x operations): "
                            "at most 100000000"),
             qPrintable(r.err));
  }

  // The ranges' edges are accepted: the largest spindle power, full immersion, the smallest Kr.
  void edgeValuesAreAccepted() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject manifest = mx::test::lobesManifest();
    manifest["tools"] = QJsonArray{"R1"};
    manifest["machines"] = QJsonArray{QJsonObject{{"name", "Edge"}, {"spindle_power_W", 1e6}}};
    manifest["materials"] = QJsonArray{QJsonObject{{"name", "Edge"}, {"Kt_N_mm2", 1e5}, {"Kr", 0.0}}};
    manifest["operations"] =
        QJsonArray{QJsonObject{{"milling", "up"}, {"radial_immersion", 1.0}, {"max_feed_per_tooth_mm", 0.15}}};
    const CliRun r = batch(mx::test::writeManifest(dir, manifest), dir.filePath("out.jsonl"));
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json["cases"].toInt(), 1);
    const QJsonObject line = mx::test::jsonLines(dir.filePath("out.jsonl"))[0];
    QCOMPARE(line["machine"].toObject()["spindle_power_W"].toDouble(), 1e6);
    QCOMPARE(line["operation"].toObject()["radial_immersion"].toDouble(), 1.0);
  }

  // A Kubernetes Indexed Job's pod: JOB_COMPLETION_INDEX of --shard-count.
  void kubernetesIndex() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* slurm : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_COUNT"})
      env.remove(slurm);
    env.insert("JOB_COMPLETION_INDEX", "2");
    p.setProcessEnvironment(env);
    p.start(MX_CLI_PATH, {"batch", mx::test::writeManifest(dir, mx::test::lobesManifest()), "--out",
                          dir.filePath("out.jsonl"), "--shard-count", "3"});
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 0);
    const QJsonObject summary = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    QCOMPARE(summary["shard"].toObject()["source"].toString(), QString("Kubernetes"));
    QCOMPARE(summary["shard"].toObject()["index"].toInt(), 2);
    QList<qint64> cases;
    for (const QJsonObject& line : mx::test::jsonLines(dir.filePath("out.jsonl")))
      cases.append(line["case"].toInteger());
    QCOMPARE(cases, (QList<qint64>{2, 5}));
  }

  void badFlags_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("shard I = N") << QStringList{"--shard", "4/4"} << "--shard I = '4': must be an integer in [0, 3]";
    QTest::newRow("shard N = 0") << QStringList{"--shard", "0/0"}
                                 << "--shard N = '0': must be an integer in [1, 1000000]";
    QTest::newRow("shard text") << QStringList{"--shard", "1"} << "--shard = '1': must be I/N";
    QTest::newRow("jobs 0") << QStringList{"--jobs", "0"} << "--jobs = 0: must be an integer in [1, 256]";
    QTest::newRow("jobs 257") << QStringList{"--jobs", "257"} << "--jobs = 257: must be an integer in [1, 256]";
    QTest::newRow("shard-count alone") << QStringList{"--shard-count", "3"} << "JOB_COMPLETION_INDEX is not set";
  }

  void badFlags() {
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const CliRun r = batch(mx::test::writeManifest(dir, mx::test::lobesManifest()), dir.filePath("o.jsonl"), flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }

  // lobes case 5 (R2 on DMU-50 in 6061) and rank case 3 (Mini, 6061): "result" is byte for byte the
  // single command's output on a project holding the case's sections.
  void resultIsTheSingleCommandsOutput() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QString lobes_out = dir.filePath("lobes.jsonl");
    const CliRun lobes = batch(mx::test::writeManifest(dir, mx::test::lobesManifest()), lobes_out);
    QCOMPARE(lobes.code, 0);
    QCOMPARE(lobes.json["computed"].toInt(), 8);
    const CliRun single = mx::test::runCli({"lobes", caseProject(dir, "case5.mxproj", 0, 1), "--tool", "R2", "--from",
                                            "4000", "--to", "18000", "--step", "200"});
    QCOMPARE(single.code, 0);
    const QByteArray line = lineOfCase(lobes_out, 5);
    QCOMPARE(QJsonDocument::fromJson(line).object()["tool"].toString(), QString("R2"));
    QCOMPARE(rawResult(line), single.out.trimmed());

    QJsonObject manifest = mx::test::lobesManifest();
    manifest["computation"] = "rank";
    manifest["options"] = QJsonObject{{"no_simulation", true}, {"c", "0.2,0.7,0.1"}};
    const QString rank_out = dir.filePath("rank.jsonl");
    const CliRun rank = batch(mx::test::writeManifest(dir, manifest, "rank.json"), rank_out);
    QCOMPARE(rank.code, 0);
    QCOMPARE(rank.json["computed"].toInt(), 4);
    const CliRun single_rank =
        mx::test::runCli({"rank", caseProject(dir, "case3.mxproj", 1, 1), "--no-simulation", "--c", "0.2,0.7,0.1"});
    QCOMPARE(single_rank.code, 0);
    const QByteArray rank_line = lineOfCase(rank_out, 3);
    QCOMPARE(rawResult(rank_line), single_rank.out.trimmed());
    const QJsonObject parsed = QJsonDocument::fromJson(rank_line).object();
    QCOMPARE(parsed["tool"].toArray(), (QJsonArray{"R1", "R2"}));
    QCOMPARE(parsed["machine"].toObject()["name"].toString(), QString("Mini"));
    QCOMPARE(parsed["material"].toObject()["name"].toString(), QString("6061"));
    QCOMPARE(parsed["project"].toString(), QString("rubio.mxproj"));
  }

  // A killed job: the last line torn mid-way. The rerun cuts it off and redoes that case only.
  void resumeRedoesTheTornLine() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QString manifest = mx::test::writeManifest(dir, mx::test::lobesManifest());
    const QString out = dir.filePath("out.jsonl");
    QCOMPARE(batch(manifest, out).code, 0);
    const QStringList complete = mx::test::sortedLines(out);
    QCOMPARE(complete.size(), 8);
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadWrite));
    const QByteArray text = file.readAll();
    const qsizetype last_start = text.lastIndexOf('\n', text.size() - 2) + 1;
    const qint64 torn_case = QJsonDocument::fromJson(text.mid(last_start)).object()["case"].toInteger();
    QVERIFY(file.resize(last_start + (text.size() - last_start) / 2));  // half of the last line, no newline
    file.close();
    const CliRun again = batch(manifest, out);
    QCOMPARE(again.code, 0);
    QCOMPARE(again.json["skipped"].toInt(), 7);
    QCOMPARE(again.json["computed"].toInt(), 1);
    QCOMPARE(mx::test::sortedLines(out), complete);
    QCOMPARE(QJsonDocument::fromJson(mx::test::readBytes(out).split('\n').at(7)).object()["case"].toInteger(),
             torn_case);
    // A third run has nothing left to do.
    const CliRun third = batch(manifest, out);
    QCOMPARE(third.json["skipped"].toInt(), 8);
    QCOMPARE(third.json["computed"].toInt(), 0);
  }

  void aBadLineBeforeTheLastIsRefused() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QString out = mx::test::writeText(dir, "out.jsonl", "{\"hash\":\"a\"}\nnot json\n{\"hash\":\"b\"}\n");
    const CliRun r = batch(mx::test::writeManifest(dir, mx::test::lobesManifest()), out);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("out.jsonl:2: not a results line"), qPrintable(r.err));
  }

  void twoJobsWriteTheSameLines() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QString manifest = mx::test::writeManifest(dir, mx::test::lobesManifest());
    QCOMPARE(batch(manifest, dir.filePath("one.jsonl"), {"--jobs", "1"}).code, 0);
    const CliRun two = batch(manifest, dir.filePath("two.jsonl"), {"--jobs", "2"});
    QCOMPARE(two.code, 0);
    QCOMPARE(two.json["computed"].toInt(), 8);
    QCOMPARE(mx::test::sortedLines(dir.filePath("two.jsonl")), mx::test::sortedLines(dir.filePath("one.jsonl")));
  }

  // Shards 0/3, 1/3, 2/3 into one file: every case once, the same lines as one run.
  void shardsMakeUpTheWhole() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QString manifest = mx::test::writeManifest(dir, mx::test::lobesManifest());
    QCOMPARE(batch(manifest, dir.filePath("all.jsonl")).code, 0);
    QList<qint64> counts;
    for (int i = 0; i < 3; ++i) {
      const CliRun r = batch(manifest, dir.filePath("shards.jsonl"), {"--shard", QString("%1/3").arg(i)});
      QCOMPARE(r.code, 0);
      counts.append(r.json["computed"].toInteger());
    }
    QCOMPARE(counts, (QList<qint64>{3, 3, 2}));
    QCOMPARE(mx::test::sortedLines(dir.filePath("shards.jsonl")), mx::test::sortedLines(dir.filePath("all.jsonl")));
  }

  // A case that fails writes its error and the others still run; the batch exits 1.
  void aFailedCaseIsALine() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject manifest = mx::test::lobesManifest();
    manifest["options"] = QJsonObject{{"from", 4000}, {"to", 18000}, {"step", 200}, {"alpha", 2}};
    const QString out = dir.filePath("out.jsonl");
    const CliRun r = batch(mx::test::writeManifest(dir, manifest), out);
    QCOMPARE(r.code, 1);
    QCOMPARE(r.json["failed"].toInt(), 8);
    const std::vector<QJsonObject> lines = mx::test::jsonLines(out);
    QCOMPARE(lines.size(), std::size_t(8));
    const QJsonObject error = lines[0]["error"].toObject();
    QCOMPARE(error["exit_code"].toInt(), 2);
    QVERIFY2(error["message"].toString().contains("--alpha = 2"), qPrintable(error["message"].toString()));
    QVERIFY(lines[0]["result"].isNull());
  }

  // rank over 2 machines x 2 materials: one row each, the selected tool and q*; lobes: the best pocket of
  // each tool. Duplicate files count once.
  void mergeMakesTheTable() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject manifest = mx::test::lobesManifest();
    manifest["computation"] = "rank";
    manifest["options"] = QJsonObject{{"no_simulation", true}};
    const QString rank_out = dir.filePath("rank.jsonl");
    QCOMPARE(batch(mx::test::writeManifest(dir, manifest, "rank.json"), rank_out).code, 0);
    QFile::copy(rank_out, dir.filePath("rank-copy.jsonl"));
    const QString summary_path = dir.filePath("summary.json"), csv = dir.filePath("summary.csv");
    const CliRun merged = mx::test::runCli({"batch-merge", rank_out, dir.filePath("rank-copy.jsonl"), "--out",
                                            summary_path, "--csv", csv, "--html", dir.filePath("summary.html")});
    QCOMPARE(merged.code, 0);
    QCOMPARE(merged.json["cases"].toInt(), 4);
    QCOMPARE(merged.json["duplicates"].toInt(), 4);
    const QJsonObject summary = mx::test::readJson(summary_path);
    QCOMPARE(summary["computation"].toString(), QString("rank"));
    const QJsonArray rows = summary["rows"].toArray();
    QCOMPARE(rows.size(), 4);
    const QStringList expected_rows{"DMU-50/7075", "DMU-50/6061", "Mini/7075", "Mini/6061"};
    for (qsizetype i = 0; i < rows.size(); ++i) {
      const QJsonObject row = rows[i].toObject();
      QCOMPARE(row["machine"].toString() + "/" + row["material"].toString(), expected_rows[i]);
      const QJsonArray entries = row["entries"].toArray();
      QCOMPARE(entries.size(), 1);
      const QJsonObject entry = entries[0].toObject();
      const QJsonObject line = mx::test::jsonLines(rank_out)[static_cast<std::size_t>(i)];
      QCOMPARE(entry["tool"].toString(), line["result"].toObject()["selected"].toString());
      QCOMPARE(entry["q"].toObject(), line["result"].toObject()["q_star"].toObject());
    }
    // Rubio's R1 wins everywhere; the 745 W spindle caps the depth below the 15 kW one's.
    QCOMPARE(rows[0].toObject()["entries"].toArray()[0].toObject()["tool"].toString(), QString("R1"));
    const auto depth = [&](int i) {
      return rows[i].toObject()["entries"].toArray()[0].toObject()["q"].toObject()["depth_mm"].toDouble();
    };
    QVERIFY(depth(2) < depth(0));
    const QStringList csv_lines = mx::test::sortedLines(csv);
    QCOMPARE(csv_lines.size(), 5);  // header + one line per row
    QVERIFY(QFile::exists(dir.filePath("summary.html")));

    const QString lobes_out = dir.filePath("lobes.jsonl");
    QCOMPARE(batch(mx::test::writeManifest(dir, mx::test::lobesManifest()), lobes_out).code, 0);
    QCOMPARE(mx::test::runCli({"batch-merge", lobes_out, "--out", summary_path}).code, 0);
    const QJsonObject lobes = mx::test::readJson(summary_path);
    const QJsonArray lobe_rows = lobes["rows"].toArray();
    QCOMPARE(lobe_rows.size(), 4);
    const QJsonArray pockets = lobe_rows[0].toObject()["entries"].toArray();
    QCOMPARE(pockets.size(), 2);  // R1 and R2
    for (const auto& p : pockets) {
      const qint64 index = p.toObject()["case"].toInteger();
      const QJsonObject result = mx::test::jsonLines(lobes_out)[static_cast<std::size_t>(index)]["result"].toObject();
      double best = 0.0;
      for (const auto& b : result["blim_mm"].toArray()) best = std::max(best, b.toDouble());
      QCOMPARE(p.toObject()["pocket"].toObject()["blim_mm"].toDouble(), best);
    }
  }

  // A job still writing: its torn last line is left out of the table, the whole lines kept.
  void mergeLeavesOutATornLine() {
    QTemporaryDir dir;
    // moc reads raw strings poorly: the torn line's unbalanced brace stays in an ordinary literal.
    const QByteArray whole = R"({"case":0,"hash":"a","result":{"selected":"R1"},"project":"p"})";
    const QString path = mx::test::writeText(dir, "a.jsonl", whole + "\n{\"case\":1,\"hash\":\"b\",\"result\":{\"sel");
    const CliRun r = mx::test::runCli({"batch-merge", path, "--out", dir.filePath("s.json")});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["cases"].toInt(), 1);
    QVERIFY2(r.err.contains("torn line"), qPrintable(r.err));
    const QJsonObject summary = mx::test::readJson(dir.filePath("s.json"));
    QCOMPARE(summary["torn_lines"].toInt(), 1);
    QCOMPARE(summary["rows"].toArray()[0].toObject()["entries"].toArray()[0].toObject()["tool"].toString(),
             QString("R1"));
  }

  void conflictingResultsAreAnError() {
    QTemporaryDir dir;
    mx::test::writeText(dir, "a.jsonl",
                        R"({"case":0,"hash":"abc","result":{"selected":"R1"}})"
                        "\n");
    mx::test::writeText(dir, "b.jsonl",
                        R"({"case":0,"hash":"abc","result":{"selected":"R2"}})"
                        "\n");
    const CliRun r = mx::test::runCli(
        {"batch-merge", dir.filePath("a.jsonl"), dir.filePath("b.jsonl"), "--out", dir.filePath("s.json")});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("hash abc: different results in"), qPrintable(r.err));
    QVERIFY(!QFile::exists(dir.filePath("s.json")));
  }
};

MX_REGISTER_TEST(TestCliBatch)
#include "test_command_batch.moc"
