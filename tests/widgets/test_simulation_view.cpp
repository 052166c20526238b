// SimulationView: chunks stream into the plots (coalesced repaints), memory stays bounded by the ring
// buffers, the summary shows the verdict and a one-click move to the Smith-Tlusty speed.
#include <QApplication>
#include <QPushButton>
#include <QSignalSpy>
#include <QThreadPool>
#include <cmath>

#include "simulation_runner.h"
#include "simulation_view.h"
#include "support/fixtures.h"
#include "test_registry.h"

using mx::gui::SimulationChunkData;
using mx::gui::SimulationSummary;
using mx::widgets::SimulationView;

namespace {
// One revolution of synthetic samples starting at sample `first` (dt = 10 us).
SimulationChunkData syntheticChunk(int revolution, int samples) {
  SimulationChunkData c;
  c.revolution = revolution;
  c.revolutions = 1000;
  c.first_index = static_cast<qsizetype>(revolution - 1) * samples;
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(c.first_index + i) * 1e-5;
    c.time_s.push_back(t);
    c.x_m.push_back(1e-5 * std::sin(2.0 * M_PI * 600.0 * t));
    c.y_m.push_back(-1e-5 * std::cos(2.0 * M_PI * 600.0 * t));
    c.force_n.push_back(500.0 + 100.0 * std::sin(2.0 * M_PI * 290.0 * t));
    c.power_w.push_back(700.0 + 20.0 * std::sin(2.0 * M_PI * 290.0 * t));
  }
  return c;
}

SimulationSummary chatterSummary() {
  SimulationSummary s;
  s.spindle_rpm = 5800.0;
  s.teeth = 3;
  s.spindle_power_limit_w = 15000.0;
  s.eta = 2.4;
  s.chip_ratio = 3.1;
  s.chatter = s.chatter_by_eta = s.chatter_by_chip_ratio = true;
  s.chatter_frequency_hz = 641.4;
  s.tooth_passing_hz = 290.0;
  s.suggested_rpm = 6414.0;  // 60 * 641.4 / (3 * 2)
  s.suggested_k = 2;
  s.simulated_revolutions = 60;
  s.evaluated_revolutions = 20;
  for (int i = 0; i <= 300; ++i) {
    s.spectrum_hz.push_back(5.0 * i);
    s.spectrum_n.push_back(i == 58 ? 120.0 : 1.0);
  }
  return s;
}
}  // namespace

class TestSimulationView : public QObject {
  Q_OBJECT
 private slots:
  void chunksReachThePlots() {
    SimulationView view;
    view.resize(1600, 900);
    view.show();
    view.beginRun(15000.0, 3, 290.0);
    QCOMPARE(view.sampleCount(), 0);
    const int flushes = view.flushCount();
    for (int r = 1; r <= 5; ++r) view.appendChunk(syntheticChunk(r, 300));
    QCOMPARE(view.sampleCount(), 1500);
    QVERIFY(view.replotPending());  // coalesced: no repaint per chunk
    QTRY_COMPARE(view.plottedSampleCount(), 1500);
    QCOMPARE(view.flushCount(), flushes + 1);
    QCOMPARE(view.latestTime(), 1499 * 1e-5);
    QVERIFY(!view.chatterShown());
    QVERIFY(view.suggestedSpeedText().isEmpty());
    // While running, the spectrum of the latest samples follows a few times a second.
    QCOMPARE(view.spectrumPointCount(), 0);
    QTest::qWait(300);
    view.appendChunk(syntheticChunk(6, 300));
    QTRY_VERIFY(view.spectrumPointCount() > 10);  // 1800 samples at 100 kHz: 55.6 Hz bins up to 5 f_tp
  }

  void memoryStaysBoundedByTheRingBuffer() {
    SimulationView view(nullptr, 2000);
    QCOMPARE(view.capacity(), std::size_t{2000});
    view.beginRun(15000.0, 3, 290.0);
    // 10x the capacity, as a long simulation would send.
    for (int r = 1; r <= 100; ++r) view.appendChunk(syntheticChunk(r, 200));
    QCOMPARE(view.sampleCount(), 2000);
    QCOMPARE(view.latestTime(), (100 * 200 - 1) * 1e-5);
    QTRY_COMPARE(view.plottedSampleCount(), 2000);
    // A single chunk longer than the buffer keeps its tail.
    view.appendChunk(syntheticChunk(101, 5000));
    QCOMPARE(view.sampleCount(), 2000);
    QCOMPARE(view.latestTime(), (100 * 5000 + 4999) * 1e-5);
    QCOMPARE(SimulationView::kDefaultCapacity, std::size_t{20000});
  }

