// GUI benchmark (QtTest QBENCHMARK, not a CTest gate): the latency of one drag step on the lobe chart,
// from the mouse-move event to the readouts of the new point, computed on the readout thread and shown
// with the marker (target: 16 ms or less).
// Run: QT_QPA_PLATFORM=offscreen build/release/bench/millexpert-gui-bench
#include <QApplication>
#include <QSignalSpy>
#include <QtTest>

#include "lobes_feature.h"
#include "main_window.h"
#include "simulation_feature.h"

class BenchDrag : public QObject {
  Q_OBJECT
 private slots:
  void dragStepUpdatesReadouts() {
    mx::gui::MainWindow window;
    window.setQuiet(true);
    window.resize(1600, 950);
    window.show();
    auto* lobes = window.findChild<mx::gui::LobesFeature*>("lobesFeature");
    auto* simulation = window.findChild<mx::gui::SimulationFeature*>("simulationFeature");
    QSignalSpy shown(lobes, &mx::gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(MX_DEFAULT_PROJECT));
    QVERIFY(shown.wait(20000));
    QSignalSpy simulated(simulation, &mx::gui::SimulationFeature::simulationShown);
    QVERIFY(simulated.wait(20000));  // the first simulation of the initial point is done
    QWidget* plot = lobes->chart()->plotWidget();
    const QPoint a = lobes->chart()->pixelFor(2000.0, 0.2), b = lobes->chart()->pixelFor(5000.0, 0.5);
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, a);
    int i = 0;
    QBENCHMARK {
      const QPoint p = (i++ % 2) ? a : b;
      QTest::mouseMove(plot, p);
      QCoreApplication::processEvents();  // marker repaint on the overlay layer
      while (!lobes->readoutIsCurrent()) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, a);
    QVERIFY(!lobes->readout()->text("blim").isEmpty());
  }
};

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  BenchDrag bench;
  return QTest::qExec(&bench, argc, argv);
}
#include "bench_drag.moc"
