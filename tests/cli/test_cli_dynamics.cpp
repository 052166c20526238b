// --dynamics modal|measured in lobes, point, rank and pareto: the tap-test FRF of a tool, written by the
// test from the tool's own modes, gives the lobes of those modes; delta > 0 and semi-discretization use
// the fitted modes and say so ("dynamics_used", stderr); a tool with only an FRF needs a fit for the
// simulation; every bad flag or file exits 2 naming it.
#include <sys/stat.h>

#include <QDir>

#include "document/project.h"
#include "frf/uff_writer.h"
#include "support/cli_runner.h"
#include "support/frf_samples.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {

// R1 of the 2006 tool-selection project with taps/R1.uff (x: dataset 0, y: dataset 1, accelerance,
// 0.25 Hz lines to 3 kHz) made from its modes; `keep_modes` false leaves R1 with the FRFs only.
QString tapProject(const QTemporaryDir& dir, bool keep_modes, double delta_per_s = 0.0) {
  Project p = loadProject(test::projectsPath("rubio2006-tool-selection.mxproj"));
  p.folder = dir.path();  // the FRF paths below are relative to the copy
  ToolSpec& r1 = p.tools[0];
  const MillingSetup modes = p.setupFor("R1");
  const auto f = test::evenFrequencies(0.0, 0.25, 12001);
  QDir(dir.path()).mkpath("taps");
  test::writeBytes(dir.filePath("taps/R1.uff").toStdString(),
                   uff58String({test::modalFrf(modes.modes_x, FrfQuantity::Accelerance, f, FrfDirection::X),
                                test::modalFrf(modes.modes_y, FrfQuantity::Accelerance, f, FrfDirection::Y)}));
  r1.frf_x = FrfRefSpec{"taps/R1.uff", std::nullopt, std::nullopt, {}};
  r1.frf_y = FrfRefSpec{"taps/R1.uff", 1, QString("accelerance"), {}};
  if (!keep_modes) r1.modes_x.clear(), r1.modes_y.clear();
  p.expert->delta_per_s = delta_per_s;
  QString path = dir.filePath("tap.mxproj");
  saveProject(p, path);
  return path;
}

QStringList lobes(const QString& project, const QStringList& extra) {
  return QStringList{"lobes", project, "--tool", "R1", "--from", "2000", "--to", "12000", "--step", "50"} + extra;
}

}  // namespace

class TestCliDynamics : public QObject {
  Q_OBJECT
 private slots:
  // The FRF of the modes, interpolated between 0.25 Hz lines, gives the modal lobes within 1 % at every
  // speed of the minima (the finest structure); the envelopes agree within 2 % everywhere.
  void measuredLobesMatchTheModes() {
    QTemporaryDir dir;
    const QString project = tapProject(dir, true);
    const test::CliRun modal = test::runCli(lobes(project, {"--dynamics", "modal"}));
    const test::CliRun measured = test::runCli(lobes(project, {"--dynamics", "measured"}));
    QCOMPARE(modal.code, 0);
    QCOMPARE(measured.code, 0);
    QCOMPARE(modal.json["dynamics_used"].toString(), QString("modal"));
    QCOMPARE(measured.json["dynamics_used"].toString(), QString("measured"));
    QVERIFY(measured.err.isEmpty());
    const QJsonArray a = modal.json["blim_mm"].toArray(), b = measured.json["blim_mm"].toArray();
    QCOMPARE(a.size(), b.size());
    double worst = 0.0;
    for (qsizetype i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(b[i].toDouble() / a[i].toDouble() - 1.0));
    qInfo("worst envelope difference measured vs modal: %.3f %%", 100.0 * worst);
    QCOMPARE_LE(worst, 0.02);
    const QJsonArray ma = modal.json["minima"].toArray(), mb = measured.json["minima"].toArray();
    QVERIFY(!ma.isEmpty());
    QCOMPARE(ma.size(), mb.size());
    for (qsizetype i = 0; i < ma.size(); ++i)
      QCOMPARE_LE(std::abs(mb[i]["blim_mm"].toDouble() / ma[i]["blim_mm"].toDouble() - 1.0), 0.01);
  }

