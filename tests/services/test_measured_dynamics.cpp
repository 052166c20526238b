// Measured tool dynamics (services/measured_dynamics.h): which dynamics a command uses for a tool, the
// fall-back to the fitted modes (delta > 0, semi-discretization), and the FRF files read into the setup
// with errors that name the tool, the field and the path.
#include <QDir>

#include "document/project.h"
#include "frf/frf_csv.h"
#include "frf/uff_writer.h"
#include "services/measured_dynamics.h"
#include "services/service_errors.h"
#include "support/error_message.h"
#include "support/frf_samples.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {

const ModalAxis kX{{600.0, 0.03, 5e6}};
const ModalAxis kY{{650.0, 0.035, 6e6}};

FrfRefSpec ref(const QString& file, std::optional<int> dataset = std::nullopt,
               std::optional<QString> quantity = std::nullopt) {
  return FrfRefSpec{file, dataset, std::move(quantity), {}};
}

// taps/xy.uff: dataset 0 = x/x accelerance, dataset 1 = y/y accelerance; taps/x.csv: x receptance.
Project tapProject(const QTemporaryDir& dir) {
  QDir(dir.path()).mkpath("taps");
  const auto f = test::evenFrequencies(0.0, 1.0, 2001);
  test::writeBytes(dir.filePath("taps/xy.uff").toStdString(),
                   uff58String({test::modalFrf(kX, FrfQuantity::Accelerance, f, FrfDirection::X),
                                test::modalFrf(kY, FrfQuantity::Accelerance, f, FrfDirection::Y)}));
  test::writeBytes(dir.filePath("taps/x.csv").toStdString(),
                   frfCsvString(test::modalFrf(kX, FrfQuantity::Receptance, f, FrfDirection::X)));
  Project p = loadProject(test::projectsPath("rubio2006-tool-selection.mxproj"));
  p.folder = dir.path();
  return p;
}

// The InputError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString inputErrorOf(F fn) {
  return mx::test::messageOf<InputError>(fn);
}

}  // namespace

Q_DECLARE_METATYPE(mx::DynamicsSource)
Q_DECLARE_METATYPE(std::optional<mx::DynamicsSource>)

class TestMeasuredDynamics : public QObject {
  Q_OBJECT
 private slots:
  void names() {
    QCOMPARE(dynamicsSourceFromName("--dynamics", "modal"), DynamicsSource::Modal);
    QCOMPARE(dynamicsSourceFromName("--dynamics", "measured"), DynamicsSource::Measured);
    QCOMPARE(dynamicsName(DynamicsSource::Measured), QString("measured"));
    const QString e = inputErrorOf([] { dynamicsSourceFromName("--dynamics", "frf"); });
    QVERIFY2(e.contains("--dynamics = 'frf': must be modal or measured"), qPrintable(e));
  }

  // rows: modes on x/y, FRF on x/y, requested, delta, sdm -> used, note expected, error fragment
  void choice_data() {
    QTest::addColumn<bool>("modes_x");
    QTest::addColumn<bool>("frf_x");
    QTest::addColumn<std::optional<DynamicsSource>>("requested");
    QTest::addColumn<double>("delta");
    QTest::addColumn<bool>("sdm");
    QTest::addColumn<int>("used");  // 0 modal, 1 measured
    QTest::addColumn<bool>("note");
    QTest::addColumn<QString>("error");
    const std::optional<DynamicsSource> none, modal = DynamicsSource::Modal, measured = DynamicsSource::Measured;
    QTest::newRow("modes only, default") << true << false << none << 0.0 << false << 0 << false << "";
    QTest::newRow("both, default") << true << true << none << 0.0 << false << 0 << false << "";
    QTest::newRow("frf only, default") << false << true << none << 0.0 << false << 1 << false << "";
    QTest::newRow("both, measured") << true << true << measured << 0.0 << false << 1 << false << "";
    QTest::newRow("both, measured, delta") << true << true << measured << 0.05 << false << 0 << true << "";
    QTest::newRow("both, measured, sdm") << true << true << measured << 0.0 << true << 0 << true << "";
    QTest::newRow("modes only, measured")
        << true << false << measured << 0.0 << false << -1 << false << "needs a tap-test FRF";
    QTest::newRow("frf only, modal") << false << true << modal << 0.0 << false << -1 << false
                                     << "modes_x is empty and only frf_x";
    QTest::newRow("frf only, delta") << false << true << none << 0.05 << false << -1 << false
                                     << "a margin delta > 0 needs fitted modes";
    QTest::newRow("frf only, sdm") << false << true << measured << 0.0 << true << -1 << false
                                   << "semi-discretization needs fitted modes";
  }
  void choice() {
    QFETCH(bool, modes_x);
    QFETCH(bool, frf_x);
    QFETCH(std::optional<DynamicsSource>, requested);
    QFETCH(double, delta);
    QFETCH(bool, sdm);
    QFETCH(int, used);
    QFETCH(bool, note);
    QFETCH(QString, error);
    ToolSpec tool;
    tool.id = "T9";
    if (modes_x) tool.modes_x = {ModeSpec{600.0, 3.0, 5.0, {}}};
    tool.modes_y = {ModeSpec{650.0, 3.5, 6.0, {}}};
    if (frf_x) tool.frf_x = ref("taps/x.uff");
    const StabilityMethod method = sdm ? StabilityMethod::SemiDiscretization : StabilityMethod::ZeroOrder;
    if (used < 0) {
      const QString e = inputErrorOf([&] { chooseDynamics(tool, requested, delta, method); });
      QVERIFY2(e.contains("tool 'T9'") && e.contains(error), qPrintable(e));
      return;
    }
    const DynamicsChoice c = chooseDynamics(tool, requested, delta, method);
    QCOMPARE(static_cast<int>(c.used), used);
    QCOMPARE(!c.note.isEmpty(), note);
  }

