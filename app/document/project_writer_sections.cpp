// The process sections of projectToJson, each written over the unknown keys of its object (so that
// they survive, and go with a sub-object the project no longer has).
#include <QJsonArray>
#include <utility>

#include "document/project_grafcet_io.h"
#include "document/project_sections_io.h"

namespace mx::app {

namespace {

void putString(QJsonObject& o, const QString& key, const std::optional<QString>& value) {
  if (value) {
    o.insert(key, *value);
  } else {
    o.remove(key);
  }
}

void putBool(QJsonObject& o, const QString& key, const std::optional<bool>& value) {
  if (value) {
    o.insert(key, *value);
  } else {
    o.remove(key);
  }
}

template <typename Spec, typename Writer>
void putObject(QJsonObject& o, const QString& key, const std::optional<Spec>& spec, Writer write) {
  if (spec) {
    QJsonObject child = o.value(key).toObject();
    write(child, *spec);
    o.insert(key, child);
  } else {
    o.remove(key);
  }
}

void putDepthSteps(QJsonObject& o, const QString& key, const std::optional<std::vector<DepthStepSpec>>& steps) {
  if (!steps) {
    o.remove(key);
    return;
  }
  QJsonArray out;
  for (const DepthStepSpec& step : *steps) {
    QJsonObject s = step.unknown;
    putNumber(s, "length_mm", step.length_mm);
    putNumber(s, "depth_mm", step.depth_mm);
    out.append(s);
  }
  o.insert(key, out);
}

void putProgramme(QJsonObject& o, const QString& key,
                  const std::optional<std::vector<ControlProgrammePointSpec>>& points) {
  if (!points) {
    o.remove(key);
    return;
  }
  QJsonArray out;
  for (const ControlProgrammePointSpec& point : *points) {
    QJsonObject e = point.unknown;
    putNumber(e, "speed_rpm", point.speed_rpm);
    putNumber(e, "depth_mm", point.depth_mm);
    putNumber(e, "length_mm", point.length_mm);
    putOptional(e, "feed_mm_s", point.feed_mm_s);
    out.append(e);
  }
  o.insert(key, out);
}

void writeControl(QJsonObject& o, const ControlSection& c) {
  putString(o, "tool", c.tool);
  putOptional(o, "spindle_rpm", c.spindle_rpm);
  putOptional(o, "cutting_pressure_N_mm2", c.cutting_pressure_N_mm2);
  putOptional(o, "start_angle_deg", c.start_angle_deg);
  putOptional(o, "exit_angle_deg", c.exit_angle_deg);
  putOptional(o, "drive_time_constant_ms", c.drive_time_constant_ms);
  putOptional(o, "process_time_constant_ms", c.process_time_constant_ms);
  putOptional(o, "beta", c.beta);
  putOptional(o, "force_reference_N", c.force_reference_N);
  putOptional(o, "breakage_force_N", c.breakage_force_N);
  putOptional(o, "safety_factor", c.safety_factor);
  putOptional(o, "feed_max_mm_s", c.feed_max_mm_s);
  putObject(o, "reference_model", c.reference_model, [](QJsonObject& m, const ControlReferenceModelSpec& s) {
    putOptional(m, "damping", s.damping);
    putOptional(m, "rise_time_periods", s.rise_time_periods);
  });
  putObject(o, "rls", c.rls, [](QJsonObject& m, const ControlRlsSpec& s) {
    putOptional(m, "lambda", s.lambda);
    putOptional(m, "P0", s.P0);
    putOptional(m, "theta0", s.theta0);
    putString(m, "reset", s.reset);
    putOptional(m, "reset_fraction", s.reset_fraction);
    putOptional(m, "trace_min", s.trace_min);
    putOptional(m, "trace_max", s.trace_max);
  });
  putDepthSteps(o, "workpiece", c.workpiece);
  putString(o, "sample_period", c.sample_period);
  putOptional(o, "rule4_periods", c.rule4_periods);
  putProgramme(o, "programme", c.programme);
}

void writeSdnrp(QJsonObject& o, const SdnrpSection& s) {
  putOptional(o, "ra_um", s.ra_um);
  putOptional(o, "seconds", s.seconds);
  putObject(o, "disturbance", s.disturbance, [](QJsonObject& d, const SdnrpDisturbanceSpec& v) {
    putBool(d, "enabled", v.enabled);
    putOptional(d, "seed", v.seed);
    putOptional(d, "sigma_N", v.sigma_N);
    putOptional(d, "hold_ms", v.hold_ms);
  });
  putObject(o, "initial", s.initial, [](QJsonObject& i, const SdnrpInitialSpec& v) {
    putOptional(i, "feed_mm_min", v.feed_mm_min);
    putOptional(i, "speed_rpm", v.speed_rpm);
  });
  putObject(o, "drives", s.drives, [](QJsonObject& d, const SdnrpDrivesSpec& v) {
    putOptional(d, "feed_natural_frequency_rad_s", v.feed_natural_frequency_rad_s);
    putOptional(d, "feed_damping", v.feed_damping);
    putOptional(d, "spindle_time_constant_s", v.spindle_time_constant_s);
  });
  putOptional(o, "integral_rate_per_s", s.integral_rate_per_s);
}

void writeForceControl(QJsonObject& o, const ForceControlSection& f) {
  putString(o, "tool", f.tool);
  putObject(o, "model", f.model, [](QJsonObject& m, const ForceModelSpec& v) {
    putOptional(m, "K_N", v.K_N);
    putOptional(m, "depth_exponent", v.depth_exponent);
    putOptional(m, "feed_exponent", v.feed_exponent);
  });
  putOptional(o, "reference_force_N", f.reference_force_N);
  putOptional(o, "max_feed_mm_s", f.max_feed_mm_s);
  putOptional(o, "max_feed_per_tooth_mm", f.max_feed_per_tooth_mm);
}

void writePartProgram(QJsonObject& o, const PartProgramSection& p) {
  putOptional(o, "stock_top_mm", p.stock_top_mm);
  putDepthSteps(o, "depth_profile", p.depth_profile);
  putOptional(o, "speed_rpm", p.speed_rpm);
  putBool(o, "keep_plunge_feed", p.keep_plunge_feed);
  putString(o, "controller", p.controller);
}

void writeSupervisor(QJsonObject& o, const SupervisorSection& s) {
  putString(o, "tool", s.tool);
  putOptional(o, "spindle_rpm", s.spindle_rpm);
  putOptional(o, "programmed_feed_mm_s", s.programmed_feed_mm_s);
  putObject(o, "part", s.part, [](QJsonObject& p, const SupervisorPartSpec& v) {
    putOptional(p, "length_mm", v.length_mm);
    putOptional(p, "width_mm", v.width_mm);
    putOptional(p, "approach_mm", v.approach_mm);
  });
  putObject(o, "passes_mm", s.passes_mm, [](QJsonObject& p, const SupervisorPassesSpec& v) {
    putNumbers(p, "none", v.none);
    putNumbers(p, "smc1", v.smc1);
    putNumbers(p, "smc2", v.smc2);
  });
  putOptional(o, "scan_period_ms", s.scan_period_ms);
  putOptional(o, "reference_force_N", s.reference_force_N);
  putOptional(o, "power_margin", s.power_margin);
  putOptional(o, "chatter_threshold_N", s.chatter_threshold_N);
  putObject(o, "model_controller", s.model_controller, [](QJsonObject& m, const SupervisorModelControllerSpec& v) {
    putOptional(m, "time_constant_ms", v.time_constant_ms);
    putString(m, "reset_feed", v.reset_feed);
  });
  if (s.events) {
    QJsonArray out;
    for (const SupervisorEventSpec& event : *s.events) {
      QJsonObject e = event.unknown;
      putNumber(e, "t_s", event.t_s);
      e.insert("type", event.type);
      out.append(e);
    }
    o.insert("events", out);
  } else {
    o.remove("events");
  }
  putObject(o, "charts", s.charts, [](QJsonObject& c, const SupervisorChartsSpec& v) {
    for (const QString controller : {"none", "smc1", "smc2"}) {
      if (const std::optional<GrafcetChartSpec>& chart = *v.of(controller)) {
        c.insert(controller, grafcetChartToJson(*chart));
      } else {
        c.remove(controller);
      }
    }
  });
}

void writePowerLaw(QJsonObject& o, const PowerLawSpec& m) {
  putNumber(o, "K", m.K);
  putNumber(o, "speed_exponent", m.speed_exponent);
  putNumber(o, "depth_exponent", m.depth_exponent);
  putNumber(o, "feed_exponent", m.feed_exponent);
}

void writePareto(QJsonObject& o, const ParetoSection& p) {
  putString(o, "tool", p.tool);
  putObject(o, "taylor", p.taylor, writePowerLaw);
  putObject(o, "roughness", p.roughness, writePowerLaw);
  putNumbers(o, "weights", p.weights);
  putObject(o, "fine", p.fine,
            [](QJsonObject& f, const ParetoFineSpec& v) { putOptional(f, "divisions", v.divisions); });
  putObject(o, "auto_weights", p.auto_weights, [](QJsonObject& a, const ParetoAutoWeightsSpec& v) {
    putOptional(a, "step", v.step);
    putOptional(a, "tolerance", v.tolerance);
    putOptional(a, "max_iterations", v.max_iterations);
  });
  putString(o, "normalisation", p.normalisation);
  putString(o, "objective", p.objective);
  putObject(o, "economics", p.economics, [](QJsonObject& e, const ParetoEconomicsSpec& v) {
    putNumber(e, "machine_rate_per_h", v.machine_rate_per_h);
    putNumber(e, "tool_cost", v.tool_cost);
    putNumber(e, "tool_change_min", v.tool_change_min);
    putNumber(e, "removal_volume_cm3", v.removal_volume_cm3);
  });
  putObject(o, "requirements", p.requirements, [](QJsonObject& q, const ParetoRequirementsSpec& v) {
    putOptional(q, "min_mrr_cm3_s", v.min_mrr_cm3_s);
    putOptional(q, "min_mrr_fraction", v.min_mrr_fraction);
    putOptional(q, "max_time_min", v.max_time_min);
    putOptional(q, "removal_volume_cm3", v.removal_volume_cm3);
  });
}

}  // namespace

QJsonArray numbersOver(const QJsonArray& old, const std::vector<double>& values) {
  QJsonArray out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto k = static_cast<qsizetype>(i);
    const bool same = k < old.size() && old.at(k).isDouble() && old.at(k).toDouble() == values[i];
    out.append(same ? old.at(k) : QJsonValue(values[i]));
  }
  return out;
}

