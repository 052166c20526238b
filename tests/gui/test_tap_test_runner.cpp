// The tap-test runner: a file read and a fit on the engine pool, back on the GUI thread with progress;
// a cancel before the fit starts ends it as cancelled; a newer request makes an older result stale.
#include <QSemaphore>
#include <QSignalSpy>
#include <QThreadPool>

#include "frf/uff_writer.h"
#include "support/frf_samples.h"
#include "tap_test_runner.h"
#include "test_registry.h"

using namespace mx;

namespace {

const ModalAxis kModes{{700.0, 0.03, 8e6}, {1650.0, 0.02, 2.2e7}};

Receptance receptanceOf(const ModalAxis& modes) {
  const FrfDataset d = test::modalFrf(modes, FrfQuantity::Receptance, test::evenFrequencies(1.0, 1.0, 2500));
  return toReceptance(d);
}

widgets::TapTestFitRequest automatic() {
  widgets::TapTestFitRequest r;
  r.direction = "x";
  r.from_hz = 1.0;
  r.to_hz = 2500.0;
  return r;
}

}  // namespace

class TestTapTestRunner : public QObject {
  Q_OBJECT
 private slots:
  void loadsAFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("t.uff");
    test::writeBytes(
        path.toStdString(),
        uff58bString({test::modalFrf(kModes, FrfQuantity::Mobility, test::evenFrequencies(0.0, 1.0, 100))}));
    QThreadPool pool;
    gui::TapTestRunner runner(&pool);
    QSignalSpy loaded(&runner, &gui::TapTestRunner::loaded);
    QSignalSpy failed(&runner, &gui::TapTestRunner::failed);
    const quint64 g = runner.load(path, std::nullopt);
    QVERIFY(loaded.wait(10000));
    QCOMPARE(loaded.at(0).at(0).toULongLong(), g);
    const auto file = loaded.at(0).at(1).value<gui::TapTestFile>();
    QCOMPARE(file.file.format, FrfFormat::Uff58b);
    QCOMPARE(file.file.datasets.at(0).quantity, FrfQuantity::Mobility);
    runner.load(dir.filePath("none.uff"), std::nullopt);
    QVERIFY(failed.wait(10000));
    QVERIFY(failed.at(0).at(1).toString().contains("none.uff"));
  }

  void fitsWithProgress() {
    QThreadPool pool;
    gui::TapTestRunner runner(&pool);
    QSignalSpy fitted(&runner, &gui::TapTestRunner::fitted);
    QSignalSpy progress(&runner, &gui::TapTestRunner::progress);
    QSignalSpy busy(&runner, &gui::TapTestRunner::busyChanged);
    runner.fit(receptanceOf(kModes), automatic());
    QVERIFY(fitted.wait(20000));
    const auto fit = fitted.at(0).at(1).value<gui::TapTestFit>();
    QCOMPARE(fit.result.modes.size(), kModes.size());
    for (std::size_t i = 0; i < kModes.size(); ++i)
      QCOMPARE_LE(std::abs(fit.result.modes[i].natural_frequency_hz / kModes[i].natural_frequency_hz - 1.0), 1e-6);
    QVERIFY(!fit.at_poles);
    QVERIFY(progress.count() >= 2);
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);
    QCOMPARE(busy.count(), 2);
    QVERIFY(!runner.busy());
  }

  // With the pool's only thread held, the fit cannot start before cancel(): it ends as cancelled.
  void cancelBeforeStart() {
    QThreadPool pool;
    pool.setMaxThreadCount(1);
    QSemaphore release;
    pool.start([&release] { release.acquire(); });
    gui::TapTestRunner runner(&pool);
    QSignalSpy cancelled(&runner, &gui::TapTestRunner::cancelled);
    QSignalSpy fitted(&runner, &gui::TapTestRunner::fitted);
    const quint64 g = runner.fit(receptanceOf(kModes), automatic());
    runner.cancel();
    release.release();
    QVERIFY(cancelled.wait(20000));
    QCOMPARE(cancelled.at(0).at(0).toULongLong(), g);
    QCOMPARE(fitted.count(), 0);
  }

  // Fits at chosen poles; an older fit's result is dropped once a newer one is asked for.
  void polesAndStaleness() {
    QThreadPool pool;
    pool.setMaxThreadCount(1);
    gui::TapTestRunner runner(&pool);
    QSignalSpy fitted(&runner, &gui::TapTestRunner::fitted);
    widgets::TapTestFitRequest at_poles = automatic();
    for (const Mode& m : kModes) {
      const double w = 2.0 * std::numbers::pi * m.natural_frequency_hz;
      at_poles.poles.emplace_back(-m.damping_ratio * w, w * std::sqrt(1.0 - m.damping_ratio * m.damping_ratio));
    }
    runner.fit(receptanceOf(kModes), automatic());
    const quint64 newer = runner.fit(receptanceOf(kModes), at_poles);
    QVERIFY(fitted.wait(20000));
    QTest::qWait(100);
    QCOMPARE(fitted.count(), 1);
    QCOMPARE(fitted.at(0).at(0).toULongLong(), newer);
    const auto fit = fitted.at(0).at(1).value<gui::TapTestFit>();
    QVERIFY(fit.at_poles);
    for (std::size_t i = 0; i < kModes.size(); ++i)
      QCOMPARE_LE(std::abs(fit.result.modes[i].stiffness_n_per_m / kModes[i].stiffness_n_per_m - 1.0), 1e-6);
  }
};

MX_REGISTER_TEST(TestTapTestRunner)
#include "test_tap_test_runner.moc"
