// TapTestPanel: fitRequested carries the form (band, model size with "automatic", method, direction),
// the band limits follow the measurement, a diagram choice asks for a fit at the chosen poles, Accept
// waits for a fit of the current direction, the busy state switches Fit and Cancel, and a fit result
// fills the modes table, the fit error and the plots.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>

#include "frf_plot_view.h"
#include "stabilisation_diagram_view.h"
#include "tap_test_panel.h"
#include "test_registry.h"

using mx::widgets::TapTestFitRequest;
using mx::widgets::TapTestPanel;
using C = std::complex<double>;

namespace {

struct Frf {
  std::vector<double> f;
  std::vector<C> h;
};

// One mode at f_n [Hz], zeta 0.02, k 2e7 N/m, on 0 .. 2000 Hz.
Frf oneMode(double f_n, int points = 401) {
  Frf frf;
  for (int i = 0; i < points; ++i) {
    const double f = 2000.0 * i / (points - 1);
    const double r = f / f_n;
    frf.f.push_back(f);
    frf.h.push_back(1.0 / 2e7 / C(1.0 - r * r, 2.0 * 0.02 * r));
  }
  return frf;
}

mx::ModalFitResult fitResult(const Frf& frf) {
  mx::ModalFitResult result;
  result.modes = {{1000.0, 0.02, 2e7}};
  result.fit_error_pct = 1.25;
  result.method = "LSCF + LSFD + NLLS";
  result.band_frequency_hz.assign(frf.f.begin() + 1, frf.f.end());
  result.fitted.assign(frf.h.begin() + 1, frf.h.end());
  const double w = 2.0 * std::numbers::pi * 1000.0;
  for (int order = 2; order <= 6; order += 2)
    result.diagram.orders.push_back(
        {order,
         {{C(-0.02 * w, w), 1000.0, 0.02, order > 2 ? mx::PoleStability::Stable : mx::PoleStability::Unstable}}});
  return result;
}

template <typename T>
T* child(const TapTestPanel& panel, const char* name) {
  auto* widget = panel.findChild<T*>(QString::fromLatin1(name));
  if (!widget) qFatal("no child %s", name);
  return widget;
}

}  // namespace

