// frf-info and frf-fit on files the test writes with the engine's own writers from known modes: the
// datasets listed with their directions, quantities and ranges; the fitted modes back within 0.1 % on
// exact data; every bad file or flag exits 2 with a message that names it.
#include "frf/frf_csv.h"
#include "frf/uff_writer.h"
#include "support/cli_runner.h"
#include "support/frf_samples.h"
#include "support/hostile_files.h"
#include "test_registry.h"

using namespace mx;

namespace {

const ModalAxis kModesX{{620.0, 0.03, 6e6}, {1450.0, 0.04, 2.5e7}};
const ModalAxis kModesY{{880.0, 0.025, 9e6}};

QString writeFile(const QTemporaryDir& dir, const QString& name, const std::string& bytes) {
  QString path = dir.filePath(name);
  test::writeBytes(path.toStdString(), bytes);
  return path;
}

// x as receptance, y as accelerance, 0.5 Hz lines from 0 to 3 kHz, in one ASCII universal file.
std::string tapTestFile() {
  const std::vector<double> f = test::evenFrequencies(0.0, 0.5, 6001);
  FrfDataset x = test::modalFrf(kModesX, FrfQuantity::Receptance, f, FrfDirection::X);
  FrfDataset y = test::modalFrf(kModesY, FrfQuantity::Accelerance, f, FrfDirection::Y);
  return uff58String({x, y});
}

void checkModes(const QJsonArray& got, const ModalAxis& want) {
  QCOMPARE(got.size(), static_cast<qsizetype>(want.size()));
  for (qsizetype i = 0; i < got.size(); ++i) {
    const QJsonObject m = got[i].toObject();
    const Mode& w = want[static_cast<std::size_t>(i)];
    QVERIFY2(std::abs(m["freq_Hz"].toDouble() / w.natural_frequency_hz - 1.0) < 1e-3, qPrintable(QString::number(i)));
    QVERIFY(std::abs(m["damping_pct"].toDouble() / (w.damping_ratio * 100.0) - 1.0) < 1e-3);
    QVERIFY(std::abs(m["stiffness_N_per_um"].toDouble() / (w.stiffness_n_per_m * 1e-6) - 1.0) < 1e-3);
  }
}

}  // namespace

