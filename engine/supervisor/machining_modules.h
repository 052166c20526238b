#pragma once
// The machining modules A-L of Landers & Ulsoy, Table 1, as components over a shared MachiningContext
// (the machine-tool controller's data: sampled force, operator inputs, feed command, part program,
// the signals a-e the supervisory logic reads). Each module has a letter and a period (0: event-driven,
// run at every scheduler tick); reset() is the impulse action "X*"; deactivate() runs when its level
// action drops. The ModuleScheduler runs them; it owns them.
//   a feed hold requested (B)       b tool-part contact (J)       c chatter signalled by the operator (D)
//   d chatter detected automatically (E)                          e chatter suppression routine complete (G)
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/model_based_force_loop.h"
#include "control/rls_estimator.h"

namespace mx {

struct MachiningLimits {
  double max_feed_rate_m_per_s = 36e-3;
  double max_feed_per_tooth_m = 0.6e-3;
  double spindle_power_limit_W = 745.7;
};

struct MachiningContext {
  double t_s = 0.0;
  // Machine and operation (fixed parameter modules).
  int teeth = 4;
  double spindle_rev_per_s = 25.0;
  double sample_period_s = 5e-4;
  MachiningLimits limits;
  double reference_force_N = 150.0;
  double programmed_feed_m_per_s = 10e-3;
  // Measurements: F_y samples of the last spindle revolution (newest at the back) and the feed applied.
  std::deque<double> fy_samples;
  std::deque<double> feed_samples;
  // Operator inputs (keyboard).
  bool operator_feed_hold = false;
  bool operator_chatter_key = false;  // latched until the suppression routine completes
  // Signals of the state supervisor.
  bool a = false, b = false, c = false, d = false, e = false;
  double F_Y_N = 0.0;              // force signal processor output
  double chatter_indicator = 0.0;  // automatic chatter detector: peak non-harmonic amplitude [N]
  double estimated_gain = 0.0;     // H: K d^b of F_Y = K d^b f^a [N / mm^a]
  bool gain_valid = false;
  bool estimator_restart = false;  // K* asks H to start its estimate afresh
  // Feed.
  bool feed_hold = false;       // C, or the hold of G
  bool override_valid = false;  // a force controller has set override_feed
  double override_feed_m_per_s = 0.0;
  double commanded_feed_m_per_s = 10e-3;  // A's output, applied to the feed drive
  // Part program: remaining pass depths; the current pass is passes[current_pass].
  std::vector<double> passes_m;
  int current_pass = 0;
  bool replanned = false;  // F rewrote the program (the driver adapts the process depth)
  // Event log hook (t, type, detail).
  std::function<void(double, const std::string&, const std::string&)> log;

  double currentDepth() const;
  void report(const std::string& type, const std::string& detail) const {
    if (log) log(t_s, type, detail);
  }
};

class MachiningModule {
 public:
  MachiningModule(char letter, std::string name, double period_s)
      : letter_(letter), name_(std::move(name)), period_(period_s) {}
  virtual ~MachiningModule() = default;
  char letter() const { return letter_; }
  const std::string& name() const { return name_; }
  double period() const { return period_; }  // s; 0 = every tick
  virtual void run(MachiningContext& ctx) = 0;
  virtual void reset(MachiningContext&) {}
  virtual void deactivate(MachiningContext&) {}
  virtual void activate(MachiningContext&) {}  // its level action has just risen

 private:
  char letter_;
  std::string name_;
  double period_;
};

class FeedrateRoutine : public MachiningModule {  // A, 10 ms
 public:
  FeedrateRoutine() : MachiningModule('A', "feedrate routine", 0.010) {}
  void run(MachiningContext& ctx) override;
};

class OperatorInputMonitor : public MachiningModule {  // B, 10 ms
 public:
  OperatorInputMonitor() : MachiningModule('B', "operator input monitor", 0.010) {}
  void run(MachiningContext& ctx) override;
};

class FeedHold : public MachiningModule {  // C, event-driven
 public:
  FeedHold() : MachiningModule('C', "feed hold", 0.0) {}
  void run(MachiningContext& ctx) override { ctx.feed_hold = true; }
  void deactivate(MachiningContext& ctx) override { ctx.feed_hold = false; }
};

class OperatorChatterDetector : public MachiningModule {  // D, event-driven
 public:
  OperatorChatterDetector() : MachiningModule('D', "operator chatter detector", 0.0) {}
  void run(MachiningContext& ctx) override;
};

struct ChatterDetectorSettings {
  double threshold_N = 40.0;  // peak amplitude of F_y at frequencies that are not tooth harmonics
};

class AutomaticChatterDetector : public MachiningModule {  // E, 40 ms
 public:
  explicit AutomaticChatterDetector(ChatterDetectorSettings s = {});
  void run(MachiningContext& ctx) override;
  void reset(MachiningContext& ctx) override;
  // Peak one-sided amplitude [N] over the non-tooth-harmonic DFT bins of one revolution of samples.
  static double nonHarmonicAmplitude(const std::deque<double>& samples, int teeth);

