// A batch study as File > Batch study writes it (app/services/batch_study.h): the manifest read back as
// `batch` reads it, with one section per material and machine and the case count (tools x machines x
// materials for the per-tool computations, machines x materials for rank); the refusals, each before
// anything is written; and the machines of other project files, a file without one named.
#include <QFile>
#include <QTemporaryDir>

#include "document/project.h"
#include "services/batch_manifest.h"
#include "services/batch_study.h"
#include "services/service_errors.h"
#include "support/error_message.h"
#include "support/project_files.h"
#include "test_registry.h"

using mx::app::BatchStudyRequest;
using mx::app::InputError;
using mx::app::MachineSpec;
using mx::app::MaterialSpec;

namespace {

MachineSpec machine(const QString& name, double power_W) {
  MachineSpec m;
  m.name = name;
  m.spindle_power_W = power_W;
  return m;
}

const MachineSpec kMazak = [] {
  MachineSpec m = machine("Mazak VCN", 22000.0);
  m.max_spindle_rpm = 10000.0;
  return m;
}();
const MachineSpec kHermle = [] {
  MachineSpec m = machine("Hermle C42", 35000.0);
  m.max_torque_Nm = 200.0;
  return m;
}();
const MaterialSpec kSteel = [] {
  MaterialSpec m;
  m.name = "Steel C45";
  m.Kt_N_mm2 = 2100.0;
  m.Kr = 0.3;
  return m;
}();

BatchStudyRequest studyOf(const QString& computation, std::vector<MachineSpec> machines) {
  const mx::app::Project p = mx::app::loadProject(mx::test::kRubio);
  BatchStudyRequest r;
  r.computation = computation;
  r.tools = {"R1", "R2"};
  r.materials = {*p.material, kSteel};
  r.machines = std::move(machines);
  return r;
}

}  // namespace

class TestBatchStudy : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void cases_data() {
    QTest::addColumn<QString>("computation");
    QTest::addColumn<int>("machines");
    QTest::addColumn<qint64>("cases");
    QTest::newRow("lobes, the project's machine") << "lobes" << 0 << qint64{2 * 2};
    QTest::newRow("lobes, two machines") << "lobes" << 2 << qint64{2 * 2 * 2};
    QTest::newRow("rank, two machines") << "rank" << 2 << qint64{2 * 2};
    QTest::newRow("point, one machine") << "point" << 1 << qint64{2 * 2};
  }

  void cases() {
    QFETCH(QString, computation);
    QFETCH(int, machines);
    QFETCH(qint64, cases);
    std::vector<MachineSpec> listed{kMazak, kHermle};
    listed.resize(static_cast<std::size_t>(machines));
    const QString manifest = dir_.filePath(QString("%1-%2.json").arg(computation).arg(machines));
    const mx::app::BatchStudyFiles files =
        mx::app::writeBatchStudy(mx::app::loadProject(mx::test::kRubio), studyOf(computation, listed), manifest);
    QCOMPARE(files.cases, cases);
    QVERIFY(QFile::exists(files.project));
    const mx::app::BatchManifest m = mx::app::readBatchManifest(manifest);
    QCOMPARE(m.machines.size(), listed.size());
    for (std::size_t i = 0; i < listed.size(); ++i) {
      QCOMPARE(m.machines[i]["name"].toString(), *listed[i].name);
      QCOMPARE(m.machines[i]["spindle_power_W"].toDouble(), listed[i].spindle_power_W);
    }
    if (machines == 2) {
      QCOMPARE(m.machines[0]["max_spindle_rpm"].toDouble(), 10000.0);
      QCOMPARE(m.machines[1]["max_torque_Nm"].toDouble(), 200.0);
      QVERIFY(!m.machines[1].contains("max_spindle_rpm"));
    }
    QCOMPARE(m.materials.size(), std::size_t{2});
    QCOMPARE(m.materials[1]["Kt_N_mm2"].toDouble(), 2100.0);
  }

  void refused_data() {
    QTest::addColumn<QString>("what");
    QTest::addColumn<QString>("message");
    QTest::newRow("no tool") << "no tool"
                             << "no tool is checked";
    QTest::newRow("unknown tool") << "unknown tool"
                                  << "tool 'T99' is not in the project";
    QTest::newRow("no material") << "no material"
                                 << "no material is checked";
    QTest::newRow("machine without power") << "machine without power"
                                           << "machines[1].spindle_power_W = 0";
  }

  void refused() {
    QFETCH(QString, what);
    QFETCH(QString, message);
    BatchStudyRequest r = studyOf("lobes", {kMazak, kHermle});
    if (what == "no tool") r.tools.clear();
    if (what == "unknown tool") r.tools << "T99";
    if (what == "no material") r.materials.clear();
    if (what == "machine without power") r.machines[1].spindle_power_W = 0.0;
    const QString manifest = dir_.filePath("refused.json");
    const QString error = mx::test::messageOf<InputError>(
        [&] { mx::app::writeBatchStudy(mx::app::loadProject(mx::test::kRubio), r, manifest); });
    QVERIFY2(error.contains(message), qPrintable(error));
    QVERIFY(!QFile::exists(manifest));
    QVERIFY(!QFile::exists(dir_.filePath("refused.mxproj")));
  }

  void machinesOfProjectFiles() {
    mx::app::Project cell = mx::app::loadProject(mx::test::kRubio);
    cell.machine = kMazak;
    const QString with = dir_.filePath("cell-2.mxproj"), without = dir_.filePath("bare.mxproj");
    mx::app::saveProject(cell, with);
    cell.machine.reset();
    mx::app::saveProject(cell, without);
    const QString missing = dir_.filePath("missing.mxproj");
    QStringList problems;
    const std::vector<mx::app::MachineOfProject> read =
        mx::app::machinesOfProjects({without, with, missing, mx::test::kRubio}, &problems);
    QCOMPARE(read.size(), std::size_t{2});
    QCOMPARE(read[0].file, with);
    QCOMPARE(read[0].machine, kMazak);
    QCOMPARE(read[1].machine.spindle_power_W, 745.3);
    QCOMPARE(problems, (QStringList{without + ": no machine section", missing + ": project file not found"}));
  }
};

MX_REGISTER_TEST(TestBatchStudy)
#include "test_batch_study.moc"
