// The cases of a batch manifest (services/batch_cases.h): their order and count, their hashes, and
// shards that partition them.
#include <QSet>

#include "document/project.h"
#include "services/batch_cases.h"
#include "services/batch_shard.h"
#include "support/batch_manifests.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

struct Expanded {
  BatchManifest manifest;
  std::vector<Project> projects;
  BatchSections sections;
  std::vector<BatchCase> cases;
};

Expanded expand(const QTemporaryDir& dir, const QJsonObject& root) {
  Expanded e;
  e.manifest = batchManifestFromJson(root, dir.path());
  for (qsizetype i = 0; i < e.manifest.projects.size(); ++i)
    e.projects.push_back(loadProject(e.manifest.projectPath(i)));
  e.sections = readBatchSections(e.manifest);
  e.cases = expandBatchCases(e.manifest, e.projects);
  return e;
}

QStringList hashes(const Expanded& e) {
  QStringList out;
  for (const BatchCase& c : e.cases) {
    const Project p = batchCaseProject(e.manifest, e.sections, e.projects[static_cast<std::size_t>(c.project)], c);
    out.append(batchCaseHash(batchCaseInputs(e.manifest, c, p)));
  }
  return out;
}

// "project/tool/machine/material/operation" of each case, -1 for the project's own section.
QStringList labels(const Expanded& e) {
  QStringList out;
  for (const BatchCase& c : e.cases)
    out.append(QString("%1/%2/%3/%4/%5").arg(c.project).arg(c.tool).arg(c.machine).arg(c.material).arg(c.operation));
  return out;
}

}  // namespace

