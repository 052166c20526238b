// The process sections of projectFromJson: control, sdnrp, force_control, part_program,
// supervisor, pareto, operator_rules, and the expert extras.
#include <initializer_list>

#include "document/project_grafcet_io.h"
#include "document/project_sections_io.h"

namespace mx::app {

namespace {

template <typename Spec, typename Read>
std::optional<Spec> readOptional(const ObjectReader& r, const QString& key, Read read) {
  if (auto o = r.optionalObject(key)) return read(*o);
  return std::nullopt;
}

QJsonObject withoutKeys(QJsonObject o, std::initializer_list<const char*> keys) {
  for (const char* k : keys) o.remove(k);
  return o;
}

double requiredNumber(const ObjectReader& r, const QString& key, const QString& range) {
  if (!r.has(key)) throwMissingField(r.pathOf(key), range);
  return *r.optionalNumber(key);
}

std::optional<std::vector<DepthStepSpec>> readDepthSteps(const ObjectReader& r, const QString& key) {
  const std::optional<QJsonArray> array = r.optionalArray(key);
  if (!array) return std::nullopt;
  std::vector<DepthStepSpec> steps;
  for (qsizetype i = 0; i < array->size(); ++i) {
    const ObjectReader s = elementObject(*array, i, r.pathOf(key));
    steps.push_back({requiredNumber(s, "length_mm", "in (0, 1e7]"), requiredNumber(s, "depth_mm", "in [0, 1000]"),
                     withoutKeys(s.object(), {"length_mm", "depth_mm"})});
  }
  return steps;
}

std::optional<std::vector<double>> readNumberArray(const ObjectReader& r, const QString& key) {
  return r.optionalNumbers(key);
}

std::optional<std::vector<ControlProgrammePointSpec>> readProgramme(const ObjectReader& r, const QString& key) {
  const std::optional<QJsonArray> array = r.optionalArray(key);
  if (!array) return std::nullopt;
  std::vector<ControlProgrammePointSpec> points;
  for (qsizetype i = 0; i < array->size(); ++i) {
    const ObjectReader e = elementObject(*array, i, r.pathOf(key));
    ControlProgrammePointSpec p;
    p.speed_rpm = requiredNumber(e, "speed_rpm", "in (0, 100000]");
    p.depth_mm = requiredNumber(e, "depth_mm", "in (0, 1000]");
    p.length_mm = requiredNumber(e, "length_mm", "in (0, 1e7]");
    p.feed_mm_s = e.optionalNumber("feed_mm_s");
    p.unknown = withoutKeys(e.object(), {"speed_rpm", "depth_mm", "length_mm", "feed_mm_s"});
    points.push_back(p);
  }
  return points;
}

ControlSection readControl(const ObjectReader& r) {
  ControlSection c;
  c.tool = r.optionalString("tool");
  c.spindle_rpm = r.optionalNumber("spindle_rpm");
  c.cutting_pressure_N_mm2 = r.optionalNumber("cutting_pressure_N_mm2");
  c.start_angle_deg = r.optionalNumber("start_angle_deg");
  c.exit_angle_deg = r.optionalNumber("exit_angle_deg");
  c.drive_time_constant_ms = r.optionalNumber("drive_time_constant_ms");
  c.process_time_constant_ms = r.optionalNumber("process_time_constant_ms");
  c.beta = r.optionalNumber("beta");
  c.force_reference_N = r.optionalNumber("force_reference_N");
  c.breakage_force_N = r.optionalNumber("breakage_force_N");
  c.safety_factor = r.optionalNumber("safety_factor");
  c.feed_max_mm_s = r.optionalNumber("feed_max_mm_s");
  c.reference_model = readOptional<ControlReferenceModelSpec>(r, "reference_model", [](const ObjectReader& m) {
    return ControlReferenceModelSpec{m.optionalNumber("damping"), m.optionalNumber("rise_time_periods")};
  });
  c.rls = readOptional<ControlRlsSpec>(r, "rls", [](const ObjectReader& m) {
    ControlRlsSpec s;
    s.lambda = m.optionalNumber("lambda");
    s.P0 = m.optionalNumber("P0");
    s.theta0 = m.optionalNumber("theta0");
    s.reset = m.optionalString("reset");
    s.reset_fraction = m.optionalNumber("reset_fraction");
    s.trace_min = m.optionalNumber("trace_min");
    s.trace_max = m.optionalNumber("trace_max");
    return s;
  });
  c.workpiece = readDepthSteps(r, "workpiece");
  c.sample_period = r.optionalString("sample_period");
  c.rule4_periods = r.optionalNumber("rule4_periods");
  c.programme = readProgramme(r, "programme");
  return c;
}

SdnrpSection readSdnrp(const ObjectReader& r) {
  SdnrpSection s;
  s.ra_um = r.optionalNumber("ra_um");
  s.seconds = r.optionalNumber("seconds");
  s.disturbance = readOptional<SdnrpDisturbanceSpec>(r, "disturbance", [](const ObjectReader& d) {
    return SdnrpDisturbanceSpec{d.optionalBool("enabled"), d.optionalNumber("seed"), d.optionalNumber("sigma_N"),
                                d.optionalNumber("hold_ms")};
  });
  s.initial = readOptional<SdnrpInitialSpec>(r, "initial", [](const ObjectReader& i) {
    return SdnrpInitialSpec{i.optionalNumber("feed_mm_min"), i.optionalNumber("speed_rpm")};
  });
  s.drives = readOptional<SdnrpDrivesSpec>(r, "drives", [](const ObjectReader& d) {
    return SdnrpDrivesSpec{d.optionalNumber("feed_natural_frequency_rad_s"), d.optionalNumber("feed_damping"),
                           d.optionalNumber("spindle_time_constant_s")};
  });
  s.integral_rate_per_s = r.optionalNumber("integral_rate_per_s");
  return s;
}

ForceControlSection readForceControl(const ObjectReader& r) {
  ForceControlSection f;
  f.tool = r.optionalString("tool");
  f.model = readOptional<ForceModelSpec>(r, "model", [](const ObjectReader& m) {
    return ForceModelSpec{m.optionalNumber("K_N"), m.optionalNumber("depth_exponent"),
                          m.optionalNumber("feed_exponent")};
  });
  f.reference_force_N = r.optionalNumber("reference_force_N");
  f.max_feed_mm_s = r.optionalNumber("max_feed_mm_s");
  f.max_feed_per_tooth_mm = r.optionalNumber("max_feed_per_tooth_mm");
  return f;
}

PartProgramSection readPartProgram(const ObjectReader& r) {
  PartProgramSection p;
  p.stock_top_mm = r.optionalNumber("stock_top_mm");
  p.depth_profile = readDepthSteps(r, "depth_profile");
  p.speed_rpm = r.optionalNumber("speed_rpm");
  p.keep_plunge_feed = r.optionalBool("keep_plunge_feed");
  p.controller = r.optionalString("controller");
  return p;
}

SupervisorSection readSupervisor(const ObjectReader& r) {
  SupervisorSection s;
  s.tool = r.optionalString("tool");
  s.spindle_rpm = r.optionalNumber("spindle_rpm");
  s.programmed_feed_mm_s = r.optionalNumber("programmed_feed_mm_s");
  s.part = readOptional<SupervisorPartSpec>(r, "part", [](const ObjectReader& p) {
    return SupervisorPartSpec{p.optionalNumber("length_mm"), p.optionalNumber("width_mm"),
                              p.optionalNumber("approach_mm")};
  });
  s.passes_mm = readOptional<SupervisorPassesSpec>(r, "passes_mm", [](const ObjectReader& p) {
    return SupervisorPassesSpec{readNumberArray(p, "none"), readNumberArray(p, "smc1"), readNumberArray(p, "smc2")};
  });
  s.scan_period_ms = r.optionalNumber("scan_period_ms");
  s.reference_force_N = r.optionalNumber("reference_force_N");
  s.power_margin = r.optionalNumber("power_margin");
  s.chatter_threshold_N = r.optionalNumber("chatter_threshold_N");
  s.model_controller = readOptional<SupervisorModelControllerSpec>(r, "model_controller", [](const ObjectReader& m) {
    return SupervisorModelControllerSpec{m.optionalNumber("time_constant_ms"), m.optionalString("reset_feed")};
  });
  if (auto events = r.optionalArray("events")) {
    std::vector<SupervisorEventSpec> list;
    for (qsizetype i = 0; i < events->size(); ++i) {
      const ObjectReader e = elementObject(*events, i, r.pathOf("events"));
      list.push_back({requiredNumber(e, "t_s", "in [0, 1e5]"), e.optionalString("type").value_or(QString()),
                      withoutKeys(e.object(), {"t_s", "type"})});
    }
    s.events = list;
  }
  s.charts = readOptional<SupervisorChartsSpec>(r, "charts", [](const ObjectReader& c) {
    SupervisorChartsSpec charts;
    for (const QString controller : {"none", "smc1", "smc2"})
      if (c.has(controller)) *charts.of(controller) = grafcetChartFromJson(c.value(controller), c.pathOf(controller));
    return charts;
  });
  return s;
}

PowerLawSpec readPowerLaw(const ObjectReader& r) {
  PowerLawSpec m;
  m.K = requiredNumber(r, "K", "a finite number > 0");
  m.speed_exponent = requiredNumber(r, "speed_exponent", "in [-10, 10]");
  m.depth_exponent = requiredNumber(r, "depth_exponent", "in [-10, 10]");
  m.feed_exponent = requiredNumber(r, "feed_exponent", "in [-10, 10]");
  return m;
}

ParetoSection readPareto(const ObjectReader& r) {
  ParetoSection p;
  p.tool = r.optionalString("tool");
  p.taylor = readOptional<PowerLawSpec>(r, "taylor", readPowerLaw);
  p.roughness = readOptional<PowerLawSpec>(r, "roughness", readPowerLaw);
  if (r.has("weights")) {
    const QJsonValue wv = r.value("weights");
    const QString message = r.pathOf("weights") + ": must be an array of 4 numbers";
    if (!wv.isArray()) throw ProjectError(message);
    std::vector<double> values;
    for (const auto& v : wv.toArray()) {
      if (!v.isDouble()) throw ProjectError(message);
      values.push_back(v.toDouble());
    }
    p.weights = values;
  }
  p.fine = readOptional<ParetoFineSpec>(
      r, "fine", [](const ObjectReader& f) { return ParetoFineSpec{f.optionalNumber("divisions")}; });
  p.auto_weights = readOptional<ParetoAutoWeightsSpec>(r, "auto_weights", [](const ObjectReader& a) {
    return ParetoAutoWeightsSpec{a.optionalNumber("step"), a.optionalNumber("tolerance"),
                                 a.optionalNumber("max_iterations")};
  });
  p.normalisation = r.optionalString("normalisation");
  p.objective = r.optionalString("objective");
  p.economics = readOptional<ParetoEconomicsSpec>(r, "economics", [](const ObjectReader& e) {
    return ParetoEconomicsSpec{
        requiredNumber(e, "machine_rate_per_h", "in [0, 1e6]"), requiredNumber(e, "tool_cost", "in [0, 1e6]"),
        requiredNumber(e, "tool_change_min", "in [0, 1e4]"), requiredNumber(e, "removal_volume_cm3", "in (0, 1e9]")};
  });
  p.requirements = readOptional<ParetoRequirementsSpec>(r, "requirements", [](const ObjectReader& q) {
    return ParetoRequirementsSpec{q.optionalNumber("min_mrr_cm3_s"), q.optionalNumber("min_mrr_fraction"),
                                  q.optionalNumber("max_time_min"), q.optionalNumber("removal_volume_cm3")};
  });
  return p;
}

std::optional<QStringList> readOperatorRules(const ObjectReader& root) {
  if (!root.has("operator_rules")) return std::nullopt;
  const QJsonValue rv = root.value("operator_rules");
  if (!rv.isArray()) throw ProjectError("operator_rules: must be an array of strings (one rule each)");
  const QJsonArray rules = rv.toArray();
  QStringList out;
  for (qsizetype i = 0; i < rules.size(); ++i) {
    if (!rules[i].isString() || rules[i].toString().contains('\n'))
      throw ProjectError(QString("operator_rules[%1]: must be a string holding one rule").arg(i));
    out << rules[i].toString();
  }
  return out;
}

}  // namespace

void readProcessSections(const ObjectReader& root, Project& p) {
  p.control = readOptional<ControlSection>(root, "control", readControl);
  p.sdnrp = readOptional<SdnrpSection>(root, "sdnrp", readSdnrp);
  p.force_control = readOptional<ForceControlSection>(root, "force_control", readForceControl);
  p.part_program = readOptional<PartProgramSection>(root, "part_program", readPartProgram);
  p.supervisor = readOptional<SupervisorSection>(root, "supervisor", readSupervisor);
  p.pareto = readOptional<ParetoSection>(root, "pareto", readPareto);
  p.operator_rules = readOperatorRules(root);
}

namespace {
constexpr FieldRange kRule5SpeedStep{1e-9, 1e5, "in (0, 1e5]"};
constexpr FieldRange kRule5DepthStep{1e-12, 100.0, "in (0, 100]"};
constexpr FieldRange kRule5FeedStep{1e-12, 10.0, "in (0, 10]"};
constexpr FieldRange kRule5Iterations{0.0, 1000.0, "an integer in [0, 1000]", true};

std::optional<double> checkedNumber(const ObjectReader& r, const QString& key, const FieldRange& range) {
  const std::optional<double> v = r.optionalNumber(key);
  if (v) checkField(r.pathOf(key), *v, range);
  return v;
}

Rule5SearchSpec readRule5Search(const ObjectReader& r) {
  Rule5SearchSpec s;
  s.speed_step_rpm = checkedNumber(r, "speed_step_rpm", kRule5SpeedStep);
  s.depth_step_mm = checkedNumber(r, "depth_step_mm", kRule5DepthStep);
  s.feed_step_mm = checkedNumber(r, "feed_step_mm", kRule5FeedStep);
  if (const auto n = checkedNumber(r, "max_iterations", kRule5Iterations)) s.max_iterations = static_cast<int>(*n);
  return s;
}
}  // namespace

void readExpertExtras(const ObjectReader& r, ExpertSpec& e) {
  e.method = r.optionalString("method");
  if (r.has("simulated_points")) {
    const double k = *r.optionalNumber("simulated_points");
    checkField(r.pathOf("simulated_points"), k, {1.0, 1000.0, "an integer in [1, 1000]", true});
    e.simulated_points = static_cast<int>(k);
  }
  if (auto search = r.optionalObject("rule5_search")) e.rule5_search = readRule5Search(*search);
  if (auto grid = r.optionalObject("grid"); grid && e.grid)
    e.grid->modal_candidate_speeds = grid->optionalBool("modal_candidate_speeds");
}

}  // namespace mx::app