  // 60 revolutions of 300 samples: each time trace is a min/max band of 2 points per tooth period
  // (3.4 ms, longer than a pixel column) whose extremes are exactly the samples'; zoomed in to a few
  // periods it is the samples themselves.
  void longRunDrawsEnvelopes() {
    using Trace = SimulationView::Trace;
    SimulationView view;
    view.resize(1920, 500);
    view.show();
    view.beginRun(15000.0, 3, 290.0);
    double x_lo = 0.0, x_hi = 0.0, f_lo = 1e9, f_hi = 0.0;
    for (int r = 1; r <= 60; ++r) {
      const SimulationChunkData c = syntheticChunk(r, 300);
      for (int i = 0; i < c.x_m.size(); ++i) {
        x_lo = std::min(x_lo, c.x_m[i] * 1e6);
        x_hi = std::max(x_hi, c.x_m[i] * 1e6);
        f_lo = std::min(f_lo, c.force_n[i]);
        f_hi = std::max(f_hi, c.force_n[i]);
      }
      view.appendChunk(c);
    }
    QTRY_COMPARE(view.plottedSampleCount(), 18000);
    for (Trace t : {Trace::X, Trace::Y, Trace::Force, Trace::Power}) {
      QTRY_VERIFY(view.envelopeShown(t));
      QVERIFY(view.plotColumns(t) > 300);
      QVERIFY2(view.drawnPointCount(t) <= 2 * view.plotColumns(t),
               qPrintable(QString("%1 points for %2 columns").arg(view.drawnPointCount(t)).arg(view.plotColumns(t))));
      QCOMPARE(view.envelopeBuckets(t), static_cast<int>(17999e-5 * 290.0));  // whole tooth periods
      QCOMPARE(view.drawnPointCount(t), 2 * view.envelopeBuckets(t));
    }
    QCOMPARE(view.drawnValueRange(Trace::X), std::pair(x_lo, x_hi));
    QCOMPARE(view.drawnValueRange(Trace::Force), std::pair(f_lo, f_hi));

    // Zoomed in to 200 samples (about one period of x): the raw samples.
    view.setTimeRange(0.1, 0.1 + 199e-5);
    QTRY_VERIFY(!view.envelopeShown(Trace::X));
    QVERIFY(!view.envelopeShown(Trace::Power));
    QVERIFY(view.drawnPointCount(Trace::X) >= 200 && view.drawnPointCount(Trace::X) <= 202);
    QVERIFY(view.drawnValueRange(Trace::X).second <= x_hi);
    // Back to the whole run: the band again.
    view.setTimeRange(0.0, 17999e-5);
    QTRY_VERIFY(view.envelopeShown(Trace::X));
    QCOMPARE(view.drawnValueRange(Trace::X), std::pair(x_lo, x_hi));
  }

  // The resultant force is a saturated colour of its own, and its axis says so in the same colour.
  void forceTraceIsSaturatedWithItsAxisInItsColour() {
    using Trace = SimulationView::Trace;
    SimulationView view;
    const QColor force = view.traceColor(Trace::Force);
    QVERIFY2(force.hsvSaturation() >= 150 && force.alpha() == 255, qPrintable(force.name()));
    QCOMPARE(view.axisLabelColor(Trace::Force), force);
    for (Trace t : {Trace::X, Trace::Y, Trace::Power}) QVERIFY(view.traceColor(t) != force);
  }

