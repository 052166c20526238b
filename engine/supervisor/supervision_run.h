#pragma once
// Supervised face-milling run (Landers & Ulsoy): the face-milling process (A1-A12) sampled every 0.5 ms,
// the machining modules A-L on the multi-rate scheduler, and a SupervisorLogic (the Grafcet chart of
// SMC I, SMC II or the no-control baseline) scanned every scan_period_s, over a part program of passes.
// Each pass moves the tool from `approach_m` before the part's leading edge (tool edge) to the same
// clearance past its trailing edge; between passes the tool returns at the maximum feed rate (time
// counted, not simulated). Operator events are timed. docs/supervision-notes.md gives every choice.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "supervisor/face_milling_process.h"
#include "supervisor/machining_modules.h"
#include "supervisor/operator_event_queue.h"
#include "supervisor/supervision_metrics.h"
#include "supervisor/supervisor_logic.h"

namespace mx {

enum class SupervisionController { None, SmcI, SmcII };
std::string controllerName(SupervisionController c);             // "none", "smc1", "smc2"
SupervisionController parseController(const std::string& name);  // throws InvalidInput
std::vector<double> defaultPassDepths(SupervisionController c);  // none, SMC II: {2 mm}; SMC I: {1, 1 mm}

struct SupervisionResult;

struct SupervisionScenario {
  SupervisionController controller = SupervisionController::None;  // reported; the logic is passed in
  std::vector<double> pass_depths_m{2e-3};
  FaceMillingParameters process;  // tool, structure, part width/position (part start is set here)
  double part_start_x_m = 0.0;    // leading edge of the part on the feed axis
  double part_length_m = 0.1;     // 100 mm bar, 50 mm wide (process.part_width_m)
  double approach_m = 2e-3;       // clearance between the tool edge and the part at start and end
  double programmed_feed_m_per_s = 10e-3;
  MachiningLimits limits;
  double reference_force_N = std::numeric_limits<double>::quiet_NaN();  // NaN: derived from the power limit
  double power_margin = 0.95;                     // F_ref keeps the mean cutting power at this fraction of the limit
  PowerLawForceModel force_model;                 // F_Y = 0.76 d^0.65 f^0.63 kN (SMC I's model; a for SMC II)
  double force_time_constant_s = 0.2;             // module L's closed-loop force time constant (not given)
  ResetFeed force_reset_feed = ResetFeed::Model;  // where module L restarts at contact
  ChatterDetectorSettings chatter_detector;
  double scan_period_s = 0.010;               // supervisor scan (not given by the paper; = the fastest module)
  double sample_period_s = 5e-4;              // force sampling (Table 1)
  double record_period_s = 2e-3;              // time-series decimation
  double chatter_indicator_threshold = 0.02;  // TDS ground truth: RMS regen / f_t over a revolution
  double max_time_s = 300.0;
  std::vector<OperatorEvent> events;
  // Live runs (the GUI): called at a scan every progress_period_s of simulated time with the result so
  // far (on the running thread); and at every 0.5 ms sample to collect events injected meanwhile
  // (their time is set to the current time).
  std::function<void(const SupervisionResult& so_far, double t_s)> on_progress;
  double progress_period_s = 0.05;
  std::function<void(double t_s, std::vector<OperatorEvent>& injected)> poll_events;
};

void validateSupervisionScenario(const SupervisionScenario& s);  // InvalidInput naming the field

struct SupervisionSample {
  double t_s = 0.0, fy_N = 0.0, F_Y_N = 0.0, power_W = 0.0, feed_m_per_s = 0.0, depth_m = 0.0;
  int pass = 0;
};
struct ActiveStepsRecord {
  double t_s = 0.0;
  std::vector<std::string> steps;  // recorded when the situation changes
};
struct ModuleActivityRecord {
  double t_s = 0.0;
  std::string active;  // module letters, recorded when the set changes
};
struct SupervisionEvent {
  double t_s = 0.0;
  std::string type, detail;
};

struct SupervisionResult {
  std::string controller;
  std::vector<double> final_program_m;  // pass depths after any re-planning
  std::vector<SupervisionSample> series;
  std::vector<ActiveStepsRecord> steps;
  std::vector<ModuleActivityRecord> modules;
  std::vector<SupervisionEvent> events;
  SupervisionMetrics metrics;
};

// F_ref such that the mean cutting power at the reference equals power_margin * P_limit:
// F_ref = margin P_limit / kappa, kappa = P_mean / F_Y of the rigid process at the first depth and the
// programmed feed (F_Y and power scale together along the feed).
double referenceForceFromPower(const SupervisionScenario& s);

// Runs the scenario; logic.reset() first. Throws InvalidInput, Cancelled (job), or runtime_error
// when the run exceeds max_time_s.
SupervisionResult runSupervision(const SupervisionScenario& scenario, SupervisorLogic& logic,
                                 const JobControl& job = {});

}  // namespace mx
