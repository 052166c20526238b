#include "simulation_job.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "core/cancellation.h"
#include "simulation/milling_simulation.h"
#include "simulation/smith_tlusty.h"
#include "spectrum_plot.h"

namespace mx::gui {

namespace {
QVector<double> toQVector(std::span<const double> values) {
  return QVector<double>(values.begin(), values.end());
}
}  // namespace

SimulationChunkData copyChunk(const SimulationChunk& chunk) {
  SimulationChunkData out;
  out.revolution = chunk.revolution;
  out.revolutions = chunk.revolutions;
  out.first_index = static_cast<qsizetype>(chunk.first_index);
  out.time_s = toQVector(chunk.time_s);
  out.x_m = toQVector(chunk.x_m);
  out.y_m = toQVector(chunk.y_m);
  out.force_n = toQVector(chunk.force_n);
  out.power_w = toQVector(chunk.power_w);
  return out;
}

SimulationSummary summarizeSimulation(const SimulationJobInput& input, const SimulationResult& result,
                                      std::size_t window_first_index) {
  const ChatterIndicators& ind = result.indicators;
  SimulationSummary s;
  s.spindle_rpm = revPerSToRpm(input.point.spindle_rev_per_s);
  s.teeth = input.setup.teeth;
  s.spindle_power_limit_w = input.spindle_power_limit_w;
  s.eta = ind.eta;
  s.chip_ratio = ind.chip_ratio;
  s.eta_threshold = input.options.eta_threshold;
  s.chip_ratio_threshold = input.options.chip_ratio_threshold;
  s.chatter_by_eta = ind.chatter_by_eta;
  s.chatter_by_chip_ratio = ind.chatter_by_chip_ratio;
  s.chatter = ind.chatter;
  s.chatter_frequency_hz = ind.chatter_frequency_hz;
  s.tooth_passing_hz = ind.tooth_passing_hz;
  s.a_chatter_n = ind.a_chatter;
  s.a_toothpass_n = ind.a_toothpass;
  s.peak_force_n = ind.peak_force_n;
  s.peak_power_w = ind.peak_power_w;
  s.power_limit_exceeded = input.spindle_power_limit_w > 0.0 && ind.peak_power_w > input.spindle_power_limit_w;
  s.simulated_revolutions = result.simulated_revolutions;
  s.evaluated_revolutions = input.options.evaluated_revolutions;
  s.diverged = result.diverged;

  if (ind.chatter && ind.chatter_frequency_hz) {
    const double max_rev =
        input.max_spindle_rev_per_s > 0.0 ? input.max_spindle_rev_per_s : std::numeric_limits<double>::infinity();
    if (const auto choice = smithTlustyChoice(*ind.chatter_frequency_hz, input.setup.teeth,
                                              input.point.spindle_rev_per_s, 0.0, max_rev);
        choice && choice->rev_per_s > 0.0) {
      s.suggested_rpm = revPerSToRpm(choice->rev_per_s);
      s.suggested_k = choice->k;
    }
  }

  // The recorded trace is uniform at dt * record_every.
  const std::vector<double>& force = result.trace.force_n;
  const std::size_t first = std::min(window_first_index, force.size());
  const double rate = 1.0 / (result.dt_s * input.options.record_every);
  if (force.size() - first >= 4 && std::isfinite(rate) && rate > 0.0) {
    const widgets::SpectrumSeries spectrum = widgets::SpectrumPlot::computeSpectrum(
        std::span<const double>(force).subspan(first), rate, ind.tooth_passing_hz, ind.largest_nonharmonic_hz);
    s.spectrum_hz = spectrum.hz;
    s.spectrum_n = spectrum.amplitude;
  }
  return s;
}

SimulationSummary runSimulationJob(const SimulationJobInput& input, const std::atomic<bool>& cancel,
                                   const ChunkSink& sink) {
  JobControl control;
  control.cancel = &cancel;
  if (control.cancelled()) throw Cancelled();
  // Trace index where each revolution's samples begin: the evaluated window starts at one of them.
  std::vector<std::size_t> revolution_starts;
  revolution_starts.reserve(static_cast<std::size_t>(std::max(input.options.revolutions, 0)));
  SimulationOptions options = input.options;
  options.on_chunk = [&](const SimulationChunk& chunk) {
    revolution_starts.push_back(chunk.first_index);
    if (sink && !control.cancelled()) sink(copyChunk(chunk));
  };
  const SimulationResult result = simulateMilling(input.setup, input.point, options, control);
  if (control.cancelled()) throw Cancelled();
  const std::size_t evaluated = static_cast<std::size_t>(input.options.evaluated_revolutions);
  const std::size_t window_first = revolution_starts.size() > evaluated
                                       ? revolution_starts[revolution_starts.size() - evaluated]
                                       : (revolution_starts.empty() ? 0 : revolution_starts.front());
  return summarizeSimulation(input, result, window_first);
}

}  // namespace mx::gui