  void chatterSummaryOffersTheMove() {
    SimulationView view;
    view.show();
    view.beginRun(15000.0, 3, 290.0);
    view.appendChunk(syntheticChunk(1, 300));
    view.setSummary(chatterSummary());
    QVERIFY(view.chatterShown());
    QVERIFY(view.verdictText().contains("CHATTER"));
    QVERIFY(view.verdictText().contains("641.4"));
    QCOMPARE(view.suggestedSpeedText(), QString("Move to 6414 rpm"));
    QCOMPARE(view.spectrumPointCount(), 301);
    QSignalSpy move(&view, &SimulationView::moveToPointRequested);
    auto* button = view.findChild<QPushButton*>("moveToSpeedButton");
    QVERIFY(button && button->isEnabled());
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(move.size(), 1);
    QCOMPARE(move.first().at(0).toDouble(), 6414.0);
    QVERIFY(std::isnan(move.first().at(1).toDouble()));  // the depth stays

    // No stable speed at this depth: the button moves to the pocket's speed and its deepest stable depth.
    SimulationSummary shallower = chatterSummary();
    shallower.suggested_rpm = 3400.0;
    shallower.suggested_depth_mm = 0.912;
    shallower.suggestion_note = "No speed in 800-5800 rpm is stable at 1.206 mm";
    view.setSummary(shallower);
    QCOMPARE(view.suggestedSpeedText(), QString("Move to 3400 rpm, b = 0.9120 mm"));
    QCOMPARE(view.suggestionNote(), shallower.suggestion_note);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(move.size(), 2);
    QCOMPARE(move.last().at(1).toDouble(), 0.912);

    // A stable run: no suggestion, the button does nothing.
    SimulationSummary stable = chatterSummary();
    stable.chatter = stable.chatter_by_eta = stable.chatter_by_chip_ratio = false;
    stable.eta = 1.02;
    stable.chip_ratio = 1.01;
    stable.chatter_frequency_hz.reset();
    stable.suggested_rpm.reset();
    view.beginRun(15000.0, 3, 290.0);
    view.setSummary(stable);
    QVERIFY(!view.chatterShown());
    QVERIFY(view.verdictText().contains("STABLE"));
    QVERIFY(view.suggestedSpeedText().isEmpty());
    QVERIFY(!button->isEnabled());
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(move.size(), 2);  // no new move
  }

  void clearEmptiesTheView() {
    SimulationView view;
    view.beginRun(0.0, 3, 290.0);
    view.appendChunk(syntheticChunk(1, 300));
    view.setSummary(chatterSummary());
    view.clear();
    QCOMPARE(view.sampleCount(), 0);
    QCOMPARE(view.plottedSampleCount(), 0);
    QCOMPARE(view.spectrumPointCount(), 0);
    QVERIFY(!view.chatterShown());
    QVERIFY(view.suggestedSpeedText().isEmpty());
  }

  // End to end on the engine thread: R1 chattering at 5800 rpm, 3 mm streams in and ends with a move.
  void liveRunFromTheRunner() {
    QThreadPool pool;
    pool.setMaxThreadCount(1);
    mx::gui::SimulationRunner runner(&pool);
    SimulationView view;
    view.resize(1920, 1080);
    view.show();
    int chunks_shown_before_summary = -1;
    connect(&runner, &mx::gui::SimulationRunner::chunkReady, &view,
            [&](quint64, const SimulationChunkData& c) { view.appendChunk(c); });
    connect(&runner, &mx::gui::SimulationRunner::finished, &view, [&](quint64, const SimulationSummary& s) {
      chunks_shown_before_summary = view.sampleCount();
      view.setSummary(s);
    });
    const mx::MillingSetup r1 = mx::test::rubioR1();
    const mx::OperatingPoint point{5800.0 / 60.0, 3e-3, 0.1e-3};
    view.beginRun(15000.0, r1.teeth, r1.teeth * point.spindle_rev_per_s);
    mx::SimulationOptions options;
    options.revolutions = 60;
    runner.submit(r1, point, options, 15000.0, 12000.0 / 60.0);
    QTRY_VERIFY_WITH_TIMEOUT(chunks_shown_before_summary >= 0, 60000);
    QVERIFY(chunks_shown_before_summary > 1000);
    QVERIFY(view.chatterShown());
    QVERIFY(view.suggestedSpeedText().startsWith("Move to "));
    QVERIFY(view.suggestedSpeedRpm() > 0.0 && view.suggestedSpeedRpm() <= 12000.0);
    QVERIFY(view.spectrumPointCount() > 50);
    QTRY_COMPARE(view.plottedSampleCount(), view.sampleCount());
    if (qEnvironmentVariableIsSet("MX_SIMVIEW_SCREENSHOT")) {  // for a look at 1080p
      QTest::qWait(100);                                       // the queued replots
      view.grab().save(qEnvironmentVariable("MX_SIMVIEW_SCREENSHOT"));
    }
  }
};

MX_REGISTER_TEST(TestSimulationView)
#include "test_simulation_view.moc"