  void readsTheFrfsIntoTheSetup() {
    QTemporaryDir dir;
    Project p = tapProject(dir);
    p.tools[0].frf_x = ref("taps/xy.uff", 0, QString("accelerance"));
    p.tools[0].frf_y = ref("taps/xy.uff", 1);
    const MillingSetup modal = dynamicsSetupFor(p, "R1", DynamicsSource::Modal);
    QVERIFY(!modal.measured_x && !modal.measured_y);
    const MillingSetup s = dynamicsSetupFor(p, "R1", DynamicsSource::Measured);
    QVERIFY(s.measured_x && s.measured_y);
    QCOMPARE(s.modes_x.size(), std::size_t{1});                      // the modes stay for the methods that need them
    QCOMPARE(s.measured_x->frequency_hz.size(), std::size_t{2000});  // accelerance: 0 Hz dropped
    // the accelerance came back as the receptance of the modes, at 600 Hz and 650 Hz
    const double w = 2.0 * std::numbers::pi;
    const auto gx = receptance(kX, {0.0, w * 600.0}), gy = receptance(kY, {0.0, w * 650.0});
    QCOMPARE_LE(std::abs(s.measured_x->at(w * 600.0) - gx), 1e-9 * std::abs(gx));
    QCOMPARE_LE(std::abs(s.measured_y->at(w * 650.0) - gy), 1e-9 * std::abs(gy));
    // a CSV needs its quantity
    p.tools[0].frf_x = ref("taps/x.csv", std::nullopt, QString("receptance"));
    QCOMPARE_LE(std::abs(dynamicsSetupFor(p, "R1", DynamicsSource::Measured).measured_x->at(w * 600.0) - gx),
                1e-9 * std::abs(gx));
  }

  void fileErrorsNameToolFieldAndPath_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("dataset");
    QTest::addColumn<QString>("quantity");  // "" = none
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("missing") << "taps/none.uff" << 0 << ""
                             << QStringList{"tool 'R1'", "frf_x.file = \"taps/none.uff\"", "none.uff", "not found"};
    QTest::newRow("dataset out of range")
        << "taps/xy.uff" << 2 << "" << QStringList{"tool 'R1'", "frf_x", "dataset = 2: must be in [0, 1]"};
    QTest::newRow("wrong direction") << "taps/xy.uff" << 1 << ""
                                     << QStringList{"tool 'R1'", "frf_x.file", "y/y FRF", "must be x/x"};
    QTest::newRow("quantity disagrees") << "taps/xy.uff" << 0 << "mobility"
                                        << QStringList{"tool 'R1'", "frf_x", "quantity = mobility", "accelerance"};
    QTest::newRow("csv without quantity")
        << "taps/x.csv" << 0 << "" << QStringList{"tool 'R1'", "frf_x", "x.csv", "quantity"};
    QTest::newRow("not an FRF file") << "p.mxproj" << 0 << "" << QStringList{"tool 'R1'", "frf_x", "p.mxproj"};
  }
  void fileErrorsNameToolFieldAndPath() {
    QFETCH(QString, file);
    QFETCH(int, dataset);
    QFETCH(QString, quantity);
    QFETCH(QStringList, expected);
    QTemporaryDir dir;
    Project p = tapProject(dir);
    saveProject(p, dir.filePath("p.mxproj"));
    p.tools[0].frf_x = ref(file, dataset, quantity.isEmpty() ? std::nullopt : std::optional(quantity));
    const QString e = inputErrorOf([&] { dynamicsSetupFor(p, "R1", DynamicsSource::Measured); });
    for (const QString& f : expected) QVERIFY2(e.contains(f), qPrintable(QString("'%1' not in: %2").arg(f, e)));
  }
};

MX_REGISTER_TEST(TestMeasuredDynamics)
#include "test_measured_dynamics.moc"