class TestBatchCases : public QObject {
  Q_OBJECT
 private slots:
  // Per-tool computations: projects, tools, machines, materials, operations, the last varying fastest.
  void perToolOrderAndCount() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir, "a.mxproj");
    mx::test::copyRubio(dir, "b.mxproj");
    QJsonObject root = mx::test::lobesManifest();
    root["projects"] = QJsonArray{"a.mxproj", "b.mxproj"};
    root["operations"] = QJsonArray{mx::test::batchOperations()[0], mx::test::batchOperations()[0]};
    const Expanded e = expand(dir, root);
    QCOMPARE(e.cases.size(), std::size_t(2 * 2 * 2 * 2 * 2));
    for (std::size_t i = 0; i < e.cases.size(); ++i) QCOMPARE(e.cases[i].index, qint64(i));
    const QStringList l = labels(e);
    QCOMPARE(l[0], QString("0/R1/0/0/0"));
    QCOMPARE(l[1], QString("0/R1/0/0/1"));
    QCOMPARE(l[2], QString("0/R1/0/1/0"));
    QCOMPARE(l[4], QString("0/R1/1/0/0"));
    QCOMPARE(l[8], QString("0/R2/0/0/0"));
    QCOMPARE(l[16], QString("1/R1/0/0/0"));
    QCOMPARE(l[31], QString("1/R2/1/1/1"));
  }

  // rank runs the case's tools together: no tool level; listed tools restrict and order them.
  void togetherComputationsAndListedTools() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    QJsonObject root = mx::test::lobesManifest();
    root["computation"] = "rank";
    root.remove("options");
    Expanded e = expand(dir, root);
    QCOMPARE(e.cases.size(), std::size_t(4));
    QCOMPARE(labels(e)[3], QString("0//1/1/0"));
    root["tools"] = QJsonArray{"R2"};
    e = expand(dir, root);
    const Project p = batchCaseProject(e.manifest, e.sections, e.projects[0], e.cases[0]);
    QCOMPARE(p.tools.size(), std::size_t(1));
    QCOMPARE(p.tools[0].id, QString("R2"));
    QCOMPARE(batchCaseTool(e.cases[0], p), QJsonValue(QJsonArray{"R2"}));
    // The project's own sections when the manifest lists none.
    root.remove("machines");
    root.remove("materials");
    root.remove("operations");
    e = expand(dir, root);
    QCOMPARE(e.cases.size(), std::size_t(1));
    QCOMPARE(labels(e)[0], QString("0//-1/-1/-1"));
  }

  // The machine's name becomes machine.name; each section replaces the project's own.
  void sectionsReplaceTheProjects() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const Expanded e = expand(dir, mx::test::lobesManifest());
    const Project p = batchCaseProject(e.manifest, e.sections, e.projects[0], e.cases[7]);  // R2, Mini, 6061
    QCOMPARE(p.machine->name.value_or(""), QString("Mini"));
    QCOMPARE(p.machine->spindle_power_W, 745.3);
    QVERIFY(!p.machine->max_spindle_rpm.has_value());
    QCOMPARE(p.material->name, QString("6061"));
    QCOMPARE(p.operation->milling, mx::MillingDirection::Down);
    QCOMPARE(*p.operation->radial_immersion, 0.5);
  }

  void hashesAreStable() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QStringList first = hashes(expand(dir, mx::test::lobesManifest()));
    QCOMPARE(first, hashes(expand(dir, mx::test::lobesManifest())));
    QCOMPARE(QSet<QString>(first.begin(), first.end()).size(), first.size());  // every case its own
    for (const QString& h : first) QVERIFY(QRegularExpression("^[0-9a-f]{64}$").match(h).hasMatch());
    // The manifest's key order does not matter: the same manifest written with its keys reversed.
    QByteArray reversed = "{";
    const QJsonObject root = mx::test::lobesManifest();
    for (qsizetype i = root.size() - 1; i >= 0; --i) {
      const QString key = root.keys()[i];
      const QJsonValue v = root.value(key);
      reversed += "\"" + key.toUtf8() + "\":" +
                  (v.isString()  ? "\"" + v.toString().toUtf8() + "\""
                   : v.isArray() ? QJsonDocument(v.toArray()).toJson(QJsonDocument::Compact)
                                 : QJsonDocument(v.toObject()).toJson(QJsonDocument::Compact));
      reversed += i > 0 ? "," : "}";
    }
    QVERIFY(reversed.startsWith("{\"projects\""));
    const BatchManifest again = readBatchManifest(mx::test::writeText(dir, "reversed.json", reversed));
    Expanded e = expand(dir, mx::test::lobesManifest());
    e.manifest = again;
    QCOMPARE(hashes(e), first);
  }

  void aChangedInputChangesTheHash() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const QStringList base = hashes(expand(dir, mx::test::lobesManifest()));
    QJsonObject root = mx::test::lobesManifest();
    root["options"] = QJsonObject{{"from", 4000}, {"to", 18000}, {"step", 100}};
    QStringList changed = hashes(expand(dir, root));
    for (qsizetype i = 0; i < base.size(); ++i) QVERIFY(changed[i] != base[i]);
    root = mx::test::lobesManifest();
    QJsonArray materials = mx::test::batchMaterials();
    QJsonObject m = materials[1].toObject();
    m["Kr"] = 0.31;
    materials[1] = m;
    root["materials"] = materials;
    changed = hashes(expand(dir, root));
    for (qsizetype i = 0; i < base.size(); ++i) QCOMPARE(changed[i] == base[i], i % 2 == 0);  // 6061: odd cases
  }

  void shardsPartitionTheCases() {
    QTemporaryDir dir;
    mx::test::copyRubio(dir);
    const Expanded e = expand(dir, mx::test::lobesManifest());
    for (qint64 n : {1, 3, 4, 8, 11}) {
      QSet<qint64> seen;
      qint64 owned = 0;
      for (qint64 i = 0; i < n; ++i) {
        const BatchShard shard = batchShardFrom(QString("%1/%2").arg(i).arg(n), std::nullopt, {});
        for (const BatchCase& c : e.cases)
          if (shard.owns(c.index)) {
            ++owned;
            seen.insert(c.index);
            QCOMPARE(c.index % n, i);
          }
      }
      QCOMPARE(owned, qint64(e.cases.size()));           // disjoint
      QCOMPARE(seen.size(), qsizetype(e.cases.size()));  // complete
    }
  }

  void shardFromTheScheduler() {
    QProcessEnvironment slurm;
    slurm.insert("SLURM_ARRAY_TASK_ID", "12");
    slurm.insert("SLURM_ARRAY_TASK_MIN", "10");
    slurm.insert("SLURM_ARRAY_TASK_COUNT", "4");
    BatchShard s = batchShardFrom(std::nullopt, std::nullopt, slurm);
    QCOMPARE(s.index, 2);
    QCOMPARE(s.count, 4);
    QCOMPARE(s.source, QString("Slurm"));
    s = batchShardFrom(QString("1/3"), std::nullopt, slurm);  // the flag wins
    QCOMPARE(s.index, 1);
    QCOMPARE(s.count, 3);
    QProcessEnvironment k8s;
    k8s.insert("JOB_COMPLETION_INDEX", "5");
    s = batchShardFrom(std::nullopt, 8, k8s);
    QCOMPARE(s.index, 5);
    QCOMPARE(s.count, 8);
    QCOMPARE(s.source, QString("Kubernetes"));
    s = batchShardFrom(std::nullopt, std::nullopt, {});
    QCOMPARE(s.count, 1);
  }
};

MX_REGISTER_TEST(TestBatchCases)
#include "test_batch_cases.moc"