 private:
  ChatterDetectorSettings s_;
  double armed_at_ = 0.0;  // after a reset, judge only a window of fresh samples (one revolution)
};

class ChatterSuppressor : public MachiningModule {  // F, invoked by G
 public:
  ChatterSuppressor() : MachiningModule('F', "chatter suppressor", 0.0) {}
  void run(MachiningContext& ctx) override;  // current and remaining depth over one more pass, equal depths
};

class ChatterSuppressionRoutine : public MachiningModule {  // G, event-driven
 public:
  explicit ChatterSuppressionRoutine(double hold_s = 0.2)
      : MachiningModule('G', "chatter suppression routine", 0.0), hold_s_(hold_s) {}
  void run(MachiningContext& ctx) override;
  void reset(MachiningContext& ctx) override;
  void deactivate(MachiningContext& ctx) override;

 private:
  ChatterSuppressor suppressor_;
  double hold_s_;
  double started_ = -1.0;
};

class ParameterEstimator : public MachiningModule {  // H, 40 ms
 public:
  explicit ParameterEstimator(double feed_exponent = 0.63, double forgetting = 0.8);
  void run(MachiningContext& ctx) override;
  void reset(MachiningContext& ctx) override;

 private:
  double a_;
  RlsSettings rls_settings_;
  RlsEstimator rls_;
};

class ForceSignalProcessor : public MachiningModule {  // I, 40 ms
 public:
  ForceSignalProcessor() : MachiningModule('I', "force signal processor", 0.040) {}
  void run(MachiningContext& ctx) override;
  // Re-activated (after a feed hold): F_Y holds until a whole revolution of fresh samples is in.
  void activate(MachiningContext& ctx) override { armed_at_ = ctx.t_s + 1.0 / ctx.spindle_rev_per_s; }
  void reset(MachiningContext& ctx) override { activate(ctx); }

 private:
  double armed_at_ = 0.0;
};

class ContactMonitor : public MachiningModule {  // J, 40 ms
 public:
  explicit ContactMonitor(double threshold_N = 50.0)
      : MachiningModule('J', "contact monitor", 0.040), threshold_(threshold_N) {}
  void run(MachiningContext& ctx) override { ctx.b = ctx.F_Y_N > threshold_; }

 private:
  double threshold_;
};

class AdaptiveForceController : public MachiningModule {  // K, 40 ms
 public:
  explicit AdaptiveForceController(double feed_exponent = 0.63)
      : MachiningModule('K', "adaptive force controller", 0.040), a_(feed_exponent) {}
  void run(MachiningContext& ctx) override;
  void reset(MachiningContext& ctx) override {  // K*: the controller and its estimate start afresh
    ctx.override_valid = false;
    ctx.gain_valid = false;
    ctx.estimator_restart = true;
  }
  void deactivate(MachiningContext& ctx) override { ctx.override_valid = false; }

 private:
  double a_;
};

// The loop's own parameters; the model, reference force, teeth and limits come from the context.
struct ModelBasedForceModuleSettings {
  PowerLawForceModel model;
  double time_constant_s = 0.2;  // closed-loop force time constant
  ResetFeed reset_feed = ResetFeed::Model;
};

class ModelBasedForceModule : public MachiningModule {  // L, 40 ms
 public:
  explicit ModelBasedForceModule(ModelBasedForceModuleSettings settings = {})
      : MachiningModule('L', "model-based force controller", 0.040), settings_(settings) {}
  void run(MachiningContext& ctx) override;
  void reset(MachiningContext& ctx) override;  // L* at contact: the loop restarts (ResetFeed)
  void deactivate(MachiningContext& ctx) override { ctx.override_valid = false; }

 private:
  ModelBasedForceLoop makeLoop(const MachiningContext& ctx) const;

  ModelBasedForceModuleSettings settings_;
  std::optional<ModelBasedForceLoop> loop_;
};

// All twelve modules, in the order the scheduler runs them within a tick (signal chain first, feed last).
std::vector<std::unique_ptr<MachiningModule>> makeStandardModules(ChatterDetectorSettings chatter = {},
                                                                  ModelBasedForceModuleSettings force = {});

}  // namespace mx
