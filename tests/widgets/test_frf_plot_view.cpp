// FrfPlotView: graphs per panel and axis labels per display, the frequency axis scale, legend entries
// for every curve, and the residual |H_measured - H_fitted| in µm/N (zero for an exact fit, the offset
// for an offset fit, interpolated onto a different fitted grid).
#include <QCheckBox>
#include <QComboBox>

#include "frf_plot_view.h"
#include "test_registry.h"

using mx::widgets::FrfCurve;
using mx::widgets::FrfPlotView;
using C = std::complex<double>;
Q_DECLARE_METATYPE(FrfPlotView::Display)

namespace {

// One mode, 1000 Hz, zeta 0.02, k 2e7 N/m: H = (1/k) / (1 - r^2 + 2 i zeta r).
FrfCurve oneMode(const QString& label, double f0, double f1, int points, C offset = {}) {
  FrfCurve curve{label, {}, {}};
  for (int i = 0; i < points; ++i) {
    const double f = f0 + (f1 - f0) * i / (points - 1);
    const double r = f / 1000.0;
    curve.frequency_hz.push_back(f);
    curve.h_m_per_n.push_back(1.0 / 2e7 / C(1.0 - r * r, 2.0 * 0.02 * r) + offset);
  }
  return curve;
}

}  // namespace

class TestFrfPlotView : public QObject {
  Q_OBJECT
 private slots:
  void panelsAndLabelsPerDisplay_data() {
    QTest::addColumn<FrfPlotView::Display>("display");
    QTest::addColumn<QString>("upper");
    QTest::addColumn<QString>("lower");
    QTest::newRow("magnitude / phase") << FrfPlotView::Display::MagnitudePhase << "|H| [\u00b5m/N]"
                                       << "Phase [deg]";
    QTest::newRow("real / imaginary") << FrfPlotView::Display::RealImaginary << "Re H [\u00b5m/N]"
                                      << "Im H [\u00b5m/N]";
  }
  void panelsAndLabelsPerDisplay() {
    QFETCH(FrfPlotView::Display, display);
    QFETCH(QString, upper);
    QFETCH(QString, lower);
    FrfPlotView view;
    view.setMeasured({oneMode("measured x", 0.0, 2000.0, 201), oneMode("measured y", 0.0, 2000.0, 201)});
    view.setFitted({oneMode("fitted x", 100.0, 2000.0, 191)});
    view.setDisplay(display);
    QCOMPARE(view.display(), display);
    QCOMPARE(view.upperGraphCount(), 3);
    QCOMPARE(view.lowerGraphCount(), 3);
    QCOMPARE(view.residualGraphCount(), 1);
    QCOMPARE(view.upperAxisLabel(), upper);
    QCOMPARE(view.lowerAxisLabel(), lower);
    QCOMPARE(view.frequencyAxisLabel(), QString("Frequency [Hz]"));
    QCOMPARE(view.residualAxisLabel(), QString("|\u0394H| [\u00b5m/N]"));
    QCOMPARE(view.legendNames(), QStringList({"measured x", "measured y", "fitted x", "residual x"}));
  }

  void displayComboDrivesTheView() {
    FrfPlotView view;
    auto* combo = view.findChild<QComboBox*>();
    QVERIFY(combo);
    combo->setCurrentIndex(1);
    QCOMPARE(view.display(), FrfPlotView::Display::RealImaginary);
    view.setDisplay(FrfPlotView::Display::MagnitudePhase);
    QCOMPARE(combo->currentIndex(), 0);
  }

  void logFrequency_data() {
    QTest::addColumn<bool>("log");
    QTest::addColumn<int>("points");  // 0 Hz is left out on a log axis
    QTest::newRow("linear") << false << 201;
    QTest::newRow("log") << true << 200;
  }
  void logFrequency() {
    QFETCH(bool, log);
    QFETCH(int, points);
    FrfPlotView view;
    view.setMeasured({oneMode("measured x", 0.0, 2000.0, 201)});
    view.setFitted({oneMode("fitted x", 0.0, 2000.0, 201)});
    auto* box = view.findChild<QCheckBox*>();
    QVERIFY(box);
    box->setChecked(log);
    QCOMPARE(view.logFrequency(), log);
    QCOMPARE(static_cast<int>(view.residualFrequencies(0).size()), points);
    view.setLogFrequency(!log);
    QCOMPARE(view.logFrequency(), !log);
    QCOMPARE(box->isChecked(), !log);
  }

