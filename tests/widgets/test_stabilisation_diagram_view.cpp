// StabilisationDiagramView: markers per stability class equal to the diagram's counts, labelled axes
// and legend, the summed magnitude behind the poles, and the pick logic: a click toggles the nearest
// pole within 10 px, a pole within 1 % of a chosen one replaces it, a click far from every pole does
// nothing.
#include "stabilisation_diagram_view.h"
#include "test_registry.h"

using mx::DiagramPole;
using mx::PoleStability;
using mx::StabilisationDiagram;
using mx::widgets::StabilisationDiagramView;
using C = std::complex<double>;

namespace {

DiagramPole pole(double f_hz, double zeta, PoleStability stability) {
  const double w = 2.0 * std::numbers::pi * f_hz;
  return {C(-zeta * w, w * std::sqrt(1.0 - zeta * zeta)), f_hz, zeta, stability, 1, 1};
}

// Orders 2..8: a pole at 500 Hz stable from order 4, one at 1200 Hz frequency-stable from order 4 and
// stable from order 6, a spurious unstable pole per order.
StabilisationDiagram sampleDiagram() {
  StabilisationDiagram diagram;
  for (int order = 2; order <= 8; order += 2) {
    mx::DiagramOrder o{order, {}};
    o.poles.push_back(pole(500.0 + 0.1 * order, 0.02, order >= 4 ? PoleStability::Stable : PoleStability::Unstable));
    o.poles.push_back(pole(900.0 + 37.0 * order, 0.1, PoleStability::Unstable));
    o.poles.push_back(pole(1200.0 - 0.2 * order, 0.03,
                           order >= 6   ? PoleStability::Stable
                           : order >= 4 ? PoleStability::FrequencyStable
                                        : PoleStability::Unstable));
    diagram.orders.push_back(o);
  }
  return diagram;
}

int count(const StabilisationDiagram& diagram, PoleStability stability) {
  int n = 0;
  for (const auto& o : diagram.orders)
    for (const auto& p : o.poles) n += p.stability == stability ? 1 : 0;
  return n;
}

}  // namespace

class TestStabilisationDiagramView : public QObject {
  Q_OBJECT
 private slots:
  void axesAndLegend() {
    StabilisationDiagramView view;
    QCOMPARE(view.xAxisLabel(), QString("Frequency [Hz]"));
    QCOMPARE(view.yAxisLabel(), QString("Model order [\u2013]"));
    QCOMPARE(view.magnitudeAxisLabel(), QString("\u03a3 |H| [\u00b5m/N]"));
    QCOMPARE(view.legendNames(),
             QStringList({"\u03a3 |H| measured", "stable", "frequency-stable", "unstable", "chosen"}));
  }

  void markersPerStabilityClass() {
    const StabilisationDiagram diagram = sampleDiagram();
    StabilisationDiagramView view;
    const std::vector<double> f{0.0, 500.0, 1000.0, 1500.0};
    view.setDiagram(diagram, f, {1e-7, 2e-6, 1e-7, 3e-7});
    QCOMPARE(view.markerCount(PoleStability::Stable), count(diagram, PoleStability::Stable));
    QCOMPARE(view.markerCount(PoleStability::FrequencyStable), count(diagram, PoleStability::FrequencyStable));
    QCOMPARE(view.markerCount(PoleStability::Unstable), count(diagram, PoleStability::Unstable));
    QCOMPARE(view.markerCount(PoleStability::Stable), 5);
    QCOMPARE(view.markerCount(PoleStability::FrequencyStable), 1);
    QCOMPARE(view.markerCount(PoleStability::Unstable), 6);
    QCOMPARE(view.magnitudePointCount(), 4);
    view.clear();
    QCOMPARE(view.markerCount(PoleStability::Stable), 0);
    QCOMPARE(view.magnitudePointCount(), 0);
  }

  void toggleSelectsAndDeselects() {
    const StabilisationDiagram diagram = sampleDiagram();
    StabilisationDiagramView view;
    view.setDiagram(diagram, {}, {});
    int emitted = 0;
    std::vector<C> last;
    connect(&view, &StabilisationDiagramView::selectionChanged, this, [&emitted, &last](const std::vector<C>& poles) {
      ++emitted;
      last = poles;
    });
    QVERIFY(view.togglePoleNear(500.9, 8.0));
    QCOMPARE(view.selectedPoles(), std::vector<C>{diagram.orders[3].poles[0].lambda});
    QCOMPARE(last, view.selectedPoles());
    QCOMPARE(view.chosenMarkerCount(), 1);
    QVERIFY(view.togglePoleNear(1198.4, 8.0));
    QCOMPARE(view.selectedPoles().size(), std::size_t{2});
    QVERIFY(view.togglePoleNear(500.8, 8.0));  // the same pole again: taken back
    QCOMPARE(view.selectedPoles(), std::vector<C>{diagram.orders[3].poles[2].lambda});
    QCOMPARE(emitted, 3);
    QVERIFY(!view.togglePoleNear(700.0, 1.0));  // nothing within 10 px
    QCOMPARE(emitted, 3);
  }

  // The 500 Hz poles of orders 4 and 8 are 0.08 % apart: choosing one replaces the other. The
  // 1200 Hz pole is not within 1 % and stays.
  void choiceReplacesWithinOnePercent() {
    const StabilisationDiagram diagram = sampleDiagram();
    StabilisationDiagramView view;
    view.setDiagram(diagram, {}, {});
    QVERIFY(view.togglePoleNear(1198.4, 8.0));
    QVERIFY(view.togglePoleNear(500.8, 8.0));
    QVERIFY(view.togglePoleNear(500.4, 4.0));
    const std::vector<C> expected{diagram.orders[1].poles[0].lambda, diagram.orders[3].poles[2].lambda};
    QCOMPARE(view.selectedPoles(), expected);
  }

  void setSelectedPolesShowsRingsSilently() {
    const StabilisationDiagram diagram = sampleDiagram();
    StabilisationDiagramView view;
    view.setDiagram(diagram, {}, {});
    int emitted = 0;
    connect(&view, &StabilisationDiagramView::selectionChanged, this, [&emitted] { ++emitted; });
    view.setSelectedPoles({diagram.orders[2].poles[0].lambda, pole(1500.0, 0.02, PoleStability::Stable).lambda});
    QCOMPARE(view.chosenMarkerCount(), 2);
    QCOMPARE(view.selectedPoles().size(), std::size_t{2});
    QCOMPARE(emitted, 0);
    view.setDiagram(diagram, {}, {});  // a new diagram starts without a choice
    QVERIFY(view.selectedPoles().empty());
  }

  // With the view laid out, the pick radius is in the plot's pixels.
  void pickRadiusInPixels() {
    StabilisationDiagramView view;
    view.resize(1000, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setDiagram(sampleDiagram(), {}, {});
    QTest::qWait(50);                           // the queued replot lays the plot out for the diagram's ranges
    QVERIFY(!view.togglePoleNear(540.0, 8.0));  // 39 Hz of 700 Hz over ~900 px: ~50 px away
    QVERIFY(view.togglePoleNear(504.0, 8.0));   // ~4 px away
  }
};

MX_REGISTER_TEST(TestStabilisationDiagramView)
#include "test_stabilisation_diagram_view.moc"