class TestCommandFrf : public QObject {
  Q_OBJECT
 private slots:
  void infoListsTheDatasets() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "T9.unv", tapTestFile());
    const test::CliRun r = test::runCli({"frf-info", path});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["format"].toString(), QString("uff58"));
    const QJsonArray d = r.json["datasets"].toArray();
    QCOMPARE(d.size(), 2);
    QCOMPARE(d[0].toObject()["index"].toInt(), 0);
    QCOMPARE(d[0].toObject()["response_direction"].toString(), QString("x"));
    QCOMPARE(d[0].toObject()["reference_direction"].toString(), QString("x"));
    QCOMPARE(d[0].toObject()["quantity"].toString(), QString("receptance"));
    QCOMPARE(d[0].toObject()["points"].toInt(), 6001);
    QCOMPARE(d[0].toObject()["from_Hz"].toDouble(), 0.0);
    QCOMPARE(d[0].toObject()["to_Hz"].toDouble(), 3000.0);
    QCOMPARE(d[1].toObject()["index"].toInt(), 1);
    QCOMPARE(d[1].toObject()["response_direction"].toString(), QString("y"));
    QCOMPARE(d[1].toObject()["quantity"].toString(), QString("accelerance"));
    QCOMPARE(r.json["skipped_datasets"].toInt(), 0);
  }

  void infoReadsCsvWithItsQuantity() {
    QTemporaryDir dir;
    const std::vector<double> f = test::evenFrequencies(10.0, 1.0, 2000);
    const QString path = writeFile(dir, "T9-x.csv", frfCsvString(test::modalFrf(kModesX, FrfQuantity::Mobility, f)));
    const test::CliRun r = test::runCli({"frf-info", path, "--quantity", "mobility"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["format"].toString(), QString("csv"));
    QCOMPARE(r.json["datasets"].toArray()[0].toObject()["quantity"].toString(), QString("mobility"));
    QCOMPARE(r.json["datasets"].toArray()[0].toObject()["points"].toInt(), 2000);
  }

  void fitRecoversTheModesOfEachDirection() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "T9.unv", tapTestFile());
    const test::CliRun x = test::runCli({"frf-fit", path, "--from", "300", "--to", "2500"});
    QCOMPARE(x.code, 0);
    checkModes(x.json["modes"].toArray(), kModesX);
    QVERIFY(x.json["fit_error_pct"].toDouble() < 0.1);
    QCOMPARE(x.json["response_direction"].toString(), QString("x"));
    // The accelerance of y becomes receptance before the fit.
    const test::CliRun y = test::runCli({"frf-fit", path, "--dataset", "1", "--from", "300", "--to", "2500"});
    QCOMPARE(y.code, 0);
    checkModes(y.json["modes"].toArray(), kModesY);
  }

  void fitKeepsTheRequestedNumberOfModes() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "T9.unv", tapTestFile());
    const test::CliRun r = test::runCli({"frf-fit", path, "--modes", "1", "--from", "300", "--to", "2500"});
    QCOMPARE(r.code, 0);
    const QJsonArray modes = r.json["modes"].toArray();
    QCOMPARE(modes.size(), 1);
    // The more significant mode: the one with the larger peak, 1 / (2 zeta k).
    QVERIFY(std::abs(modes[0].toObject()["freq_Hz"].toDouble() / 620.0 - 1.0) < 1e-3);
  }

  void peakPickingIsNamed() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "T9.unv", tapTestFile());
    const test::CliRun r =
        test::runCli({"frf-fit", path, "--dataset", "1", "--method", "peak", "--from", "300", "--to", "2500"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.json["method"].toString().contains("peak"));
    const QJsonArray modes = r.json["modes"].toArray();
    QCOMPARE(modes.size(), 1);
    QVERIFY(std::abs(modes[0].toObject()["freq_Hz"].toDouble() / 880.0 - 1.0) < 5e-3);
  }

  void badInputExitsTwoAndNamesIt_data() {
    QTest::addColumn<QString>("file");  // "uff", "csv", "truncated" or "missing"
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("csv without quantity") << "csv" << QStringList{"frf-info"} << "quantity";
    QTest::newRow("unknown quantity") << "uff" << QStringList{"frf-info", "--quantity", "force"} << "--quantity";
    QTest::newRow("quantity disagrees") << "uff" << QStringList{"frf-info", "--quantity", "mobility"}
                                        << "quantity = mobility";
    QTest::newRow("dataset out of range") << "uff" << QStringList{"frf-fit", "--dataset", "2"} << "dataset = 2";
    QTest::newRow("unknown method") << "uff" << QStringList{"frf-fit", "--method", "rfp"} << "--method";
    QTest::newRow("band reversed") << "uff" << QStringList{"frf-fit", "--from", "2000", "--to", "1000"} << "to_hz";
    QTest::newRow("too many modes") << "uff" << QStringList{"frf-fit", "--modes", "41"} << "--modes";
    QTest::newRow("truncated file") << "truncated" << QStringList{"frf-info"} << "line";
    QTest::newRow("missing file") << "missing" << QStringList{"frf-fit"} << "nothere.unv";
  }
  void badInputExitsTwoAndNamesIt() {
    QFETCH(QString, file);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QString path;
    if (file == "uff") path = writeFile(dir, "T9.unv", tapTestFile());
    if (file == "truncated") {
      const std::string text = tapTestFile();
      path = writeFile(dir, "T9.unv", text.substr(0, text.size() / 3));
    }
    if (file == "csv")
      path = writeFile(
          dir, "T9.csv",
          frfCsvString(test::modalFrf(kModesX, FrfQuantity::Receptance, test::evenFrequencies(10.0, 1.0, 100))));
    if (file == "missing") path = dir.filePath("nothere.unv");
    QStringList args = flags;
    args.insert(1, path);
    const test::CliRun r = test::runCli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
  }

  // A tap-test file is refused before it is read when it is not a regular file or over 64 MB.
  void unreadableFiles_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("/dev/zero") << "/dev/zero"
                               << "a character device, not a regular file: an FRF file must be a regular file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: an FRF file must be a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file: an FRF file must be a regular file";
    QTest::newRow("64 MB + 1 byte") << QString("bytes:%1").arg(64 * test::kMB + 1)
                                    << "64.0 MB (67108865 bytes) is over the 64 MB limit of an FRF file";
  }
  void unreadableFiles() {
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = test::hostileInput(dir, kind);
    QVERIFY(!path.isEmpty());
    for (const char* command : {"frf-info", "frf-fit"}) {
      const test::CliRun r = test::runCli({command, path, "--quantity", "receptance"}, 20000);
      QCOMPARE(r.code, 2);
      QVERIFY2(r.err.contains(path + ": " + expected), qPrintable(r.err));
    }
  }
};

MX_REGISTER_TEST(TestCommandFrf)
#include "test_command_frf.moc"
