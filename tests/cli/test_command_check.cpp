// millexpert-cli check PROJECT: exit 0 and a JSON summary for a valid project; exit 2 and a message
// naming the field path on stderr for every validation rule, a malformed or missing file, or a bad
// subcommand.
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QTemporaryDir>

#include "support/cli_runner.h"
#include "support/hostile_files.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {

using mx::test::CliRun;
using mx::test::fixturePath;
using mx::test::mutated;
using mx::test::readJson;
using mx::test::runCli;

}  // namespace

class TestCliCheck : public QObject {
  Q_OBJECT

 private slots:
  void validProjects_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("tools");
    QTest::newRow("rubio") << QString(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj")
                           << "Rubio, De la Sen & Ibeas (2006): tool selection R1 / R2" << QStringList{"R1", "R2"};
    QTest::newRow("insperger") << QString(MX_PROJECTS_DIR "/benchmark-insperger-1dof.mxproj")
                               << "Insperger & Stepan single-mode benchmark" << QStringList{"FULL", "LOW"};
    QTest::newRow("valid-full") << fixturePath("valid-full.mxproj")
                                << "Test fixture: every field, including the optional ones" << QStringList{"T1", "T2"};
    QTest::newRow("unknown-keys") << fixturePath("unknown-keys.mxproj")
                                  << "Test fixture: keys this version does not know" << QStringList{"R1"};
  }

  void validProjects() {
    QFETCH(QString, path);
    QFETCH(QString, name);
    QFETCH(QStringList, tools);
    const CliRun run = runCli({"check", path});
    QVERIFY2(run.code == 0, qPrintable(run.err));
    QVERIFY(run.err.isEmpty());
    QJsonParseError error;
    const QJsonDocument out = QJsonDocument::fromJson(run.out, &error);
    QVERIFY2(error.error == QJsonParseError::NoError, run.out.constData());
    QCOMPARE(out["valid"].toBool(), true);
    QCOMPARE(out["name"].toString(), name);
    QCOMPARE(out["tools"].toArray().toVariantList(), QVariant(tools).toList());
  }