void putNumber(QJsonObject& o, const QString& key, double value) {
  const QJsonValue old = o.value(key);
  if (old.isDouble() && old.toDouble() == value) return;
  o.insert(key, value);
}

void putNumbers(QJsonObject& o, const QString& key, const std::optional<std::vector<double>>& values) {
  if (values) {
    o.insert(key, numbersOver(o.value(key).toArray(), *values));
  } else {
    o.remove(key);
  }
}

void putOptional(QJsonObject& o, const QString& key, const std::optional<double>& value) {
  if (value) {
    putNumber(o, key, *value);
  } else {
    o.remove(key);
  }
}

void putProcessSections(QJsonObject& root, const Project& p) {
  putObject(root, "control", p.control, writeControl);
  putObject(root, "sdnrp", p.sdnrp, writeSdnrp);
  putObject(root, "force_control", p.force_control, writeForceControl);
  putObject(root, "part_program", p.part_program, writePartProgram);
  putObject(root, "supervisor", p.supervisor, writeSupervisor);
  putObject(root, "pareto", p.pareto, writePareto);
  if (p.operator_rules) {
    root.insert("operator_rules", QJsonArray::fromStringList(*p.operator_rules));
  } else {
    root.remove("operator_rules");
  }
}

void putExpertExtras(QJsonObject& o, const ExpertSpec& e) {
  putString(o, "method", e.method);
  if (e.simulated_points) {
    putNumber(o, "simulated_points", *e.simulated_points);
  } else {
    o.remove("simulated_points");
  }
  if (e.rule5_search) {
    QJsonObject search = o.value("rule5_search").toObject();
    const Rule5SearchSpec& s = *e.rule5_search;
    const auto put = [&search](const QString& key, const auto& value) {
      if (value) {
        putNumber(search, key, static_cast<double>(*value));
      } else {
        search.remove(key);
      }
    };
    put("speed_step_rpm", s.speed_step_rpm);
    put("depth_step_mm", s.depth_step_mm);
    put("feed_step_mm", s.feed_step_mm);
    put("max_iterations", s.max_iterations);
    o.insert("rule5_search", search);
  } else {
    o.remove("rule5_search");
  }
  if (e.grid && o.value("grid").isObject()) {
    QJsonObject grid = o.value("grid").toObject();
    putBool(grid, "modal_candidate_speeds", e.grid->modal_candidate_speeds);
    o.insert("grid", grid);
  }
}

