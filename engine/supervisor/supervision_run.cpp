#include "supervisor/supervision_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "supervisor/module_scheduler.h"

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

SupervisionResult runSupervision(const SupervisionScenario& sc, SupervisorLogic& logic, const JobControl& job) {
  validateSupervisionScenario(sc);
  const auto wall0 = std::chrono::steady_clock::now();
  SupervisionResult res;
  res.controller = controllerName(sc.controller);
  SupervisionMetrics& m = res.metrics;

  FaceMillingParameters pp = sc.process;
  pp.part_start_x_m = sc.part_start_x_m;
  pp.part_length_m = sc.part_length_m;
  FaceMillingProcess proc(pp);
  const double R = pp.tool_radius_m, period = proc.spindlePeriod();
  const auto steps_per_sample = std::max<long long>(1, std::llround(sc.sample_period_s / proc.stepSize()));
  const double Ts = static_cast<double>(steps_per_sample) * proc.stepSize();
  const auto samples_per_scan = std::max<long long>(1, std::llround(sc.scan_period_s / Ts));
  const auto samples_per_rev = static_cast<std::size_t>(std::max<long long>(8, std::llround(period / Ts)));
  const auto samples_per_tooth = static_cast<std::size_t>(std::max<long long>(1, std::llround(period / pp.teeth / Ts)));
  const auto record_every = std::max<long long>(1, std::llround(sc.record_period_s / Ts));

  MachiningContext ctx;
  ctx.teeth = pp.teeth;
  ctx.spindle_rev_per_s = 1.0 / period;
  ctx.sample_period_s = Ts;
  ctx.limits = sc.limits;
  ctx.reference_force_N = referenceForceFromPower(sc);
  ctx.programmed_feed_m_per_s = sc.programmed_feed_m_per_s;
  ctx.commanded_feed_m_per_s = sc.programmed_feed_m_per_s;
  ctx.passes_m = sc.pass_depths_m;
  ctx.log = [&res](double t, const std::string& type, const std::string& detail) {
    res.events.push_back({t, type, detail});
  };
  m.reference_force_N = ctx.reference_force_N;
  ModuleScheduler scheduler(makeStandardModules(sc.chatter_detector, sc.force_model));
  logic.reset();

  std::vector<OperatorEvent> events = sc.events;
  double next_progress = 0.0;
  bool last_stable = true;
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
  std::size_t next_event = 0;
  std::deque<double> power_window, regen_window;
  double power_sum = 0.0, regen_sum2 = 0.0, t = 0.0, tds_first = -1.0, tds_run_start = -1.0;
  long long sample = 0;
  std::vector<std::string> last_steps;
  std::string last_modules = "-";
  std::vector<double> material_start(1, sc.part_start_x_m);  // per pass: where uncut material begins
  const double x_begin = sc.part_start_x_m - R - sc.approach_m;
  const double x_end = sc.part_start_x_m + sc.part_length_m + R + sc.approach_m;
  const double f_nominal = sc.programmed_feed_m_per_s * period / pp.teeth;

  for (ctx.current_pass = 0; ctx.current_pass < static_cast<int>(ctx.passes_m.size()); ++ctx.current_pass) {
    const auto k = static_cast<std::size_t>(ctx.current_pass);
    if (material_start.size() <= k) material_start.resize(k + 1, sc.part_start_x_m);
    FaceMillingParameters pass_p = pp;
    pass_p.part_start_x_m = std::max(sc.part_start_x_m, material_start[k]);
    pass_p.part_length_m = std::max(1e-6, sc.part_start_x_m + sc.part_length_m - pass_p.part_start_x_m);
    proc = FaceMillingProcess(pass_p);
    proc.setDepth(ctx.currentDepth());
    proc.reset(x_begin);
    res.events.push_back(
        {t, "pass_start", "pass " + std::to_string(k + 1) + " at " + std::to_string(ctx.currentDepth() * 1e3) + " mm"});
    ++m.passes;
    while (proc.output().tool_x_m < x_end) {
      proc.setFeedRate(ctx.commanded_feed_m_per_s);
      for (long long i = 0; i < steps_per_sample; ++i) proc.step();
      t += Ts;
      ++sample;
      ctx.t_s = t;
      const FaceMillingOutput& o = proc.output();
      auto push = [&](std::deque<double>& q, double v, std::size_t n) {
        q.push_back(v);
        while (q.size() > n) q.pop_front();
      };
      push(ctx.fy_samples, o.fy_N, samples_per_rev);
      push(ctx.feed_samples, ctx.commanded_feed_m_per_s, samples_per_rev);
      power_window.push_back(o.power_W);
      power_sum += o.power_W;
      if (power_window.size() > samples_per_tooth) {
        power_sum -= power_window.front();
        power_window.pop_front();
      }
      regen_window.push_back(o.regen_m * o.regen_m);
      regen_sum2 += o.regen_m * o.regen_m;
      if (regen_window.size() > samples_per_rev) {
        regen_sum2 -= regen_window.front();
        regen_window.pop_front();
      }
      const double power = std::max(0.0, power_sum / static_cast<double>(power_window.size()));
      m.max_power_W = std::max(m.max_power_W, power);
      const bool fully_engaged =
          o.tool_x_m > sc.part_start_x_m + R && o.tool_x_m < sc.part_start_x_m + sc.part_length_m - R;
      if (fully_engaged && ctx.current_pass + 1 == static_cast<int>(ctx.passes_m.size()))
        m.steady_max_power_pct_of_limit =
            std::max(m.steady_max_power_pct_of_limit, 100.0 * power / sc.limits.spindle_power_limit_W);
      const double regen_rms = std::sqrt(std::max(0.0, regen_sum2) / static_cast<double>(regen_window.size()));
      const bool over_part =
          o.tool_x_m > sc.part_start_x_m - R && o.tool_x_m < sc.part_start_x_m + sc.part_length_m + R;
      const bool feeding = *std::min_element(ctx.feed_samples.begin(), ctx.feed_samples.end()) > 0.0;
      if (over_part && feeding && regen_rms / f_nominal > sc.chatter_indicator_threshold) {
        m.tds_chatter_s += Ts;
        if (tds_run_start < 0.0) tds_run_start = t;
        // Sustained: above the threshold for 10 revolutions in a row (entry and exit impacts are shorter).
        if (tds_first < 0.0 && t - tds_run_start >= 10.0 * period) tds_first = tds_run_start;
      } else {
        tds_run_start = -1.0;
      }
      if (sc.poll_events) {  // events injected while the run goes on (the GUI's operator buttons)
        std::vector<OperatorEvent> injected;
        sc.poll_events(t, injected);
        for (OperatorEvent& e : injected) {
          e.t_s = t;
          events.insert(events.begin() + static_cast<std::ptrdiff_t>(next_event), e);
        }
      }
      while (next_event < events.size() && events[next_event].t_s <= t + 1e-12) {
        const auto& e = events[next_event++];
        if (e.type == OperatorEventType::FeedHoldOn) ctx.operator_feed_hold = true;
        if (e.type == OperatorEventType::FeedHoldOff) ctx.operator_feed_hold = false;
        if (e.type == OperatorEventType::ChatterSignal) ctx.operator_chatter_key = true;
        res.events.push_back({t, "operator",
                              e.type == OperatorEventType::FeedHoldOn    ? "feed hold on"
                              : e.type == OperatorEventType::FeedHoldOff ? "feed hold off"
                                                                         : "chatter key"});
      }
      if ((sample - 1) % samples_per_scan == 0) {
        if (job.cancelled()) throw Cancelled();
        SignalValues sig{{"a", ctx.a}, {"b", ctx.b}, {"c", ctx.c}, {"d", ctx.d}, {"e", ctx.e}, {"F_Y", ctx.F_Y_N}};
        const ScanOutput out = logic.scan(sig);
        // Reported once per episode, not at every scan of it.
        if (!out.stable && last_stable) res.events.push_back({t, "logic_unstable", "no stable situation in this scan"});
        last_stable = out.stable;
        scheduler.applyScan(out, ctx);
        if (out.active_steps != last_steps) {
          last_steps = out.active_steps;
          res.steps.push_back({t, last_steps});
        }
        job.report(std::min(1.0, (ctx.current_pass + (o.tool_x_m - x_begin) / (x_end - x_begin)) /
                                     static_cast<double>(ctx.passes_m.size())));
        if (sc.on_progress && t >= next_progress) {
          next_progress = t + sc.progress_period_s;
          sc.on_progress(res, t);
        }
      }
      scheduler.tick(ctx);
      const std::string mods = scheduler.activeLetters();
      if (mods != last_modules) {
        last_modules = mods;
        res.modules.push_back({t, mods});
      }
      if ((ctx.c || ctx.d) && !m.detector_fired) {
        m.detector_fired = true;
        m.chatter_time_s = t;
      }
      if (ctx.replanned) {
        ctx.replanned = false;
        proc.setDepth(ctx.currentDepth());
        material_start.resize(ctx.passes_m.size(), sc.part_start_x_m);
        for (std::size_t j = k + 1; j < material_start.size(); ++j) material_start[j] = o.tool_x_m + R;
      }
      if (ctx.b) {
        m.max_F_Y_N = std::max(m.max_F_Y_N, ctx.F_Y_N);
      }
      if (sample % record_every == 0)
        res.series.push_back({t, o.fy_N, ctx.F_Y_N, power, proc.feedRate(), proc.depth(), ctx.current_pass + 1});
      if (t > sc.max_time_s)
        throw std::runtime_error("supervision: run exceeded max_time_s = " + std::to_string(sc.max_time_s) + " s");
    }
    if (ctx.current_pass + 1 < static_cast<int>(ctx.passes_m.size()))
      t += (x_end - x_begin) / sc.limits.max_feed_rate_m_per_s;
  }
  res.events.push_back({t, "end", "part program complete"});
  res.final_program_m = ctx.passes_m;
  m.max_power_pct_of_limit = 100.0 * m.max_power_W / sc.limits.spindle_power_limit_W;
  m.overshoot_pct = 100.0 * (m.max_F_Y_N - ctx.reference_force_N) / ctx.reference_force_N;
  // Without a firing detector, sustained TDS chatter still counts.
  const bool tds_chatter = tds_first >= 0.0;
  if (!m.detector_fired && tds_chatter) m.chatter_time_s = tds_first;
  m.chatter_detected = m.detector_fired || tds_chatter;
  m.cycle_time_s = t;
  m.run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace mx
