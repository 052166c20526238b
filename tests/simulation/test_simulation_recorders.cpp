// The time-domain simulation's recorders: the trace keeps every record_every-th step and hands each
// revolution's samples to on_chunk; the window keeps the maxima per revolution and the signals of
// the last E revolutions the run reached.
#include <cstdint>
#include <vector>

#include "simulation/simulation_recorders.h"
#include "test_registry.h"

using namespace mx;

namespace {
// Step n: t = n / 2, force n, static force 1, chip n / 8, power 100 - n, x = n, y = -n.
StepSample sampleAt(std::int64_t n) {
  const auto v = static_cast<double>(n);
  StepSample s;
  s.n = n;
  s.t_s = 0.5 * v;
  s.x_m = v;
  s.y_m = -v;
  s.fx_n = 2.0 * v;
  s.fy_n = 3.0 * v;
  s.force_n = v;
  s.power_w = 100.0 - v;
  s.chip_m = v / 8.0;
  s.static_force_n = 1.0;
  s.static_chip_m = 0.5;
  return s;
}

struct Chunk {
  int revolution, revolutions;
  std::size_t first, count;
  double first_time;
};
}  // namespace

class TestSimulationRecorders : public QObject {
  Q_OBJECT
 private slots:
  void traceDecimation() {
    SimulationTrace trace;
    trace.time_s = {42.0};  // cleared by the recorder
    SimulationOptions options;
    options.record_every = 3;
    TraceRecorder recorder(trace, options, 10);
    for (std::int64_t n = 0; n < 10; ++n) recorder.record(sampleAt(n));
    QCOMPARE(trace.size(), std::size_t{4});  // steps 0, 3, 6, 9
    QCOMPARE(trace.time_s, (std::vector<double>{0.0, 1.5, 3.0, 4.5}));
    QCOMPARE(trace.x_m, (std::vector<double>{0.0, 3.0, 6.0, 9.0}));
    QCOMPARE(trace.fy_n, (std::vector<double>{0.0, 9.0, 18.0, 27.0}));
    QCOMPARE(trace.power_w, (std::vector<double>{100.0, 97.0, 94.0, 91.0}));
  }

  // One chunk per finished revolution with new samples; none when nothing was recorded since.
  void chunksPerRevolution() {
    std::vector<Chunk> chunks;
    SimulationOptions options;
    options.revolutions = 3;
    options.on_chunk = [&](const SimulationChunk& c) {
      chunks.push_back({c.revolution, c.revolutions, c.first_index, c.time_s.size(), c.time_s.front()});
    };
    SimulationTrace trace;
    TraceRecorder recorder(trace, options, 6);
    for (std::int64_t n = 0; n < 4; ++n) recorder.record(sampleAt(n));
    recorder.finishRevolution(1);
    for (std::int64_t n = 4; n < 6; ++n) recorder.record(sampleAt(n));
    recorder.finishRevolution(2);
    recorder.finishRevolution(3);
    QCOMPARE(chunks.size(), std::size_t{2});
    QCOMPARE(chunks[0].revolution, 1);
    QCOMPARE(chunks[0].revolutions, 3);
    QCOMPARE(chunks[0].first, std::size_t{0});
    QCOMPARE(chunks[0].count, std::size_t{4});
    QCOMPARE(chunks[1].revolution, 2);
    QCOMPARE(chunks[1].first, std::size_t{4});
    QCOMPARE(chunks[1].count, std::size_t{2});
    QCOMPARE(chunks[1].first_time, 2.0);
  }

  // 5 revolutions of 4 steps, E = 2: the window is revolutions 3 and 4 (steps 12 .. 19).
  void windowOfTheLastRevolutions() {
    WindowRecorder recorder(5, 2, 4, 0.5);
    for (std::int64_t n = 0; n < 20; ++n) recorder.record(sampleAt(n));
    const WindowSignals w = recorder.window(20, 5);
    QCOMPARE(w.sample_rate_hz, 2.0);
    QCOMPARE(w.max_force_n, 19.0);
    QCOMPARE(w.max_static_force_n, 1.0);
    QCOMPARE(w.max_chip_m, 19.0 / 8.0);
    QCOMPARE(w.max_static_chip_m, 0.5);
    QCOMPARE(w.peak_power_w, 88.0);
    QCOMPARE(w.force_n, (std::vector<double>{12, 13, 14, 15, 16, 17, 18, 19}));
    QCOMPARE(w.x_m.front(), 12.0);
    QCOMPARE(w.y_m.back(), -19.0);
  }

  // A run stopped inside revolution 3 (after 14 steps, 4 revolutions touched): the window is the last
  // two it reached, revolutions 2 and 3 (steps 8 .. 13).
  void windowAfterAnEarlyStop() {
    WindowRecorder recorder(5, 2, 4, 0.5);
    for (std::int64_t n = 0; n < 14; ++n) recorder.record(sampleAt(n));
    const WindowSignals w = recorder.window(14, 4);
    QCOMPARE(w.force_n, (std::vector<double>{8, 9, 10, 11, 12, 13}));
    QCOMPARE(w.max_force_n, 13.0);
    QCOMPARE(w.peak_power_w, 92.0);
  }

  // Unequal teeth: the reference is the revolution-synchronous average over the complete evaluated
  // revolutions. Revolutions 3 and 4 (steps 12 .. 19): force 12 .. 15 and 16 .. 19 average to 14 .. 17;
  // chips n / 8 to 14 / 8 .. 17 / 8. A window of one complete revolution keeps the rigid reference.
  void synchronousReference() {
    WindowRecorder recorder(5, 2, 4, 0.5, true);
    for (std::int64_t n = 0; n < 20; ++n) recorder.record(sampleAt(n));
    const WindowSignals w = recorder.window(20, 5);
    QCOMPARE(w.max_force_n, 19.0);
    QCOMPARE(w.max_static_force_n, 17.0);
    QCOMPARE(w.max_static_chip_m, 17.0 / 8.0);
    WindowRecorder short_run(5, 1, 4, 0.5, true);
    for (std::int64_t n = 0; n < 20; ++n) short_run.record(sampleAt(n));
    QCOMPARE(short_run.window(20, 5).max_static_force_n, 1.0);
  }
};

MX_REGISTER_TEST(TestSimulationRecorders)
#include "test_simulation_recorders.moc"
