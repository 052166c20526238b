// Ranges of the process sections and the expert extras. The ranges and messages are those the
// request builders always used ("control.beta = 2: must be in [-1, 1]").
#include <QStringList>

#include "document/project_rules.h"
#include "document/project_sections_io.h"

namespace mx::app {

namespace {

constexpr FieldRange kLength{1e-6, 1e7, "in (0, 1e7]"};
constexpr FieldRange kDepth{0.0, 1e3, "in [0, 1000]"};

void validateDepthSteps(const QString& path, const std::optional<std::vector<DepthStepSpec>>& steps) {
  if (!steps) return;
  if (steps->empty()) throwBadField(path, "(not a non-empty array)", "an array of {length_mm, depth_mm}");
  for (std::size_t i = 0; i < steps->size(); ++i) {
    const QString element = indexPath(path, static_cast<qsizetype>(i));
    checkField(element + ".length_mm", (*steps)[i].length_mm, kLength);
    checkField(element + ".depth_mm", (*steps)[i].depth_mm, kDepth);
  }
}

void checkOneOf(const QString& path, const std::optional<QString>& value, const QStringList& allowed,
                const QString& wording) {
  if (value && !allowed.contains(*value)) throwBadField(path, "'" + *value + "'", wording);
}

void validateProgramme(const QString& path, const std::optional<std::vector<ControlProgrammePointSpec>>& points) {
  if (!points) return;
  if (points->empty())
    throwBadField(path, "(not a non-empty array)", "an array of {speed_rpm, depth_mm, length_mm[, feed_mm_s]}");
  for (std::size_t i = 0; i < points->size(); ++i) {
    const QString element = indexPath(path, static_cast<qsizetype>(i));
    const ControlProgrammePointSpec& point = (*points)[i];
    checkField(element + ".speed_rpm", point.speed_rpm, {1e-3, 1e5, "in (0, 100000]"});
    checkField(element + ".depth_mm", point.depth_mm, {1e-9, 1e3, "in (0, 1000]"});
    checkField(element + ".length_mm", point.length_mm, kLength);
    checkField(element + ".feed_mm_s", point.feed_mm_s, {1e-6, 1e5, "in (0, 1e5]"});
  }
}

void validateControl(const ControlSection& c, const Project& p) {
  if (!c.spindle_rpm && !c.programme) throwMissingField("control.spindle_rpm", "in (0, 100000]");
  checkField("control.spindle_rpm", c.spindle_rpm, {1e-3, 1e5, "in (0, 100000]"});
  const double kt = p.material ? p.material->Kt_N_mm2 : 0.0;
  if (!c.cutting_pressure_N_mm2 && !(kt > 0.0)) throwMissingField("control.cutting_pressure_N_mm2", "in (0, 1e6]");
  checkField("control.cutting_pressure_N_mm2", c.cutting_pressure_N_mm2, {1e-3, 1e6, "in (0, 1e6]"});
  checkField("control.start_angle_deg", c.start_angle_deg, {0.0, 180.0, "in [0, 180]"});
  checkField("control.exit_angle_deg", c.exit_angle_deg, {0.0, 180.0, "in [0, 180]"});
  checkField("control.drive_time_constant_ms", c.drive_time_constant_ms, {1e-6, 1e4, "in (0, 1e4]"});
  checkField("control.process_time_constant_ms", c.process_time_constant_ms, {0.0, 1e4, "in [0, 1e4] (0: default)"});
  checkField("control.beta", c.beta, {-1.0, 1.0, "in [-1, 1]"});
  checkField("control.feed_max_mm_s", c.feed_max_mm_s, {1e-3, 1e5, "in (0, 1e5]"});
  checkField("control.force_reference_N", c.force_reference_N, {1e-3, 1e7, "in (0, 1e7]"});
  checkField("control.breakage_force_N", c.breakage_force_N, {0.0, 1e7, "in [0, 1e7] (0: not given)"});
  checkField("control.safety_factor", c.safety_factor, {1e-3, 1.0, "in (0, 1]"});
  if (c.reference_model) {
    checkField("control.reference_model.damping", c.reference_model->damping, {0.05, 5.0, "in [0.05, 5]"});
    checkField("control.reference_model.rise_time_periods", c.reference_model->rise_time_periods,
               {0.5, 1000.0, "in [0.5, 1000]"});
  }
  if (c.rls) {
    const ControlRlsSpec& r = *c.rls;
    checkField("control.rls.lambda", r.lambda, {0.5, 1.0, "in [0.5, 1]"});
    checkField("control.rls.P0", r.P0, {1e-6, 1e15, "in [1e-6, 1e15]"});
    checkField("control.rls.theta0", r.theta0, {-1e6, 1e6, "in [-1e6, 1e6]"});
    checkOneOf("control.rls.reset", r.reset, {"error", "trace", "none"}, "one of error, trace, none");
    checkField("control.rls.reset_fraction", r.reset_fraction, {1e-6, 10.0, "in (0, 10]"});
    checkField("control.rls.trace_min", r.trace_min, {0.0, 1e15, "in [0, 1e15]"});
    checkField("control.rls.trace_max", r.trace_max, {1e-12, 1e300, "in (0, 1e300]"});
    const double trace_min = r.trace_min.value_or(1e-6), trace_max = r.trace_max.value_or(1e12);
    if (!(trace_max > trace_min))
      throwBadField("control.rls.trace_max", QString::number(trace_max), "greater than control.rls.trace_min");
  }
  validateDepthSteps("control.workpiece", c.workpiece);
  checkOneOf("control.sample_period", c.sample_period, {"spindle", "rule4"}, "one of spindle, rule4");
  checkField("control.rule4_periods", c.rule4_periods, {1.0, 100.0, "an integer in [1, 100]", true});
  validateProgramme("control.programme", c.programme);
}

void validateSdnrp(const SdnrpSection& s) {
  checkField("sdnrp.ra_um", s.ra_um, {0.25, 2.5, "in [0.25, 2.5]"});
  checkField("sdnrp.seconds", s.seconds, {0.1, 600.0, "in [0.1, 600]"});
  if (s.disturbance) {
    checkField("sdnrp.disturbance.seed", s.disturbance->seed, {0.0, 9.0e15, "an integer in [0, 9e15]", true});
    checkField("sdnrp.disturbance.sigma_N", s.disturbance->sigma_N, {0.0, 1e4, "in [0, 1e4]"});
    checkField("sdnrp.disturbance.hold_ms", s.disturbance->hold_ms, {1.0, 1e4, "in [1, 1e4]"});
  }
  if (s.initial) {
    checkField("sdnrp.initial.feed_mm_min", s.initial->feed_mm_min, {1e-3, 1e5, "in (0, 1e5]"});
    checkField("sdnrp.initial.speed_rpm", s.initial->speed_rpm, {1e-3, 1e5, "in (0, 1e5]"});
  }
  if (s.drives) {
    checkField("sdnrp.drives.feed_natural_frequency_rad_s", s.drives->feed_natural_frequency_rad_s,
               {0.1, 1e4, "in [0.1, 1e4]"});
    checkField("sdnrp.drives.feed_damping", s.drives->feed_damping, {0.05, 5.0, "in [0.05, 5]"});
    checkField("sdnrp.drives.spindle_time_constant_s", s.drives->spindle_time_constant_s,
               {1e-4, 100.0, "in [1e-4, 100]"});
  }
  checkField("sdnrp.integral_rate_per_s", s.integral_rate_per_s, {1e-3, 100.0, "in [1e-3, 100]"});
}

void validateForceControl(const ForceControlSection& f) {
  if (f.model) {
    checkField("force_control.model.K_N", f.model->K_N, {1e-6, 1e9, "in (0, 1e9]"});
    checkField("force_control.model.depth_exponent", f.model->depth_exponent, {0.01, 5.0, "in [0.01, 5]"});
    checkField("force_control.model.feed_exponent", f.model->feed_exponent, {0.01, 5.0, "in [0.01, 5]"});
  }
  checkField("force_control.reference_force_N", f.reference_force_N, {1e-3, 1e7, "in (0, 1e7]"});
  checkField("force_control.max_feed_mm_s", f.max_feed_mm_s, {1e-3, 1e5, "in (0, 1e5]"});
  checkField("force_control.max_feed_per_tooth_mm", f.max_feed_per_tooth_mm, {1e-4, 100.0, "in (0, 100]"});
}

void validatePartProgram(const PartProgramSection& p) {
  checkField("part_program.stock_top_mm", p.stock_top_mm, {-1e5, 1e5, "in [-1e5, 1e5]"});
  validateDepthSteps("part_program.depth_profile", p.depth_profile);
  checkField("part_program.speed_rpm", p.speed_rpm, {1e-3, 1e5, "in (0, 1e5]"});
  checkOneOf("part_program.controller", p.controller, {"adaptive", "model-based"}, "adaptive or model-based");
}

void validatePasses(const QString& controller, const std::optional<std::vector<double>>& passes) {
  if (!passes) return;
  const QString path = "supervisor.passes_mm." + controller;
  if (passes->empty()) throwBadField(path, "(not a non-empty array)", "an array of depths [mm]");
  for (std::size_t i = 0; i < passes->size(); ++i) {
    const double d = (*passes)[i];
    if (!(d > 0.0 && d <= 20.0))
      throwBadField(indexPath(path, static_cast<qsizetype>(i)), QString::number(d, 'g', 10), "a depth in (0, 20] mm");
  }
}

void validateSupervisor(const SupervisorSection& s) {
  checkField("supervisor.spindle_rpm", s.spindle_rpm, {1.0, 1e5, "in [1, 1e5]"});
  checkField("supervisor.programmed_feed_mm_s", s.programmed_feed_mm_s, {1e-3, 1e4, "in (0, 1e4]"});
  if (s.part) {
    checkField("supervisor.part.length_mm", s.part->length_mm, {1e-3, 1e5, "in (0, 1e5]"});
    checkField("supervisor.part.width_mm", s.part->width_mm, {1e-3, 1e4, "in (0, 1e4]"});
    checkField("supervisor.part.approach_mm", s.part->approach_mm, {0.0, 1e4, "in [0, 1e4]"});
  }
  if (s.passes_mm) {
    validatePasses("none", s.passes_mm->none);
    validatePasses("smc1", s.passes_mm->smc1);
    validatePasses("smc2", s.passes_mm->smc2);
  }
  checkField("supervisor.scan_period_ms", s.scan_period_ms, {0.5, 1000.0, "in [0.5, 1000]"});
  checkField("supervisor.reference_force_N", s.reference_force_N, {1e-3, 1e7, "in (0, 1e7]"});
  checkField("supervisor.power_margin", s.power_margin, {0.05, 1.0, "in [0.05, 1]"});
  checkField("supervisor.chatter_threshold_N", s.chatter_threshold_N, {1e-3, 1e6, "in (0, 1e6]"});
  if (s.model_controller) {
    checkField("supervisor.model_controller.time_constant_ms", s.model_controller->time_constant_ms,
               {1.0, 1e5, "in [1, 1e5]"});
    checkOneOf("supervisor.model_controller.reset_feed", s.model_controller->reset_feed, {"current", "model"},
               "current or model");
  }
  if (s.events) {
    for (std::size_t i = 0; i < s.events->size(); ++i) {
      const QString path = indexPath("supervisor.events", static_cast<qsizetype>(i));
      const SupervisorEventSpec& e = (*s.events)[i];
      checkField(path + ".t_s", e.t_s, {0.0, 1e5, "in [0, 1e5]"});
      checkOneOf(path + ".type", e.type, {"feed_hold_on", "feed_hold_off", "chatter"},
                 "one of feed_hold_on, feed_hold_off, chatter");
    }
  }
}

void validatePowerLaw(const QString& path, const std::optional<PowerLawSpec>& m) {
  if (!m) throw ProjectError(QString("%1 is missing: the model constants K and exponents").arg(path));
  checkField(path + ".K", m->K, {1e-300, 1e300, "a finite number > 0"});
  checkField(path + ".speed_exponent", m->speed_exponent, {-10.0, 10.0, "in [-10, 10]"});
  checkField(path + ".depth_exponent", m->depth_exponent, {-10.0, 10.0, "in [-10, 10]"});
  checkField(path + ".feed_exponent", m->feed_exponent, {-10.0, 10.0, "in [-10, 10]"});
}

void validateParetoEconomics(const ParetoEconomicsSpec& e) {
  checkField("pareto.economics.machine_rate_per_h", e.machine_rate_per_h, {0.0, 1e6, "in [0, 1e6]"});
  checkField("pareto.economics.tool_cost", e.tool_cost, {0.0, 1e6, "in [0, 1e6]"});
  checkField("pareto.economics.tool_change_min", e.tool_change_min, {0.0, 1e4, "in [0, 1e4]"});
  checkField("pareto.economics.removal_volume_cm3", e.removal_volume_cm3, {1e-6, 1e9, "in (0, 1e9]"});
  if (e.machine_rate_per_h == 0.0 && e.tool_cost == 0.0)
    throw ProjectError("pareto.economics: machine_rate_per_h = 0 and tool_cost = 0: at least one must be > 0");
}

void validateParetoRequirements(const ParetoRequirementsSpec& q, bool has_economics) {
  checkField("pareto.requirements.min_mrr_cm3_s", q.min_mrr_cm3_s, {0.0, 1e6, "in [0, 1e6]"});
  checkField("pareto.requirements.min_mrr_fraction", q.min_mrr_fraction, {0.0, 1.0, "in [0, 1]"});
  checkField("pareto.requirements.max_time_min", q.max_time_min, {1e-6, 1e6, "in (0, 1e6]"});
  checkField("pareto.requirements.removal_volume_cm3", q.removal_volume_cm3, {1e-6, 1e9, "in (0, 1e9]"});
  if (q.max_time_min && !q.removal_volume_cm3 && !has_economics)
    throw ProjectError(
        "pareto.requirements.max_time_min needs a removal volume: pareto.requirements.removal_volume_cm3 or "
        "pareto.economics.removal_volume_cm3");
  const int given =
      int(q.min_mrr_cm3_s.has_value()) + int(q.min_mrr_fraction.has_value()) + int(q.max_time_min.has_value());
  if (given > 1)
    throw ProjectError(
        "pareto.requirements: give one of min_mrr_cm3_s, min_mrr_fraction and max_time_min (each sets the "
        "minimum MRR)");
}

void validatePareto(const ParetoSection& p) {
  validatePowerLaw("pareto.taylor", p.taylor);
  validatePowerLaw("pareto.roughness", p.roughness);
  if (p.weights && p.weights->size() != 4) {
    throw ProjectError(
        QString("pareto.weights has %1 values: expected 4 weights (tol, mrr, surf, ros)").arg(p.weights->size()));
  }
  if (p.fine) checkField("pareto.fine.divisions", p.fine->divisions, {1.0, 100.0, "an integer in [1, 100]", true});
  if (p.auto_weights) {
    checkField("pareto.auto_weights.step", p.auto_weights->step, {1e-12, 1.0, "in (0, 1]"});
    checkField("pareto.auto_weights.tolerance", p.auto_weights->tolerance, {1e-15, 0.999999, "in (0, 1)"});
    checkField("pareto.auto_weights.max_iterations", p.auto_weights->max_iterations,
               {1.0, 100000.0, "an integer in [1, 100000]", true});
  }
  checkOneOf("pareto.normalisation", p.normalisation, {"minmax", "max", "log"}, "one of minmax, max, log");
  checkOneOf("pareto.objective", p.objective, {"weighted", "min_cost", "max_rate"},
             "one of weighted, min_cost, max_rate");
  if (p.economics) validateParetoEconomics(*p.economics);
  if (p.objective && *p.objective != "weighted" && !p.economics)
    throw ProjectError(QString("pareto.objective = '%1' needs pareto.economics (machine_rate_per_h, tool_cost, "
                               "tool_change_min, removal_volume_cm3)")
                           .arg(*p.objective));
  if (p.requirements) validateParetoRequirements(*p.requirements, p.economics.has_value());
}

}  // namespace

void validateProcessSections(const Project& p) {
  if (p.control) validateControl(*p.control, p);
  if (p.sdnrp) validateSdnrp(*p.sdnrp);
  if (p.force_control) validateForceControl(*p.force_control);
  if (p.part_program) validatePartProgram(*p.part_program);
  if (p.supervisor) validateSupervisor(*p.supervisor);
  if (p.pareto) validatePareto(*p.pareto);
  if (p.operator_rules) {
    for (qsizetype i = 0; i < p.operator_rules->size(); ++i)
      if (p.operator_rules->at(i).contains('\n'))
        throw ProjectError(QString("operator_rules[%1]: must be a string holding one rule").arg(i));
  }
}

void validateExpertExtras(const ExpertSpec& e) {
  checkOneOf("expert.method", e.method, {"zoa", "sdm"}, "zoa or sdm");
  if (e.simulated_points)
    checkField("expert.simulated_points", *e.simulated_points, {1.0, 1000.0, "an integer in [1, 1000]", true});
  if (const auto& s = e.rule5_search) {
    checkField("expert.rule5_search.speed_step_rpm", s->speed_step_rpm, {1e-9, 1e5, "in (0, 1e5]"});
    checkField("expert.rule5_search.depth_step_mm", s->depth_step_mm, {1e-12, 100.0, "in (0, 100]"});
    checkField("expert.rule5_search.feed_step_mm", s->feed_step_mm, {1e-12, 10.0, "in (0, 10]"});
    if (s->max_iterations)
      checkField("expert.rule5_search.max_iterations", *s->max_iterations,
                 {0.0, 1000.0, "an integer in [0, 1000]", true});
  }
}

}  // namespace mx::app
