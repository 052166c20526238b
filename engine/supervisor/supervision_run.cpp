#include "supervisor/supervision_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <optional>
#include <stdexcept>

#include "supervisor/module_scheduler.h"
#include "supervisor/operator_event_queue.h"
#include "supervisor/rolling_mean.h"
#include "supervisor/supervision_metrics.h"

namespace mx {

namespace {
void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (!ok) throw InvalidInput("supervision: " + field + " = " + std::to_string(value) + ": must be " + range);
}
}  // namespace

std::string controllerName(SupervisionController c) {
  switch (c) {
    case SupervisionController::SmcI:
      return "smc1";
    case SupervisionController::SmcII:
      return "smc2";
    default:
      return "none";
  }
}

SupervisionController parseController(const std::string& name) {
  if (name == "none") return SupervisionController::None;
  if (name == "smc1") return SupervisionController::SmcI;
  if (name == "smc2") return SupervisionController::SmcII;
  throw InvalidInput("supervision: controller = " + name + ": must be none, smc1 or smc2");
}

std::vector<double> defaultPassDepths(SupervisionController c) {
  return c == SupervisionController::SmcI ? std::vector<double>{1e-3, 1e-3} : std::vector<double>{2e-3};
}

void validateSupervisionScenario(const SupervisionScenario& s) {
  require(!s.pass_depths_m.empty(), "pass_depths_m.size", 0, ">= 1");
  for (double d : s.pass_depths_m) require(std::isfinite(d) && d > 0.0 && d <= 0.02, "pass depth m", d, "in (0, 0.02]");
  validateFaceMillingParameters(s.process);
  require(std::isfinite(s.part_start_x_m), "part_start_x_m", s.part_start_x_m, "finite");
  require(std::isfinite(s.part_length_m) && s.part_length_m > 0.0, "part_length_m", s.part_length_m, "> 0");
  require(std::isfinite(s.approach_m) && s.approach_m >= 0.0, "approach_m", s.approach_m, ">= 0");
  require(std::isfinite(s.programmed_feed_m_per_s) && s.programmed_feed_m_per_s > 0.0, "programmed_feed_m_per_s",
          s.programmed_feed_m_per_s, "> 0");
  require(s.limits.max_feed_rate_m_per_s > 0.0, "limits.max_feed_rate_m_per_s", s.limits.max_feed_rate_m_per_s, "> 0");
  require(s.limits.max_feed_per_tooth_m > 0.0, "limits.max_feed_per_tooth_m", s.limits.max_feed_per_tooth_m, "> 0");
  require(s.limits.spindle_power_limit_W > 0.0, "limits.spindle_power_limit_W", s.limits.spindle_power_limit_W, "> 0");
  require(std::isnan(s.reference_force_N) || s.reference_force_N > 0.0, "reference_force_N", s.reference_force_N,
          "> 0 (or NaN: derived)");
  require(std::isfinite(s.power_margin) && s.power_margin > 0.0 && s.power_margin <= 1.5, "power_margin",
          s.power_margin, "in (0, 1.5]");
  require(std::isfinite(s.sample_period_s) && s.sample_period_s >= 1e-4 && s.sample_period_s <= 0.01, "sample_period_s",
          s.sample_period_s, "in [1e-4, 0.01]");
  require(std::isfinite(s.scan_period_s) && s.scan_period_s >= s.sample_period_s && s.scan_period_s <= 1.0,
          "scan_period_s", s.scan_period_s, "in [sample_period_s, 1]");
  require(std::isfinite(s.record_period_s) && s.record_period_s > 0.0, "record_period_s", s.record_period_s, "> 0");
  require(std::isfinite(s.max_time_s) && s.max_time_s > 0.0, "max_time_s", s.max_time_s, "> 0");
  require(std::isfinite(s.force_time_constant_s) && s.force_time_constant_s >= 1e-3 && s.force_time_constant_s <= 100.0,
          "force_time_constant_s", s.force_time_constant_s, "in [0.001, 100]");
  for (const auto& e : s.events) require(std::isfinite(e.t_s) && e.t_s >= 0.0, "events.t_s", e.t_s, ">= 0");
}

double referenceForceFromPower(const SupervisionScenario& s) {
  if (!std::isnan(s.reference_force_N)) return s.reference_force_N;
  const FaceMillingProcess proc(s.process);
  const double f_t = s.programmed_feed_m_per_s * proc.spindlePeriod() / s.process.teeth;
  const RigidRevolution r = proc.rigidRevolution(s.pass_depths_m.front(), f_t);
  const double kappa = r.power_mean_W / r.fy_max_N;  // m/s
  return s.power_margin * s.limits.spindle_power_limit_W / kappa;
}

