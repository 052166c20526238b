// The tap-test service: quantity names, the choice of one FRF dataset (0-based among the file's FRFs),
// the UFF quantity check, and the fit's default band (the measured range above 0 Hz).
#include "frf/uff_writer.h"
#include "services/frf_import.h"
#include "services/service_errors.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
const ModalAxis kMode{{700.0, 0.03, 8e6}};

QString writeUff(const QTemporaryDir& dir, FrfQuantity quantity) {
  QString path = dir.filePath("tap.unv");
  const std::string text =
      uff58String({test::modalFrf(kMode, quantity, test::evenFrequencies(0.0, 1.0, 2001), FrfDirection::Y)});
  test::writeBytes(path.toStdString(), text);
  return path;
}
}  // namespace

class TestFrfImport : public QObject {
  Q_OBJECT
 private slots:
  void quantityNames_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("quantity");  // -1: rejected
    QTest::newRow("receptance") << "receptance" << static_cast<int>(FrfQuantity::Receptance);
    QTest::newRow("mobility") << "mobility" << static_cast<int>(FrfQuantity::Mobility);
    QTest::newRow("accelerance") << "accelerance" << static_cast<int>(FrfQuantity::Accelerance);
    QTest::newRow("capitalised") << "Receptance" << -1;
    QTest::newRow("empty") << "" << -1;
    QTest::newRow("compliance") << "compliance" << -1;
  }
  void quantityNames() {
    QFETCH(QString, name);
    QFETCH(int, quantity);
    if (quantity < 0) {
      try {
        app::frfQuantityFromName("frf_x.quantity", name);
        QFAIL("accepted");
      } catch (const app::InputError& e) {
        QVERIFY(QString(e.what()).contains("frf_x.quantity"));
        QVERIFY(QString(e.what()).contains("receptance, mobility or accelerance"));
      }
      return;
    }
    QCOMPARE(static_cast<int>(app::frfQuantityFromName("q", name)), quantity);
  }

  void formatNames() {
    QCOMPARE(app::frfFormatName(FrfFormat::Uff58), QString("uff58"));
    QCOMPARE(app::frfFormatName(FrfFormat::Uff58b), QString("uff58b"));
    QCOMPARE(app::frfFormatName(FrfFormat::Csv), QString("csv"));
  }

  void datasetIndexIsChecked() {
    QTemporaryDir dir;
    const QString path = writeUff(dir, FrfQuantity::Mobility);
    const FrfFile file = app::loadFrfFile(path, std::nullopt);
    const Receptance r = app::frfReceptance(file, path, 0);
    QCOMPARE(r.direction, FrfDirection::Y);
    QCOMPARE(r.frequency_hz.size(), std::size_t{2000});  // mobility: the 0 Hz line cannot be converted
    QVERIFY(std::abs(r.h_m_per_n[699] / receptance(kMode, {0.0, 2.0 * std::numbers::pi * 700.0}) - 1.0) < 1e-9);
    for (int bad : {-1, 1}) {
      try {
        app::frfReceptance(file, path, bad);
        QFAIL("accepted");
      } catch (const app::InputError& e) {
        QVERIFY(QString(e.what()).contains(QString("dataset = %1: must be in [0, 0]").arg(bad)));
      }
    }
  }

  void uffQuantityMustAgree() {
    QTemporaryDir dir;
    const QString path = writeUff(dir, FrfQuantity::Accelerance);
    QCOMPARE(app::loadFrfFile(path, FrfQuantity::Accelerance).datasets.size(), std::size_t{1});
    QVERIFY_THROWS_EXCEPTION(app::InputError, app::loadFrfFile(path, FrfQuantity::Receptance));
  }

  void fitDefaultsToTheMeasuredRange() {
    QTemporaryDir dir;
    const QString path = writeUff(dir, FrfQuantity::Receptance);
    const Receptance r = app::frfReceptance(app::loadFrfFile(path, std::nullopt), path, 0);
    const ModalFitResult fit = app::fitFrfModes(r, std::nullopt, std::nullopt, {});
    QCOMPARE(fit.band_frequency_hz.front(), 1.0);  // the first line above 0 Hz
    QCOMPARE(fit.band_frequency_hz.back(), 2000.0);
    QCOMPARE(fit.modes.size(), std::size_t{1});
    QVERIFY(std::abs(fit.modes[0].natural_frequency_hz / 700.0 - 1.0) < 1e-6);
    QVERIFY(std::abs(fit.modes[0].stiffness_n_per_m / 8e6 - 1.0) < 1e-6);
    QVERIFY_THROWS_EXCEPTION(app::InputError, app::fitFrfModes(r, 900.0, 800.0, {}));
  }
};

MX_REGISTER_TEST(TestFrfImport)
#include "test_frf_import.moc"