  // The stored operating point is part of the summary; a project without one has no key.
  void reportsTheStoredPoint() {
    const CliRun run = runCli({"check", fixturePath("valid-full.mxproj")});
    QCOMPARE(run.code, 0);
    const QJsonObject point = QJsonDocument::fromJson(run.out)["operating_point"].toObject();
    QCOMPARE(point, (QJsonObject{{"tool", "T1"}, {"speed_rpm", 8000}, {"depth_mm", 1.5}, {"feed_mm_per_tooth", 0.1}}));
    const CliRun plain = runCli({"check", MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj"});
    QCOMPARE(plain.code, 0);
    QVERIFY(!QJsonDocument::fromJson(plain.out).object().contains("operating_point"));
  }

  // One row per validation rule; each invalid file is written to a temporary directory.
  void invalidProjects_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QString>("expected");
    auto row = [](const char* name, const QStringList& mutations, const char* expected) {
      QTest::newRow(name) << mutations << QString(expected);
    };
    row("format", {"format=\"other\""}, "format = \"other\": must be \"millexpert-project\"");
    row("version newer", {"version=2"}, "version = 2: the file was written by a newer MillExpert");
    row("name missing", {"-name"}, "name: missing (required string)");
    row("section type", {"machine=[]"}, "machine: expected an object, got array");
    row("missing field", {"-material/Kt_N_mm2"}, "material.Kt_N_mm2: missing (required number > 0)");
    row("wrong type", {"tools/0/diameter_mm=\"16\""}, "tools[0].diameter_mm: expected a number, got string");
    row("teeth < 1", {"tools/0/teeth=0"}, "tools[0].teeth = 0: must be an integer in [1, 100]");
    row("teeth a million", {"tools/0/teeth=1000000"}, "tools[0].teeth = 1e+06: must be an integer in [1, 100]");
    row("teeth non-integer", {"tools/1/teeth=1.5"}, "tools[1].teeth = 1.5: must be an integer in [1, 100]");
    row("diameter <= 0", {"tools/1/diameter_mm=-10"}, "tools[1].diameter_mm = -10: must be in (0, 1000]");
    row("tool radial depth > D", {"tools/1/radial_depth_mm=10.5"},
        "tools[1].radial_depth_mm = 10.5: must be in (0, 10]");
    row("operation radial depth > D", {"-operation/radial_immersion", "operation/radial_depth_mm=17"},
        "operation.radial_depth_mm = 17: must be in (0, 16]");
    row("immersion > 1", {"operation/radial_immersion=1.01"}, "operation.radial_immersion = 1.01: must be in (0, 1]");
    row("immersion and depth", {"operation/radial_depth_mm=3"},
        "operation: radial_immersion = 0.5 and radial_depth_mm = 3");
    row("no engagement", {"-operation/radial_immersion"}, "operation.radial_immersion: missing");
    row("milling", {"operation/milling=\"climb\""}, "operation.milling = \"climb\": must be \"up\" or \"down\"");
    row("damping > 100", {"tools/1/modes_x/0/damping_pct=150"},
        "tools[1].modes_x[0].damping_pct = 150: must be in [0.001, 100)");
    row("damping 0", {"tools/0/modes_y/0/damping_pct=0"},
        "tools[0].modes_y[0].damping_pct = 0: must be in [0.001, 100)");
    row("stiffness <= 0", {"tools/0/modes_x/1/stiffness_N_per_um=0"},
        "tools[0].modes_x[1].stiffness_N_per_um = 0: must be in [0.001, 1e+06]");
    row("frequency <= 0", {"tools/0/modes_y/0/freq_Hz=-1"}, "tools[0].modes_y[0].freq_Hz = -1: must be in (0, 20000]");
    row("duplicate ids", {"tools/1/id=\"T1\""}, "tools[1].id = \"T1\": duplicate of tools[0].id");
    row("point of another tool", {"operating_point/tool=\"T3\""},
        "operating_point.tool = \"T3\": must be the id of a tool of the project");
    row("point speed 0", {"operating_point/speed_rpm=0"}, "operating_point.speed_rpm = 0: must be in (0, 1e+05]");
    row("power <= 0", {"machine/spindle_power_W=0"}, "machine.spindle_power_W = 0: must be in (0, 1e+06]");
    row("max rpm <= 0", {"machine/max_spindle_rpm=-100"}, "machine.max_spindle_rpm = -100: must be in (0, 1e+05]");
    row("max feed <= 0", {"machine/max_feed_mm_s=0"}, "machine.max_feed_mm_s = 0: must be in (0, 1e+05]");
    row("Kt <= 0", {"material/Kt_N_mm2=0"}, "material.Kt_N_mm2 = 0: must be in (0, 1e+05]");
    row("Kr < 0", {"material/Kr=-0.3"}, "material.Kr = -0.3: must be in [0, 10]");
    row("tool Kt <= 0", {"tools/1/Kt_N_mm2=-800"}, "tools[1].Kt_N_mm2 = -800: must be in (0, 1e+05]");
    row("feed per tooth <= 0", {"operation/max_feed_per_tooth_mm=0"},
        "operation.max_feed_per_tooth_mm = 0: must be in (0, 10]");
    row("delta < 0", {"expert/delta_per_s=-1"}, "expert.delta_per_s = -1: must be in [0, 10000]");
    row("alpha > 1", {"expert/alpha=1.5"}, "expert.alpha = 1.5: must be in (0, 1]");
    row("alpha 0", {"expert/alpha=0"}, "expert.alpha = 0: must be in (0, 1]");
    row("weights length", {"expert/ct=[1]"}, "expert.ct = [1]: must be an array of 2 numbers >= 0, got 1");
    row("weights negative", {"expert/c/2=-0.5"}, "expert.c[2] = -0.5: must be >= 0");
    row("grid from >= to", {"expert/grid/speed_from_rpm=30000"},
        "expert.grid.speed_to_rpm = 20000: must be > expert.grid.speed_from_rpm = 30000");
    row("grid divisions", {"expert/grid/depth_divisions=0"},
        "expert.grid.depth_divisions = 0: must be an integer >= 1");
    row("grid step", {"expert/grid/feed_step_mm=0"}, "expert.grid.feed_step_mm = 0: must be in [1e-04, 10]");
  }

  void invalidProjects() {
    QFETCH(QStringList, mutations);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("invalid.mxproj");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QJsonDocument(mutated(readJson(fixturePath("valid-full.mxproj")), mutations)).toJson());
    f.close();
    const CliRun run = runCli({"check", path});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QVERIFY2(run.err.contains(path + ": " + expected), qPrintable(run.err));
  }