namespace {

// The run's sampling: process steps per 0.5 ms sample, and the samples per scan, per spindle
// revolution (the force and feed windows, the regeneration RMS), per tooth period (the mean power)
// and per recorded point.
struct SampleClock {
  long long steps_per_sample = 1;
  double period_s = 0.0;  // Ts
  long long samples_per_scan = 1;
  std::size_t samples_per_rev = 8;
  std::size_t samples_per_tooth = 1;
  long long record_every = 1;
};

SampleClock sampleClock(const SupervisionScenario& sc, const FaceMillingProcess& proc, int teeth) {
  SampleClock c;
  const double period = proc.spindlePeriod();
  c.steps_per_sample = std::max<long long>(1, std::llround(sc.sample_period_s / proc.stepSize()));
  c.period_s = static_cast<double>(c.steps_per_sample) * proc.stepSize();
  c.samples_per_scan = std::max<long long>(1, std::llround(sc.scan_period_s / c.period_s));
  c.samples_per_rev = static_cast<std::size_t>(std::max<long long>(8, std::llround(period / c.period_s)));
  c.samples_per_tooth = static_cast<std::size_t>(std::max<long long>(1, std::llround(period / teeth / c.period_s)));
  c.record_every = std::max<long long>(1, std::llround(sc.record_period_s / c.period_s));
  return c;
}

// Appends v and drops the oldest values beyond the last n.
void keepLast(std::deque<double>& q, double v, std::size_t n) {
  q.push_back(v);
  while (q.size() > n) q.pop_front();
}

// One supervised run: the passes of the part program, each sampled until the tool has crossed the
// part; the supervisor logic is scanned every samples_per_scan samples, the modules tick every sample.
class SupervisedRun {
 public:
  SupervisedRun(const SupervisionScenario& sc, SupervisorLogic& logic, const JobControl& job);
  SupervisedRun(const SupervisedRun&) = delete;  // ctx_.log refers to this run
  SupervisedRun& operator=(const SupervisedRun&) = delete;

  SupervisionResult run();

 private:
  MachiningContext context();  // its log appends to res_.events
  MetricsSettings metricsSettings() const;
  void startPass(std::size_t k);
  void sample(std::size_t k);
  double updateSignals(const FaceMillingOutput& o);
  void applyOperatorEvents();
  void scan(const FaceMillingOutput& o);
  void tickModules();
  void replan(std::size_t k, const FaceMillingOutput& o);
  bool lastPass() const { return ctx_.current_pass + 1 == static_cast<int>(ctx_.passes_m.size()); }

