// frf-export: a tool's modes written as UFF 58, 58b or CSV read back through frf-info and frf-fit as the
// same modes; the measured FRF re-exported in another format and quantity; the seeded noise repeats;
// bad flags and axes exit 2.
#include <QDir>
#include <QProcess>

#include "document/project.h"
#include "frf/frf_file.h"
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

namespace {

using mx::test::kRubio;

QStringList exportArgs(const QString& output, const QStringList& extra) {
  return QStringList{"frf-export", kRubio, "--tool", "R1", "--output", output} + extra;
}

}  // namespace

class TestCommandFrfExport : public QObject {
  Q_OBJECT
 private slots:
  // R1: x 603 Hz, 3.9 %, 5.59 N/um; y 666 Hz, 3.5 %, 5.715 N/um (the 2006 paper).
  void modesRoundTrip_data() {
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("quantity");
    QTest::newRow("uff58 receptance") << "uff58"
                                      << "receptance";
    QTest::newRow("uff58b accelerance") << "uff58b"
                                        << "accelerance";
    QTest::newRow("uff58 mobility") << "uff58"
                                    << "mobility";
  }
  void modesRoundTrip() {
    QFETCH(QString, format);
    QFETCH(QString, quantity);
    QTemporaryDir dir;
    const QString out = dir.filePath("R1.uff");
    const test::CliRun r = test::runCli(exportArgs(out, {"--format", format, "--quantity", quantity}));
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["format"].toString(), format);
    const QJsonArray written = r.json["datasets"].toArray();
    QCOMPARE(written.size(), 2);
    QCOMPARE(written[0]["direction"].toString(), QString("x"));
    QCOMPARE(written[1]["direction"].toString(), QString("y"));
    QCOMPARE(written[0]["points"].toInt(), 1301);  // x: 0 .. 1300 Hz (2 x 603 rounded up), 1 Hz
    QCOMPARE(written[0]["to_Hz"].toDouble(), 1300.0);
    QCOMPARE(written[1]["to_Hz"].toDouble(), 1400.0);  // y: 2 x 666 rounded up
    const test::CliRun info = test::runCli({"frf-info", out});
    QCOMPARE(info.json["format"].toString(), format);
    QCOMPARE(info.json["datasets"].toArray().at(1)["quantity"].toString(), quantity);
    const struct {
      int dataset;
      double f, zeta_pct, k;
    } want[] = {{0, 603.0, 3.9, 5.59}, {1, 666.0, 3.5, 5.715}};
    for (const auto& w : want) {
      const test::CliRun fit = test::runCli({"frf-fit", out, "--dataset", QString::number(w.dataset), "--modes", "1"});
      QCOMPARE(fit.code, 0);
      const QJsonObject m = fit.json["modes"].toArray()[0].toObject();
      QCOMPARE_LE(std::abs(m["freq_Hz"].toDouble() / w.f - 1.0), 1e-6);
      QCOMPARE_LE(std::abs(m["damping_pct"].toDouble() / w.zeta_pct - 1.0), 1e-5);
      QCOMPARE_LE(std::abs(m["stiffness_N_per_um"].toDouble() / w.k - 1.0), 1e-5);
    }
  }

  void gridAndNoiseFlags() {
    QTemporaryDir dir;
    const QString a = dir.filePath("a.csv"), b = dir.filePath("b.csv"), c = dir.filePath("c.csv");
    const QStringList flags{"--axis", "y",      "--format", "csv",         "--from", "100",    "--to",
                            "1000",   "--step", "0.5",      "--noise-pct", "2",      "--seed", "5"};
    QCOMPARE(test::runCli(exportArgs(a, flags)).code, 0);
    QCOMPARE(test::runCli(exportArgs(b, flags)).code, 0);
    QCOMPARE(test::runCli(exportArgs(c, QStringList(flags.mid(0, 12)) << "--seed"
                                                                      << "6"))
                 .code,
             0);
    QCOMPARE(test::readBytes(a), test::readBytes(b));  // the seed repeats the noise
    QVERIFY(test::readBytes(a) != test::readBytes(c));
    const FrfFile f = readFrfFile(a.toStdString(), FrfQuantity::Receptance);
    QCOMPARE(f.datasets.at(0).frequency_hz.size(), std::size_t{1801});
    QCOMPARE(f.datasets.at(0).frequency_hz.front(), 100.0);
  }

  void measuredReexport() {
    QTemporaryDir dir;
    const QString first = dir.filePath("R1.uff");
    QCOMPARE(test::runCli(exportArgs(first, {"--format", "uff58b"})).code, 0);
    app::Project p = app::loadProject(kRubio);
    p.folder = dir.path();
    p.tools[0].frf_x = app::FrfRefSpec{"R1.uff", 0, std::nullopt, {}};
    p.tools[0].frf_y = app::FrfRefSpec{"R1.uff", 1, std::nullopt, {}};
    const QString project = dir.filePath("tap.mxproj");
    app::saveProject(p, project);
    const QString csv = dir.filePath("R1-x.csv");
    const test::CliRun r = test::runCli({"frf-export", project, "--tool", "R1", "--source", "measured", "--axis", "x",
                                         "--format", "csv", "--output", csv});
    QCOMPARE(r.code, 0);
    const FrfFile back = readFrfFile(csv.toStdString(), FrfQuantity::Receptance);
    const FrfFile original = readFrfFile(first.toStdString(), std::nullopt);
    QCOMPARE(back.datasets.at(0).frequency_hz, original.datasets.at(0).frequency_hz);
    for (std::size_t i = 0; i < back.datasets[0].values.size(); i += 97) {
      const auto want = original.datasets[0].values[i];
      QCOMPARE_LE(std::abs(back.datasets[0].values[i] - want), 1e-11 * std::abs(want));
    }
  }

  // The example's tap-test files are what our writer makes from the stated modes, byte for byte.
  void theExampleFilesAreOurs() {
    QTemporaryDir dir;
    QProcess script;
    script.start("bash",
                 {QString(MX_PROJECTS_DIR) + "/../packaging/make-tap-test-example.sh", MX_CLI_PATH, dir.path()});
    QVERIFY(script.waitForFinished(120000));
    QCOMPARE(script.exitCode(), 0);
    for (const char* name : {"T9-x.uff", "T9-y.uff"})
      QVERIFY2(test::readBytes(dir.filePath(name)) == test::readBytes(test::projectsPath(QString("taps/") + name)),
               name);
    const FrfFile y = readFrfFile(test::projectsPath("taps/T9-y.uff").toStdString(), std::nullopt);
    QCOMPARE(y.format, FrfFormat::Uff58b);
    QCOMPARE(y.datasets.at(0).quantity, FrfQuantity::Accelerance);
    QCOMPARE(y.datasets.at(0).response_direction, FrfDirection::Y);
  }

  void badInputExitsTwo_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("expected");
    QTest::newRow("format") << QStringList{"--format", "unv"} << "--format = \"unv\": must be uff58, uff58b or csv";
    QTest::newRow("axis") << QStringList{"--axis", "z"} << "--axis = \"z\": must be x, y or xy";
    QTest::newRow("quantity") << QStringList{"--quantity", "force"} << "--quantity = \"force\"";
    QTest::newRow("source") << QStringList{"--source", "fit"} << "--source = \"fit\": must be modes or measured";
    QTest::newRow("csv with two axes") << QStringList{"--format", "csv"} << "a CSV holds one FRF";
    QTest::newRow("to below from") << QStringList{"--from", "500", "--to", "100"} << "--to = 100: must be > --from";
    QTest::newRow("noise") << QStringList{"--noise-pct", "-1"} << "--noise-pct";
    QTest::newRow("no FRF") << QStringList{"--source", "measured"} << "frf_x is not given";
    QTest::newRow("tool") << QStringList{"--tool", "R9"} << "R9";
  }
  void badInputExitsTwo() {
    QFETCH(QStringList, flags);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString out = dir.filePath("out.uff");
    const test::CliRun r = test::runCli(exportArgs(out, flags));
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
  }
};

MX_REGISTER_TEST(TestCommandFrfExport)
#include "test_command_frf_export.moc"
