// library-import and library-export: the documented JSON keys, the append with renamed ids, --tools,
// the format told from the file, all-or-nothing (a bad library exits 2 and leaves the project's bytes
// as they were), and export -> import returning the same tools in every format.
#include <QDir>
#include <QFile>

#include "document/project.h"
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

using mx::test::writeText;

namespace {

using mx::test::kRubio;

QString copyOf(const QTemporaryDir& dir, const QString& source, const QString& name) {
  QString path = dir.filePath(name);
  QFile::copy(source, path);
  QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
  return path;
}

// A project with no tools, to import into.
QString emptyProject(const QTemporaryDir& dir) {
  app::Project p = app::loadProject(kRubio);
  p.tools.clear();
  p.expert.reset();
  QString path = dir.filePath("empty.mxproj");
  app::saveProject(p, path);
  return path;
}

const QByteArray kCsv =
    "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,damping_pct,stiffness_N_per_um\n"
    "R2,3,12,30,,,,x,900,2,5\n"
    "E16,4,16,30,,,,x,720,2.5,4.2\n";

}  // namespace

class TestCommandLibrary : public QObject {
  Q_OBJECT
 private slots:
  void importAppendsAndRenames() {
    QTemporaryDir dir;
    const QString project = copyOf(dir, kRubio, "p.mxproj");
    const QString csv = writeText(dir, "lib.csv", kCsv);
    const test::CliRun r = test::runCli({"library-import", csv, "--into", project});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.value("imported").toInt(), 2);
    QCOMPARE(r.json.value("tools").toArray(), QJsonArray({"R2-2", "E16"}));
    QCOMPARE(r.json.value("renamed").toArray(), QJsonArray({QJsonObject{{"from", "R2"}, {"to", "R2-2"}}}));
    QCOMPARE(r.json.value("skipped").toArray(), QJsonArray());
    const app::Project after = app::loadProject(project);
    QCOMPARE(after.tools.size(), std::size_t{4});
    QCOMPARE(after.tools[2].id, QString("R2-2"));
    QCOMPARE(after.tools[2].teeth, 3);
    QCOMPARE(after.tools[3].modes_x.at(0).freq_Hz, 720.0);
  }

  void toolsSelectsById() {
    QTemporaryDir dir;
    const QString project = emptyProject(dir);
    const QString csv = writeText(dir, "lib.csv", kCsv);
    const test::CliRun r = test::runCli({"library-import", csv, "--into", project, "--tools", "E16"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.value("tools").toArray(), QJsonArray({"E16"}));
    QCOMPARE(app::loadProject(project).tools.size(), std::size_t{1});
  }

  // A refused import exits 2, names the problem, and leaves the project's bytes as they were.
  void refusalLeavesTheProject_data() {
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<QByteArray>("library");
    QTest::addColumn<QString>("message");
    QTest::newRow("bad cell") << QStringList() << QByteArray(kCsv + "X,2,10,0,,,,x,-3,2,5\n")
                              << "lib.csv: line 4, column 9 (freq_Hz): '-3' must be in (0, 20000]";
    QTest::newRow("unknown id") << QStringList{"--tools", "E16,Q9"} << kCsv
                                << "lib.csv: tool 'Q9', --tools: the library has no tool of that id";
    QTest::newRow("empty id in --tools") << QStringList{"--tools", "E16,,R2"} << kCsv
                                         << "--tools = \"E16,,R2\": must be tool ids separated by commas";
    QTest::newRow("unknown format") << QStringList{"--format", "mastercam"} << kCsv
                                    << "--format = \"mastercam\": must be one of fusion, freecad, linuxcnc, csv, json";
    QTest::newRow("teeth 0") << QStringList{"--teeth", "0"} << kCsv << "--teeth";
    QTest::newRow("teeth 101") << QStringList{"--teeth", "101"} << kCsv << "--teeth";
  }
  void refusalLeavesTheProject() {
    QFETCH(QStringList, extra);
    QFETCH(QByteArray, library);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString project = copyOf(dir, kRubio, "p.mxproj");
    const QByteArray before = test::readBytes(project);
    const QString csv = writeText(dir, "lib.csv", library);
    const test::CliRun r = test::runCli(QStringList{"library-import", csv, "--into", project} + extra);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(test::readBytes(project), before);
  }

  // A project holds at most 100 tools: an import beyond them is refused whole.
  void importBeyondOneHundredToolsIsRefused() {
    QTemporaryDir dir;
    const QString project = copyOf(dir, kRubio, "p.mxproj");
    QByteArray csv =
        "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,damping_pct,"
        "stiffness_N_per_um\n";
    for (int i = 0; i < 99; ++i) csv += QString("T%1,2,10,0,,,,x,1000,2,5\n").arg(i).toUtf8();
    const QByteArray before = test::readBytes(project);
    const test::CliRun r = test::runCli({"library-import", writeText(dir, "big.csv", csv), "--into", project});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("the imported tools do not fit the project: tools has 101 tools: at most 100 are allowed"),
             qPrintable(r.err));
    QCOMPARE(test::readBytes(project), before);
  }

  void formatIsToldFromTheFile() {
    QTemporaryDir dir;
    const QString project = emptyProject(dir);
    // A MillExpert JSON library named .lib: its content says what it is.
    const QString json = writeText(dir, "tools.lib", test::readBytes(kRubio));
    const test::CliRun r = test::runCli({"library-import", json, "--into", project});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.value("tools").toArray(), QJsonArray({"R1", "R2"}));
    const test::CliRun unknown = test::runCli({"library-import", writeText(dir, "x.txt", "hello"), "--into", project});
    QCOMPARE(unknown.code, 2);
    QVERIFY2(unknown.err.contains("x.txt: cannot tell the library's format"), qPrintable(unknown.err));
  }

  // export -> import gives the project's tools back, in every format that carries MillExpert's data.
  void exportImportRoundTrip_data() {
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("csv") << "csv"
                         << "lib.csv";
    QTest::newRow("json") << "json"
                          << "lib.json";
  }
  void exportImportRoundTrip() {
    QFETCH(QString, format);
    QFETCH(QString, name);
    QTemporaryDir dir;
    const QString out = dir.filePath(name);
    const test::CliRun exported = test::runCli({"library-export", kRubio, "--out", out, "--format", format});
    QVERIFY2(exported.code == 0, qPrintable(exported.err));
    QCOMPARE(exported.json.value("exported").toInt(), 2);
    QCOMPARE(exported.json.value("format").toString(), format);
    QCOMPARE(exported.json.value("files").toArray().at(0).toString(), out);
    const QString project = emptyProject(dir);
    const test::CliRun imported = test::runCli({"library-import", out, "--into", project, "--format", format});
    QVERIFY2(imported.code == 0, qPrintable(imported.err));
    QCOMPARE(app::loadProject(project).tools, app::loadProject(kRubio).tools);
  }

  // Through a CAM format the tools keep their dynamics and cutting data (in the format's free field or
  // the side file); the format adds its type and record, and may number the ids. A second round trip
  // through the same format changes nothing.
  void camFormatsCarryTheDynamics_data() {
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("out");
    QTest::addColumn<QString>("library");  // what library-import reads, relative to the folder
    QTest::newRow("fusion .tools") << "fusion"
                                   << "lib.tools"
                                   << "lib.tools";
    QTest::newRow("fusion .json") << "fusion"
                                  << "lib.json"
                                  << "lib.json";
    QTest::newRow("freecad") << "freecad"
                             << "shop"
                             << "shop/Library/shop.fctl";
    QTest::newRow("freecad, the exported folder") << "freecad"
                                                  << "shop"
                                                  << "shop";
    QTest::newRow("linuxcnc") << "linuxcnc"
                              << "tool.tbl"
                              << "tool.tbl";
  }
  void camFormatsCarryTheDynamics() {
    QFETCH(QString, format);
    QFETCH(QString, out);
    QFETCH(QString, library);
    QTemporaryDir dir;
    const auto roundTrip = [&](const QString& source, const QString& folder) {
      QDir(dir.path()).mkpath(folder);
      const test::CliRun exported =
          test::runCli({"library-export", source, "--out", dir.filePath(folder + "/" + out), "--format", format});
      if (exported.code != 0) qWarning("%s", qPrintable(exported.err));
      const QString project = dir.filePath(folder + "/into.mxproj");
      app::Project empty = app::loadProject(kRubio);
      empty.tools.clear();
      empty.expert.reset();
      app::saveProject(empty, project);
      const test::CliRun imported =
          test::runCli({"library-import", dir.filePath(folder + "/" + library), "--into", project});
      if (imported.code != 0) qWarning("%s", qPrintable(imported.err));
      return app::loadProject(project);
    };
    const app::Project first = roundTrip(kRubio, "a");
    const std::vector<app::ToolSpec>& original = app::loadProject(kRubio).tools;
    QCOMPARE(first.tools.size(), original.size());
    for (std::size_t i = 0; i < original.size(); ++i) {
      app::ToolSpec back = first.tools[i];
      QCOMPARE(back.origin->format, format);
      back.id = original[i].id;
      back.type.reset();
      back.origin.reset();
      QCOMPARE(back, original[i]);
    }
    const app::Project second = roundTrip(dir.filePath("a/into.mxproj"), "b");
    QCOMPARE(second.tools, first.tools);
  }

  void exportNeverReplacesTheProject() {
    QTemporaryDir dir;
    const QString project = copyOf(dir, kRubio, "p.mxproj");
    const QByteArray before = test::readBytes(project);
    const test::CliRun r = test::runCli({"library-export", project, "--out", project, "--format", "json"});
    QCOMPARE(r.code, 2);
    QCOMPARE(test::readBytes(project), before);
  }

  void exportFormatFromTheName() {
    QTemporaryDir dir;
    const test::CliRun r = test::runCli({"library-export", kRubio, "--out", dir.filePath("lib.xyz")});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("cannot tell the format from the name"), qPrintable(r.err));
  }
};

MX_REGISTER_TEST(TestCommandLibrary)
#include "test_command_library.moc"