  // Receptance phase wraps at +90 deg: a lag just past 180 deg reads -181, not +179.
  void lowerPanelValues_data() {
    QTest::addColumn<FrfPlotView::Display>("display");
    QTest::addColumn<C>("h_m_per_n");
    QTest::addColumn<double>("expected");
    const double deg = std::numbers::pi / 180.0;
    QTest::newRow("phase -90") << FrfPlotView::Display::MagnitudePhase << C(0.0, -1e-6) << -90.0;
    QTest::newRow("phase -181") << FrfPlotView::Display::MagnitudePhase << std::polar(1e-6, 179.0 * deg) << -181.0;
    QTest::newRow("phase +89") << FrfPlotView::Display::MagnitudePhase << std::polar(1e-6, 89.0 * deg) << 89.0;
    QTest::newRow("Im H") << FrfPlotView::Display::RealImaginary << C(2e-6, -3e-6) << -3.0;
  }
  void lowerPanelValues() {
    QFETCH(FrfPlotView::Display, display);
    QFETCH(C, h_m_per_n);
    QFETCH(double, expected);
    FrfPlotView view;
    view.setDisplay(display);
    view.setMeasured({{"measured x", {100.0, 200.0}, {h_m_per_n, h_m_per_n}}});
    const auto values = view.lowerPanelValues(0);
    QCOMPARE(values.size(), std::size_t{2});
    QVERIFY2(std::abs(values[0] - expected) < 1e-9, qPrintable(QString::number(values[0])));
  }

  void residual_data() {
    QTest::addColumn<C>("offset_m_per_n");
    QTest::addColumn<double>("expected_um_per_n");
    QTest::newRow("exact fit") << C(0.0, 0.0) << 0.0;
    QTest::newRow("real offset 0.01 um/N") << C(1e-8, 0.0) << 0.01;
    QTest::newRow("complex offset 3+4i nm/N") << C(3e-9, 4e-9) << 0.005;
  }
  void residual() {
    QFETCH(C, offset_m_per_n);
    QFETCH(double, expected_um_per_n);
    FrfPlotView view;
    view.setMeasured({oneMode("measured x", 0.0, 2000.0, 2001)});
    view.setFitted({oneMode("fitted x", 100.0, 1900.0, 1801, offset_m_per_n)});
    const auto r = view.residualMicrometrePerNewton(0);
    QCOMPARE(r.size(), std::size_t{1801});
    for (const double v : r) QVERIFY2(std::abs(v - expected_um_per_n) < 1e-9, qPrintable(QString::number(v)));
  }

  // A fitted grid between the measured lines: the measurement is interpolated linearly, so the residual
  // of the linear part is exact where H is nearly linear (far from the resonance) and the points outside
  // the measured range are left out.
  void residualInterpolatesTheMeasurement() {
    FrfCurve measured{"measured x", {0.0, 10.0, 20.0}, {C(1e-6, 0.0), C(2e-6, 1e-6), C(3e-6, 2e-6)}};
    FrfCurve fitted{"fitted x", {5.0, 15.0, 25.0}, {C(1.5e-6, 0.5e-6), C(2.5e-6, 1.5e-6), C(0.0, 0.0)}};
    FrfPlotView view;
    view.setMeasured({measured});
    view.setFitted({fitted});
    QCOMPARE(view.residualFrequencies(0), std::vector<double>({5.0, 15.0}));
    for (const double v : view.residualMicrometrePerNewton(0)) QVERIFY(std::abs(v) < 1e-12);
  }

  void fittedPairsWithItsDirection() {
    FrfPlotView view;
    view.setMeasured({oneMode("measured x", 0.0, 2000.0, 201), oneMode("measured y", 0.0, 2000.0, 201, 1e-8)});
    view.setFitted({oneMode("fitted y", 0.0, 2000.0, 201)});
    for (const double v : view.residualMicrometrePerNewton(0)) QVERIFY(std::abs(v - 0.01) < 1e-9);
  }

  void clearEmptiesThePanels() {
    FrfPlotView view;
    view.setMeasured({oneMode("measured x", 0.0, 2000.0, 201)});
    view.setFitted({oneMode("fitted x", 0.0, 2000.0, 201)});
    view.clear();
    QCOMPARE(view.upperGraphCount(), 0);
    QCOMPARE(view.lowerGraphCount(), 0);
    QCOMPARE(view.residualGraphCount(), 0);
    QVERIFY(view.legendNames().isEmpty());
    QVERIFY(view.residualMicrometrePerNewton(0).empty());
  }
};

MX_REGISTER_TEST(TestFrfPlotView)
#include "test_frf_plot_view.moc"