  void malformedFiles_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected");
    QTest::newRow("NaN literal") << "invalid-nan.mxproj"
                                 << "invalid JSON at line 5, column 50 (offset 154): illegal number";
    QTest::newRow("1e999 overflow") << "invalid-overflow.mxproj"
                                    << "invalid JSON at line 5, column 40";
    QTest::newRow("trailing comma") << "invalid-syntax.mxproj"
                                    << "invalid JSON at line 5, column 2";
  }

  void malformedFiles() {
    QFETCH(QString, file);
    QFETCH(QString, expected);
    const CliRun run = runCli({"check", fixturePath(file)});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(fixturePath(file) + ": " + expected), qPrintable(run.err));
  }

  // Refused before a byte is read (a device never ends, a FIFO blocks, 64 MB is the limit), in well
  // under the time that reading them would take; a file at the limit is read (and is no JSON).
  void unreadableFiles_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("/dev/zero") << "/dev/zero"
                               << "a character device, not a regular file: a project file must be a regular file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: a project file must be a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file: a project file must be a regular file";
    QTest::newRow("64 MB + 1 byte") << QString("bytes:%1").arg(64 * mx::test::kMB + 1)
                                    << "64.0 MB (67108865 bytes) is over the 64 MB limit of a project file";
    QTest::newRow("80 MB") << QString("bytes:%1").arg(80 * mx::test::kMB)
                           << "80.0 MB (83886080 bytes) is over the 64 MB limit of a project file";
    QTest::newRow("64 MB is read") << QString("bytes:%1").arg(64 * mx::test::kMB)
                                   << "invalid JSON at line 1, column 2 (offset 1): illegal value";
  }

  void unreadableFiles() {
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = mx::test::hostileInput(dir, kind);
    QVERIFY(!path.isEmpty());
    QElapsedTimer clock;
    clock.start();
    const CliRun run = runCli({"check", path}, 20000);
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(path + ": " + expected), qPrintable(run.err));
    QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
  }

  // A 10 MB tool id is echoed as its first 80 characters and its length.
  void longValuesAreShortened() {
    QTemporaryDir dir;
    const QString path = dir.filePath("long-id.mxproj");
    const QString id(10 * 1024 * 1024, 'a');
    mx::test::writeMutatedProject(fixturePath("valid-full.mxproj"),
                                  {QString("tools/0/id=\"%1\"").arg(id), QString("tools/1/id=\"%1\"").arg(id)}, path);
    const CliRun run = runCli({"check", path});
    QCOMPARE(run.code, 2);
    const QString echoed =
        "tools[1].id = \"" + QString(80, 'a') + QChar(0x2026) + "\" (10485760 characters): duplicate of tools[0].id";
    QVERIFY2(run.err.contains(echoed), qPrintable(run.err.left(1000)));
    QVERIFY2(run.err.size() < 1000, qPrintable(QString::number(run.err.size())));
  }

  void missingFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("absent.mxproj");
    const CliRun run = runCli({"check", path});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(path), qPrintable(run.err));
    QVERIFY2(run.err.contains("not found"), qPrintable(run.err));
  }

  void badCommandLines() {
    CliRun run = runCli({"frobnicate", fixturePath("valid-full.mxproj")});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains("unknown command 'frobnicate'"), qPrintable(run.err));
    run = runCli({"check"});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains("PROJECT"), qPrintable(run.err));
    run = runCli({"check", "--no-such-flag", fixturePath("valid-full.mxproj")});
    QCOMPARE(run.code, 2);
  }
};

MX_REGISTER_TEST(TestCliCheck)
#include "test_command_check.moc"