  void defaultFollowsTheTool() {
    QTemporaryDir dir;
    const test::CliRun both = test::runCli(lobes(tapProject(dir, true), {}));
    QCOMPARE(both.json["dynamics_used"].toString(), QString("modal"));
    QTemporaryDir dir2;
    const test::CliRun frf_only = test::runCli(lobes(tapProject(dir2, false), {}));
    QCOMPARE(frf_only.code, 0);
    QCOMPARE(frf_only.json["dynamics_used"].toString(), QString("measured"));
  }

  void deltaAndSdmUseTheFittedModes_data() {
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<QString>("note");
    QTest::newRow("delta") << QStringList{"--delta", "0.05"} << "delta = 0.05 1/s > 0";
    QTest::newRow("sdm") << QStringList{"--method", "sdm", "--step", "500"}
                         << "semi-discretization needs a state-space model";
  }
  void deltaAndSdmUseTheFittedModes() {
    QFETCH(QStringList, extra);
    QFETCH(QString, note);
    QTemporaryDir dir;
    const test::CliRun r = test::runCli(lobes(tapProject(dir, true), QStringList{"--dynamics", "measured"} + extra));
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["dynamics_used"].toString(), QString("modal"));
    QVERIFY2(r.err.contains("note: tool 'R1'") && r.err.contains(note), qPrintable(r.err));
  }

  void pointRankAndPareto() {
    QTemporaryDir dir;
    const QString project = tapProject(dir, true);
    const test::CliRun point = test::runCli({"point", project, "--tool", "R1", "--speed", "5000", "--depth", "1",
                                             "--feed", "0.1", "--dynamics", "measured"});
    QCOMPARE(point.code, 0);
    QCOMPARE(point.json["dynamics_used"].toString(), QString("measured"));
    const test::CliRun rank = test::runCli({"rank", project, "--no-simulation", "--dynamics", "measured"});
    QCOMPARE(rank.code, 0);
    QCOMPARE(rank.json["dynamics_used"].toObject()["R1"].toString(), QString("measured"));
    QCOMPARE(rank.json["dynamics_used"].toObject()["R2"].toString(), QString("modal"));  // R2 has no tap test
    const test::CliRun pareto =
        test::runCli({"pareto", test::projectsPath("rubio-pareto-case.mxproj"), "--dynamics", "modal"});
    QCOMPARE(pareto.code, 0);
    QCOMPARE(pareto.json["dynamics_used"].toString(), QString("modal"));
  }

  // projects/tap-test-example.mxproj: lobes straight from its FRFs, and fits that give back the stated
  // modes of taps/T9-stated-modes.mxproj (1 % noise: f within 0.5 %, zeta 10 %, k 5 %).
  void theTapTestExample() {
    const QString example = test::projectsPath("tap-test-example.mxproj");
    const test::CliRun r = test::runCli({"lobes", example, "--tool", "T9"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["dynamics_used"].toString(), QString("measured"));
    QVERIFY(!r.json["minima"].toArray().isEmpty());
    const MillingSetup stated = loadProject(test::projectsPath("taps/T9-stated-modes.mxproj")).setupFor("T9");
    for (const auto& [file, modes] : {std::pair{"taps/T9-x.uff", stated.modes_x}, {"taps/T9-y.uff", stated.modes_y}}) {
      const test::CliRun fit = test::runCli({"frf-fit", test::projectsPath(file)});
      QCOMPARE(fit.code, 0);
      const QJsonArray got = fit.json["modes"].toArray();
      QCOMPARE(got.size(), static_cast<qsizetype>(modes.size()));
      for (qsizetype i = 0; i < got.size(); ++i) {
        const Mode& w = modes[static_cast<std::size_t>(i)];
        QCOMPARE_LE(std::abs(got[i]["freq_Hz"].toDouble() / w.natural_frequency_hz - 1.0), 0.005);
        QCOMPARE_LE(std::abs(got[i]["damping_pct"].toDouble() / (100.0 * w.damping_ratio) - 1.0), 0.10);
        QCOMPARE_LE(std::abs(got[i]["stiffness_N_per_um"].toDouble() / (1e-6 * w.stiffness_n_per_m) - 1.0), 0.05);
      }
    }
  }

  void badInputExitsTwo_data() {
    QTest::addColumn<bool>("keep_modes");
    QTest::addColumn<QStringList>("args");  // PROJECT is prepended after the subcommand
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("unknown dynamics") << true << QStringList{"lobes", "--tool", "R1", "--dynamics", "frf"}
                                      << QStringList{"--dynamics = 'frf': must be modal or measured"};
    QTest::newRow("measured without FRF") << true << QStringList{"lobes", "--tool", "R2", "--dynamics", "measured"}
                                          << QStringList{"tool 'R2'", "needs a tap-test FRF"};
    QTest::newRow("modal without modes") << false << QStringList{"lobes", "--tool", "R1", "--dynamics", "modal"}
                                         << QStringList{"tool 'R1'", "modes_x is empty", "frf-fit"};
    QTest::newRow("delta without modes") << false << QStringList{"point", "--tool", "R1",  "--speed", "5000", "--depth",
                                                                 "1",     "--feed", "0.1", "--delta", "0.1"}
                                         << QStringList{"tool 'R1'", "a margin delta > 0 needs fitted modes"};
    QTest::newRow("simulation without modes")
        << false << QStringList{"simulate", "--tool", "R1", "--speed", "5000", "--depth", "1", "--feed", "0.1"}
        << QStringList{"tool 'R1'", "the time-domain simulation needs fitted modes"};
    QTest::newRow("rank simulation without modes")
        << false << QStringList{"rank"} << QStringList{"tool 'R1'", "the time-domain refinement"};
    QTest::newRow("missing FRF file") << true << QStringList{"lobes", "--tool", "R1", "--dynamics", "measured"}
                                      << QStringList{"tool 'R1'", "frf_x.file = \"taps/R1.uff\"", "not found"};
    QTest::newRow("FRF file is a FIFO") << true << QStringList{"lobes", "--tool", "R1", "--dynamics", "measured"}
                                        << QStringList{"tool 'R1'", "R1.uff: a FIFO, not a regular file"};
    QTest::newRow("long tool id") << true << QStringList{"simulate", "--tool", QString(100000, 'x'),
                                                         "--speed",  "5000",   "--depth",
                                                         "1",        "--feed", "0.1"}
                                  << QStringList{"millexpert-cli: tool '" + QString(80, 'x') + QChar(0x2026) +
                                                 "' (100000 characters) not found; available: R1, R2\n"};
  }
  void badInputExitsTwo() {
    QFETCH(bool, keep_modes);
    QFETCH(QStringList, args);
    QFETCH(QStringList, expected);
    QTemporaryDir dir;
    const QString project = tapProject(dir, keep_modes);
    const QString tag = QTest::currentDataTag();
    if (tag == "missing FRF file" || tag == "FRF file is a FIFO") QFile::remove(dir.filePath("taps/R1.uff"));
    if (tag == "FRF file is a FIFO")
      QCOMPARE(::mkfifo(QFile::encodeName(dir.filePath("taps/R1.uff")).constData(), 0600), 0);
    args.insert(1, project);
    const test::CliRun r = test::runCli(args);
    QCOMPARE(r.code, 2);
    for (const QString& e : expected) QVERIFY2(r.err.contains(e), qPrintable(QString("'%1' not in: %2").arg(e, r.err)));
  }
};

MX_REGISTER_TEST(TestCliDynamics)
#include "test_cli_dynamics.moc"