class TestTapTestPanel : public QObject {
  Q_OBJECT
 private slots:
  void fitRequestCarriesTheForm_data() {
    QTest::addColumn<QString>("direction");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("max_modes");
    QTest::addColumn<int>("modes");  // 0: "automatic"
    QTest::addColumn<int>("method");
    QTest::newRow("defaults, automatic") << "x" << 5.0 << 2000.0 << 10 << 0 << 0;
    QTest::newRow("y, band, 3 modes") << "y" << 200.0 << 1500.0 << 12 << 3 << 0;
    QTest::newRow("peak picking, 1 mode") << "x" << 600.0 << 1400.0 << 1 << 1 << 1;
    QTest::newRow("50 modes, 50 max") << "y" << 5.0 << 2000.0 << 50 << 50 << 0;
  }
  void fitRequestCarriesTheForm() {
    QFETCH(QString, direction);
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, max_modes);
    QFETCH(int, modes);
    QFETCH(int, method);
    TapTestPanel panel;
    const Frf frf = oneMode(1000.0);
    panel.setMeasurement("x", frf.f, frf.h);
    panel.setMeasurement("y", frf.f, frf.h);
    child<QComboBox>(panel, "direction")->setCurrentText(direction);
    child<QDoubleSpinBox>(panel, "from_hz")->setValue(from);
    child<QDoubleSpinBox>(panel, "to_hz")->setValue(to);
    child<QSpinBox>(panel, "max_modes")->setValue(max_modes);
    child<QSpinBox>(panel, "modes")->setValue(modes);
    child<QComboBox>(panel, "method")->setCurrentIndex(method);
    QCOMPARE(child<QSpinBox>(panel, "modes")->text(), modes == 0 ? QString("automatic") : QString::number(modes));
    std::vector<TapTestFitRequest> requests;
    connect(&panel, &TapTestPanel::fitRequested, this,
            [&requests](const TapTestFitRequest& r) { requests.push_back(r); });
    QTest::mouseClick(child<QPushButton>(panel, "fit"), Qt::LeftButton);
    QCOMPARE(requests.size(), std::size_t{1});
    const TapTestFitRequest& r = requests.front();
    QCOMPARE(r.direction, direction);
    QCOMPARE(panel.currentDirection(), direction);
    QCOMPARE(r.from_hz, from);
    QCOMPARE(r.to_hz, to);
    QCOMPARE(r.max_modes, max_modes);
    QCOMPARE(r.modes, modes == 0 ? std::nullopt : std::optional<int>(modes));
    QCOMPARE(r.peak, method == 1);
    QVERIFY(r.poles.empty());
  }

  // The first line above 0 Hz to the last, over every direction.
  void bandLimitsFollowTheMeasurement() {
    TapTestPanel panel;
    const Frf x = oneMode(1000.0, 401);  // lines every 5 Hz
    panel.setMeasurement("x", x.f, x.h);
    auto* from = child<QDoubleSpinBox>(panel, "from_hz");
    auto* to = child<QDoubleSpinBox>(panel, "to_hz");
    QCOMPARE(from->minimum(), 5.0);
    QCOMPARE(to->maximum(), 2000.0);
    QCOMPARE(from->value(), 5.0);
    QCOMPARE(to->value(), 2000.0);
    Frf y = oneMode(1000.0, 201);
    for (double& f : y.f) f *= 1.5;  // to 3000 Hz, lines every 15 Hz
    panel.setMeasurement("y", y.f, y.h);
    QCOMPARE(from->minimum(), 5.0);
    QCOMPARE(to->maximum(), 3000.0);
    panel.clearMeasurement("x");
    QCOMPARE(from->minimum(), 15.0);
  }

  void acceptWaitsForAFitOfTheDirection() {
    TapTestPanel panel;
    const Frf frf = oneMode(1000.0);
    panel.setMeasurement("x", frf.f, frf.h);
    panel.setMeasurement("y", frf.f, frf.h);
    auto* accept = child<QPushButton>(panel, "accept");
    QVERIFY(!accept->isEnabled());
    panel.setFitResult("y", fitResult(frf), false);
    QVERIFY(!accept->isEnabled());  // x is shown
    child<QComboBox>(panel, "direction")->setCurrentText("y");
    QVERIFY(accept->isEnabled());
    QString accepted;
    connect(&panel, &TapTestPanel::acceptRequested, this, [&accepted](const QString& d) { accepted = d; });
    QTest::mouseClick(accept, Qt::LeftButton);
    QCOMPARE(accepted, QString("y"));
    panel.setMeasurement("y", frf.f, frf.h);  // a new measurement needs a new fit
    QVERIFY(!accept->isEnabled());
  }

  void busyStateTogglesButtons_data() {
    QTest::addColumn<bool>("busy");
    QTest::addColumn<bool>("fit");
    QTest::addColumn<bool>("cancel");
    QTest::addColumn<bool>("accept");
    QTest::newRow("idle") << false << true << false << true;
    QTest::newRow("busy") << true << false << true << false;
  }
  void busyStateTogglesButtons() {
    QFETCH(bool, busy);
    QFETCH(bool, fit);
    QFETCH(bool, cancel);
    QFETCH(bool, accept);
    TapTestPanel panel;
    QVERIFY(!child<QPushButton>(panel, "fit")->isEnabled());  // nothing measured
    const Frf frf = oneMode(1000.0);
    panel.setMeasurement("x", frf.f, frf.h);
    panel.setFitResult("x", fitResult(frf), false);
    panel.setBusy(busy);
    panel.setProgress(0.4);
    QCOMPARE(child<QPushButton>(panel, "fit")->isEnabled(), fit);
    QCOMPARE(child<QPushButton>(panel, "cancel")->isEnabled(), cancel);
    QCOMPARE(child<QPushButton>(panel, "accept")->isEnabled(), accept);
    QCOMPARE(child<QProgressBar>(panel, "progress")->value(), 400);
    if (busy) {
      int cancelled = 0;
      connect(&panel, &TapTestPanel::cancelRequested, this, [&cancelled] { ++cancelled; });
      QTest::mouseClick(child<QPushButton>(panel, "cancel"), Qt::LeftButton);
      QCOMPARE(cancelled, 1);
    }
  }

  void fitResultFillsTableAndPlots() {
    TapTestPanel panel;
    const Frf frf = oneMode(1000.0);
    panel.setMeasurement("x", frf.f, frf.h);
    panel.setFitResult("x", fitResult(frf), false);
    auto* table = child<QTableWidget>(panel, "modes_table");
    QCOMPARE(table->columnCount(), 3);
    QCOMPARE(table->horizontalHeaderItem(0)->text(), QString("f [Hz]"));
    QCOMPARE(table->horizontalHeaderItem(1)->text(), QString("\u03b6 [%]"));
    QCOMPARE(table->horizontalHeaderItem(2)->text(), QString("k [N/\u00b5m]"));
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(table->item(0, 0)->text(), QString("1000.0"));
    QCOMPARE(table->item(0, 1)->text(), QString("2.00"));
    QCOMPARE(table->item(0, 2)->text(), QString("20.00"));
    QVERIFY(child<QLabel>(panel, "fit_error")->text().startsWith("fit error [%]: 1.25"));
    QCOMPARE(panel.frfView()->legendNames(), QStringList({"measured x", "fitted x", "residual x"}));
    for (const double r : panel.frfView()->residualMicrometrePerNewton(0)) QVERIFY(std::abs(r) < 1e-12);
    QCOMPARE(panel.diagramView()->markerCount(mx::PoleStability::Stable), 2);
    QCOMPARE(panel.diagramView()->magnitudePointCount(), 401);
    panel.setMessage("fit failed: band too narrow");
    QCOMPARE(child<QLabel>(panel, "message")->text(), QString("fit failed: band too narrow"));
  }

  // A choice on the diagram asks for a fit at the chosen poles; the fit at them keeps the diagram.
  void diagramChoiceRequestsAFitAtThePoles() {
    TapTestPanel panel;
    const Frf frf = oneMode(1000.0);
    panel.setMeasurement("x", frf.f, frf.h);
    const mx::ModalFitResult result = fitResult(frf);
    panel.setFitResult("x", result, false);
    std::vector<TapTestFitRequest> requests;
    connect(&panel, &TapTestPanel::fitRequested, this,
            [&requests](const TapTestFitRequest& r) { requests.push_back(r); });
    QVERIFY(panel.diagramView()->togglePoleNear(1000.0, 6.0));
    QCOMPARE(requests.size(), std::size_t{1});
    QCOMPARE(requests[0].poles, std::vector<C>{result.diagram.orders[2].poles[0].lambda});
    QCOMPARE(requests[0].direction, QString("x"));
    mx::ModalFitResult at_poles = result;
    at_poles.diagram = {};
    panel.setFitResult("x", at_poles, true);
    QCOMPARE(panel.diagramView()->markerCount(mx::PoleStability::Stable), 2);
    QCOMPARE(panel.diagramView()->selectedPoles().size(), std::size_t{1});
    QVERIFY(panel.diagramView()->togglePoleNear(1000.0, 6.0));  // taken back: nothing to fit
    QCOMPARE(requests.size(), std::size_t{1});
  }
};

MX_REGISTER_TEST(TestTapTestPanel)
#include "test_tap_test_panel.moc"