  const SupervisionScenario& sc_;
  SupervisorLogic& logic_;
  const JobControl& job_;
  std::chrono::steady_clock::time_point wall0_ = std::chrono::steady_clock::now();
  SupervisionResult res_;
  FaceMillingParameters part_;  // the scenario's process with the part's position and length
  FaceMillingProcess proc_;
  double R_;       // tool radius
  double period_;  // spindle period
  SampleClock clock_;
  MachiningContext ctx_;
  ModuleScheduler scheduler_;
  OperatorEventQueue events_;
  RollingMean power_;  // cutting power over a tooth period
  RollingMean regen_;  // squared regeneration over a revolution
  SupervisionMetricsAccumulator metrics_;
  double t_ = 0.0;
  long long sample_ = 0;
  double next_progress_ = 0.0;
  bool last_stable_ = true;
  std::vector<std::string> last_steps_;
  std::string last_modules_ = "-";
  std::vector<double> material_start_;  // per pass: where uncut material begins
  double x_begin_, x_end_;              // tool centre at the start and the end of a pass
  double f_nominal_;                    // programmed feed per tooth
};

FaceMillingParameters withPart(const SupervisionScenario& sc) {
  FaceMillingParameters p = sc.process;
  p.part_start_x_m = sc.part_start_x_m;
  p.part_length_m = sc.part_length_m;
  return p;
}

SupervisedRun::SupervisedRun(const SupervisionScenario& sc, SupervisorLogic& logic, const JobControl& job)
    : sc_(sc),
      logic_(logic),
      job_(job),
      part_(withPart(sc)),
      proc_(part_),
      R_(part_.tool_radius_m),
      period_(proc_.spindlePeriod()),
      clock_(sampleClock(sc, proc_, part_.teeth)),
      ctx_(context()),
      scheduler_(
          makeStandardModules(sc.chatter_detector, {sc.force_model, sc.force_time_constant_s, sc.force_reset_feed})),
      events_(sc.events),
      power_(clock_.samples_per_tooth),
      regen_(clock_.samples_per_rev),
      metrics_(metricsSettings()),
      material_start_(1, sc.part_start_x_m),
      x_begin_(sc.part_start_x_m - R_ - sc.approach_m),
      x_end_(sc.part_start_x_m + sc.part_length_m + R_ + sc.approach_m),
      f_nominal_(sc.programmed_feed_m_per_s * period_ / part_.teeth) {
  res_.controller = controllerName(sc.controller);
  logic_.reset();
}

MachiningContext SupervisedRun::context() {
  MachiningContext ctx;
  ctx.teeth = part_.teeth;
  ctx.spindle_rev_per_s = 1.0 / period_;
  ctx.sample_period_s = clock_.period_s;
  ctx.limits = sc_.limits;
  ctx.reference_force_N = referenceForceFromPower(sc_);
  ctx.programmed_feed_m_per_s = sc_.programmed_feed_m_per_s;
  ctx.commanded_feed_m_per_s = sc_.programmed_feed_m_per_s;
  ctx.passes_m = sc_.pass_depths_m;
  ctx.log = [this](double t, const std::string& type, const std::string& detail) {
    res_.events.push_back({t, type, detail});
  };
  return ctx;
}

MetricsSettings SupervisedRun::metricsSettings() const {
  MetricsSettings s;
  s.reference_force_N = ctx_.reference_force_N;
  s.power_limit_W = sc_.limits.spindle_power_limit_W;
  s.sample_period_s = clock_.period_s;
  s.spindle_period_s = period_;
  s.chatter_indicator_threshold = sc_.chatter_indicator_threshold;
  return s;
}

SupervisionResult SupervisedRun::run() {
  for (ctx_.current_pass = 0; ctx_.current_pass < static_cast<int>(ctx_.passes_m.size()); ++ctx_.current_pass) {
    const auto k = static_cast<std::size_t>(ctx_.current_pass);
    startPass(k);
    while (proc_.output().tool_x_m < x_end_) sample(k);
    // The return to the start at the maximum feed rate: counted, not simulated.
    if (ctx_.current_pass + 1 < static_cast<int>(ctx_.passes_m.size()))
      t_ += (x_end_ - x_begin_) / sc_.limits.max_feed_rate_m_per_s;
  }
  res_.events.push_back({t_, "end", "part program complete"});
  res_.final_program_m = ctx_.passes_m;
  res_.metrics = metrics_.finish(t_, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count());
  return std::move(res_);
}

// A pass cuts from where the material still stands (an earlier re-planned pass may have cut less).
void SupervisedRun::startPass(std::size_t k) {
  if (material_start_.size() <= k) material_start_.resize(k + 1, sc_.part_start_x_m);
  FaceMillingParameters pass_p = part_;
  pass_p.part_start_x_m = std::max(sc_.part_start_x_m, material_start_[k]);
  pass_p.part_length_m = std::max(1e-6, sc_.part_start_x_m + sc_.part_length_m - pass_p.part_start_x_m);
  proc_ = FaceMillingProcess(pass_p);
  proc_.setDepth(ctx_.currentDepth());
  proc_.reset(x_begin_);
  res_.events.push_back(
      {t_, "pass_start", "pass " + std::to_string(k + 1) + " at " + std::to_string(ctx_.currentDepth() * 1e3) + " mm"});
  metrics_.countPass();
}

// One sample period Ts: the process, the measured signals, the operator, the scan, the modules.
void SupervisedRun::sample(std::size_t k) {
  proc_.setFeedRate(ctx_.commanded_feed_m_per_s);
  for (long long i = 0; i < clock_.steps_per_sample; ++i) proc_.step();
  t_ += clock_.period_s;
  ++sample_;
  ctx_.t_s = t_;
  const FaceMillingOutput& o = proc_.output();
  const double power = updateSignals(o);
  applyOperatorEvents();
  if ((sample_ - 1) % clock_.samples_per_scan == 0) scan(o);
  tickModules();
  if (ctx_.replanned) replan(k, o);
  if (ctx_.b) metrics_.addContactForce(t_, ctx_.F_Y_N);
  if (sample_ % clock_.record_every == 0)
    res_.series.push_back({t_, o.fy_N, ctx_.F_Y_N, power, proc_.feedRate(), proc_.depth(), ctx_.current_pass + 1});
  if (t_ > sc_.max_time_s)
    throw std::runtime_error("supervision: run exceeded max_time_s = " + std::to_string(sc_.max_time_s) + " s");
}

// The modules' measurement windows, the mean power and the TDS chatter indicator; returns the power.
double SupervisedRun::updateSignals(const FaceMillingOutput& o) {
  keepLast(ctx_.fy_samples, o.fy_N, clock_.samples_per_rev);
  keepLast(ctx_.feed_samples, ctx_.commanded_feed_m_per_s, clock_.samples_per_rev);
  power_.push(o.power_W);
  regen_.push(o.regen_m * o.regen_m);
  const double power = std::max(0.0, power_.mean());
  const double part_end = sc_.part_start_x_m + sc_.part_length_m;
  const bool fully_engaged = o.tool_x_m > sc_.part_start_x_m + R_ && o.tool_x_m < part_end - R_;
  metrics_.addPower(power, fully_engaged && lastPass());
  const double regen_rms = std::sqrt(std::max(0.0, regen_.mean()));
  const bool over_part = o.tool_x_m > sc_.part_start_x_m - R_ && o.tool_x_m < part_end + R_;
  const bool feeding = *std::min_element(ctx_.feed_samples.begin(), ctx_.feed_samples.end()) > 0.0;
  metrics_.addChatterIndicator(t_, over_part && feeding, regen_rms / f_nominal_);
  return power;
}

void SupervisedRun::applyOperatorEvents() {
  if (sc_.poll_events) {  // events injected while the run goes on (the GUI's operator buttons)
    std::vector<OperatorEvent> injected;
    sc_.poll_events(t_, injected);
    events_.injectAt(t_, injected);
  }
  while (const std::optional<OperatorEvent> e = events_.popDue(t_)) {
    if (e->type == OperatorEventType::FeedHoldOn) ctx_.operator_feed_hold = true;
    if (e->type == OperatorEventType::FeedHoldOff) ctx_.operator_feed_hold = false;
    if (e->type == OperatorEventType::ChatterSignal) ctx_.operator_chatter_key = true;
    res_.events.push_back({t_, "operator", operatorEventText(e->type)});
  }
}

// A scan of the supervisor logic; its actions switch the modules.
void SupervisedRun::scan(const FaceMillingOutput& o) {
  if (job_.cancelled()) throw Cancelled();
  SignalValues sig{{"a", ctx_.a}, {"b", ctx_.b}, {"c", ctx_.c}, {"d", ctx_.d}, {"e", ctx_.e}, {"F_Y", ctx_.F_Y_N}};
  const ScanOutput out = logic_.scan(sig);
  // Reported once per episode, not at every scan of it.
  if (!out.stable && last_stable_) res_.events.push_back({t_, "logic_unstable", "no stable situation in this scan"});
  last_stable_ = out.stable;
  scheduler_.applyScan(out, ctx_);
  // A restart at contact (step 3), not the initialisation of step 1.
  for (const std::string& impulse : out.impulse_actions)
    if (ctx_.b && (impulse == "L*" || impulse == "K*")) metrics_.startForceTransient(t_);
  if (out.active_steps != last_steps_) {
    last_steps_ = out.active_steps;
    res_.steps.push_back({t_, last_steps_});
  }
  job_.report(std::min(1.0, (ctx_.current_pass + (o.tool_x_m - x_begin_) / (x_end_ - x_begin_)) /
                                static_cast<double>(ctx_.passes_m.size())));
  if (sc_.on_progress && t_ >= next_progress_) {
    next_progress_ = t_ + sc_.progress_period_s;
    res_.metrics = metrics_.current();
    sc_.on_progress(res_, t_);
  }
}

void SupervisedRun::tickModules() {
  scheduler_.tick(ctx_);
  const std::string mods = scheduler_.activeLetters();
  if (mods != last_modules_) {
    last_modules_ = mods;
    res_.modules.push_back({t_, mods});
  }
  metrics_.addDetectorSignal(t_, ctx_.c || ctx_.d);
}

// F rewrote the program: the process takes the new depth, and the later passes start where this one
// has cut so far.
void SupervisedRun::replan(std::size_t k, const FaceMillingOutput& o) {
  ctx_.replanned = false;
  proc_.setDepth(ctx_.currentDepth());
  material_start_.resize(ctx_.passes_m.size(), sc_.part_start_x_m);
  for (std::size_t j = k + 1; j < material_start_.size(); ++j) material_start_[j] = o.tool_x_m + R_;
}

}  // namespace

SupervisionResult runSupervision(const SupervisionScenario& sc, SupervisorLogic& logic, const JobControl& job) {
  validateSupervisionScenario(sc);
  SupervisedRun run(sc, logic, job);
  return run.run();
}

}  // namespace mx