namespace {

// What `original` holds beyond `known`: keys `known` lacks, and within objects both hold, their
// unknown part. Arrays and scalars `known` holds are the typed values (the elements of typed arrays
// of objects keep their own unknown keys).
QJsonValue unknownPart(const QJsonValue& original, const QJsonValue& known) {
  if (!original.isObject() || !known.isObject()) return QJsonValue(QJsonValue::Undefined);
  const QJsonObject o = original.toObject(), k = known.toObject();
  QJsonObject out;
  for (auto it = o.begin(); it != o.end(); ++it) {
    if (!k.contains(it.key())) {
      out.insert(it.key(), it.value());
    } else {
      const QJsonValue u = unknownPart(it.value(), k.value(it.key()));
      if (u.isObject() && !u.toObject().isEmpty()) out.insert(it.key(), u);
    }
  }
  return out;
}

}  // namespace

QJsonObject unknownKeys(const QJsonObject& original, const QJsonObject& known) {
  return unknownPart(original, known).toObject();
}

const std::optional<std::vector<double>>* SupervisorPassesSpec::of(const QString& controller) const {
  if (controller == "none") return &none;
  if (controller == "smc1") return &smc1;
  if (controller == "smc2") return &smc2;
  return nullptr;
}

const std::optional<GrafcetChartSpec>* SupervisorChartsSpec::of(const QString& controller) const {
  if (controller == "none") return &none;
  if (controller == "smc1") return &smc1;
  if (controller == "smc2") return &smc2;
  return nullptr;
}

std::optional<GrafcetChartSpec>* SupervisorChartsSpec::of(const QString& controller) {
  return const_cast<std::optional<GrafcetChartSpec>*>(std::as_const(*this).of(controller));
}

}  // namespace mx::app
