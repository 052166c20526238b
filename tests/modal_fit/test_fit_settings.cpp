// Checks of the modal fit's input: each bad value names its field, value and range (fit_settings.h).
#include "core/invalid_input.h"
#include "modal_fit/fit_settings.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;

class TestFitSettings : public QObject {
  Q_OBJECT
 private slots:
  void invalid_data() {
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("max_modes");
    QTest::addColumn<int>("modes");  // 0: automatic
    QTest::addColumn<QString>("message");
    QTest::newRow("from below data") << 50.0 << 1000.0 << 10 << 0 << "from_hz = 50: must be in [100, 2000] Hz";
    QTest::newRow("to above data") << 200.0 << 2500.0 << 10 << 0 << "to_hz = 2500: must be in [100, 2000] Hz";
    QTest::newRow("from = to") << 500.0 << 500.0 << 10 << 0 << "to_hz = 500: must be > from_hz = 500";
    QTest::newRow("from > to") << 800.0 << 500.0 << 10 << 0 << "to_hz = 500: must be > from_hz = 800";
    QTest::newRow("from at the top") << 2000.0 << 2000.0 << 10 << 0 << "from_hz = 2000: must be in [100, 2000]";
    QTest::newRow("band of 5 points") << 500.5 << 505.5 << 10 << 0 << "points in band = 5: must be at least 8";
    QTest::newRow("max_modes 0") << 200.0 << 1000.0 << 0 << 0 << "max_modes = 0: must be in [1, 50]";
    QTest::newRow("max_modes 51") << 200.0 << 1000.0 << 51 << 0 << "max_modes = 51: must be in [1, 50]";
    QTest::newRow("modes 0") << 200.0 << 1000.0 << 10 << -1 << "modes = 0: must be in [1, 10]";
    QTest::newRow("modes 11") << 200.0 << 1000.0 << 10 << 11 << "modes = 11: must be in [1, 10]";
  }
  void invalid() {
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, max_modes);
    QFETCH(int, modes);
    QFETCH(QString, message);
    const auto frf = test::syntheticFrf({{700.0, 0.02, 2e7}}, 100.0, 2000.0, 1901);  // 1 Hz lines
    auto settings = test::bandSettings(from, to, max_modes);
    if (modes != 0) settings.modes = modes < 0 ? 0 : modes;
    try {
      validateFitInput(frf.frequency_hz, frf.h_m_per_n, settings);
      QFAIL("no exception");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
  }

  void invalidData_data() {
    QTest::addColumn<int>("defect");
    QTest::addColumn<QString>("message");
    QTest::newRow("sizes differ") << 0 << "h_m_per_n size = 1900: must be the size of frequency_hz (1901)";
    QTest::newRow("not increasing") << 1 << "frequency_hz[10] = 108: must be > the previous frequency";
    QTest::newRow("NaN in H") << 2 << "h_m_per_n[5] = nan: must be finite";
    QTest::newRow("negative frequency") << 3 << "frequency_hz[0] = -1: must be finite and >= 0 Hz";
  }
  void invalidData() {
    QFETCH(int, defect);
    QFETCH(QString, message);
    auto frf = test::syntheticFrf({{700.0, 0.02, 2e7}}, 100.0, 2000.0, 1901);
    if (defect == 0) frf.h_m_per_n.pop_back();
    if (defect == 1) frf.frequency_hz[10] = 108.0;
    if (defect == 2) frf.h_m_per_n[5] = {std::nan(""), 0.0};
    if (defect == 3) frf.frequency_hz[0] = -1.0;
    try {
      validateFitInput(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(200.0, 1000.0));
      QFAIL("no exception");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
  }

  void validPasses() {
    const auto frf = test::syntheticFrf({{700.0, 0.02, 2e7}}, 100.0, 2000.0, 1901);
    validateFitInput(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(100.0, 2000.0, 10, 10));
    validateFitInput(frf.frequency_hz, frf.h_m_per_n, test::bandSettings(499.5, 507.5, 1, 1));  // 8 points
  }
};

MX_REGISTER_TEST(TestFitSettings)
#include "test_fit_settings.moc"
