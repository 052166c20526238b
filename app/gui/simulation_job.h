#pragma once
// The simulation job: inputs copied from the GUI, run on the engine thread (mx::simulateMilling), each
// revolution's samples copied out for the live view, then summarised (indicators, Smith-Tlusty speed,
// force spectrum of the evaluated window) for the GUI.
#include <atomic>
#include <cstddef>
#include <functional>
#include <limits>

#include "model/milling_setup.h"
#include "simulation/simulation_types.h"
#include "simulation_data.h"

namespace mx::gui {

struct SimulationJobInput {
  MillingSetup setup;
  OperatingPoint point;
  SimulationOptions options;           // options.on_chunk is replaced by the job's own
  double spindle_power_limit_w = 0.0;  // <= 0: no limit
  double max_spindle_rev_per_s = std::numeric_limits<double>::infinity();  // <= 0 or inf: unbounded
};

// Called on the engine thread with an owned copy of every revolution's samples.
using ChunkSink = std::function<void(SimulationChunkData&&)>;

// Runs on the calling (engine) thread. Throws mx::Cancelled once `cancel` is set (polled every
// revolution) and mx::InvalidInput for invalid inputs.
SimulationSummary runSimulationJob(const SimulationJobInput& input, const std::atomic<bool>& cancel,
                                   const ChunkSink& sink);

SimulationChunkData copyChunk(const SimulationChunk& chunk);

// The summary of a finished run; `window_first_index` is the trace index where the evaluated window
// (the last evaluated_revolutions revolutions reached) begins.
SimulationSummary summarizeSimulation(const SimulationJobInput& input, const SimulationResult& result,
                                      std::size_t window_first_index);

}  // namespace mx::gui
