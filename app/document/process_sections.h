#pragma once
// The typed process sections of a project (control, sdnrp, force_control, part_program, supervisor,
// pareto), in the file's shop units. Every key the file may omit is a std::optional, so that a save
// writes back exactly what was there; defaults are applied by the request builders (app/services/*_request).
// Ranges: project_validation.cpp; keys, units and defaults: docs/project-file.md.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "grafcet/grafcet_chart.h"

namespace mx::app {

// One step of a depth profile along the feed path.
struct DepthStepSpec {
  double length_mm = 0.0;  // (0, 1e7]
  double depth_mm = 0.0;   // [0, 1000]
  QJsonObject unknown;     // the file's keys this build does not know; they stay with this step
  bool operator==(const DepthStepSpec&) const = default;
};

struct ControlReferenceModelSpec {
  std::optional<double> damping;            // [0.05, 5], default 0.75
  std::optional<double> rise_time_periods;  // [0.5, 1000], default 4
  bool operator==(const ControlReferenceModelSpec&) const = default;
};

struct ControlRlsSpec {
  std::optional<double> lambda;          // [0.5, 1], default 1
  std::optional<double> P0;              // [1e-6, 1e15], default 1e5
  std::optional<double> theta0;          // [-1e6, 1e6], default 0.2
  std::optional<QString> reset;          // "error" (default), "trace" or "none"
  std::optional<double> reset_fraction;  // (0, 10], default 0.05
  std::optional<double> trace_min;       // [0, 1e15], default 1e-6
  std::optional<double> trace_max;       // (0, 1e300], default 1e12; > trace_min
  bool operator==(const ControlRlsSpec&) const = default;
};

// One programmed point of "control.programme" (Pareto paper, Fig. 6: the Table 4 points in sequence).
struct ControlProgrammePointSpec {
  double speed_rpm = 0.0;           // (0, 100000]
  double depth_mm = 0.0;            // (0, 1000]
  double length_mm = 0.0;           // (0, 1e7], tool path cut at this point
  std::optional<double> feed_mm_s;  // (0, 1e5], the point's own programmed feed, reported beside the controller's
  QJsonObject unknown;              // the file's keys this build does not know
  bool operator==(const ControlProgrammePointSpec&) const = default;
};

// "control": adaptive force control under beta-FROH.
struct ControlSection {
  std::optional<QString> tool;                   // default the first tool
  std::optional<double> spindle_rpm;             // required
  std::optional<double> cutting_pressure_N_mm2;  // default material.Kt_N_mm2
  std::optional<double> start_angle_deg;
  std::optional<double> exit_angle_deg;
  std::optional<double> drive_time_constant_ms;
  std::optional<double> process_time_constant_ms;
  std::optional<double> beta;
  std::optional<double> force_reference_N;
  std::optional<double> breakage_force_N;
  std::optional<double> safety_factor;
  std::optional<double> feed_max_mm_s;
  std::optional<ControlReferenceModelSpec> reference_model;
  std::optional<ControlRlsSpec> rls;
  std::optional<std::vector<DepthStepSpec>> workpiece;
  std::optional<QString> sample_period;  // "spindle" (default) or "rule4" (Pareto paper, Rule 4)
  std::optional<double> rule4_periods;   // k of Rule 4, an integer in [1, 100], default 4
  std::optional<std::vector<ControlProgrammePointSpec>> programme;  // replaces spindle_rpm and workpiece
  bool operator==(const ControlSection&) const = default;
};

struct SdnrpDisturbanceSpec {
  std::optional<bool> enabled;  // default true
  std::optional<double> seed;   // integer in [0, 9e15], default 2008
  std::optional<double> sigma_N;
  std::optional<double> hold_ms;
  bool operator==(const SdnrpDisturbanceSpec&) const = default;
};

struct SdnrpInitialSpec {
  std::optional<double> feed_mm_min;
  std::optional<double> speed_rpm;
  bool operator==(const SdnrpInitialSpec&) const = default;
};

struct SdnrpDrivesSpec {
  std::optional<double> feed_natural_frequency_rad_s;
  std::optional<double> feed_damping;
  std::optional<double> spindle_time_constant_s;
  bool operator==(const SdnrpDrivesSpec&) const = default;
};

// "sdnrp": Cus & Zuperl's surface-roughness loop.
struct SdnrpSection {
  std::optional<double> ra_um;
  std::optional<double> seconds;
  std::optional<SdnrpDisturbanceSpec> disturbance;
  std::optional<SdnrpInitialSpec> initial;
  std::optional<SdnrpDrivesSpec> drives;
  std::optional<double> integral_rate_per_s;
  bool operator==(const SdnrpSection&) const = default;
};

struct ForceModelSpec {
  std::optional<double> K_N;
  std::optional<double> depth_exponent;
  std::optional<double> feed_exponent;
  bool operator==(const ForceModelSpec&) const = default;
};

// "force_control": the model-based controller F = K d^b f^a.
struct ForceControlSection {
  std::optional<QString> tool;
  std::optional<ForceModelSpec> model;
  std::optional<double> reference_force_N;  // required by the model-based controller
  std::optional<double> max_feed_mm_s;
  std::optional<double> max_feed_per_tooth_mm;
  bool operator==(const ForceControlSection&) const = default;
};

// "part_program": part-program feed overrides.
struct PartProgramSection {
  std::optional<double> stock_top_mm;
  std::optional<std::vector<DepthStepSpec>> depth_profile;
  std::optional<double> speed_rpm;
  std::optional<bool> keep_plunge_feed;  // default true
  std::optional<QString> controller;     // "adaptive" or "model-based"
  bool operator==(const PartProgramSection&) const = default;
};

struct SupervisorPartSpec {
  std::optional<double> length_mm;
  std::optional<double> width_mm;
  std::optional<double> approach_mm;
  bool operator==(const SupervisorPartSpec&) const = default;
};

struct SupervisorPassesSpec {  // pass depths [mm] per controller
  std::optional<std::vector<double>> none;
  std::optional<std::vector<double>> smc1;
  std::optional<std::vector<double>> smc2;
  const std::optional<std::vector<double>>* of(const QString& controller) const;
  bool operator==(const SupervisorPassesSpec&) const = default;
};

// Module L, the model-based force loop (engine/control/model_based_force_loop.h).
struct SupervisorModelControllerSpec {
  std::optional<double> time_constant_ms;  // closed-loop force time constant
  std::optional<QString> reset_feed;       // "current" or "model"
  bool operator==(const SupervisorModelControllerSpec&) const = default;
};

struct SupervisorEventSpec {
  double t_s = 0.0;
  QString type;         // "feed_hold_on", "feed_hold_off" or "chatter"
  QJsonObject unknown;  // the file's keys this build does not know; they stay with this event
  bool operator==(const SupervisorEventSpec&) const = default;
};

// What the file holds for a Grafcet chart, step or transition beyond the engine's struct.
struct GrafcetJsonKeys {
  QJsonObject unknown;           // keys this build does not know (e.g. an editor's layout)
  QStringList defaults_written;  // optional keys the file wrote at their default ("priority": 1)

  bool operator==(const GrafcetJsonKeys&) const = default;
};

// One Grafcet chart (docs/grafcet.md) as read by app/document/project_grafcet_io.h: structure and id
// ranges are checked on load, the chart's content (reachability, receptivities) by the run.
struct GrafcetChartSpec {
  GrafcetChart chart;
  GrafcetJsonKeys keys;                      // the chart object's
  std::vector<GrafcetJsonKeys> steps;        // by position in chart.steps; past its end: none
  std::vector<GrafcetJsonKeys> transitions;  // by position in chart.transitions; past its end: none

  bool operator==(const GrafcetChartSpec&) const = default;
};

struct SupervisorChartsSpec {  // the Grafcet chart per controller
  std::optional<GrafcetChartSpec> none;
  std::optional<GrafcetChartSpec> smc1;
  std::optional<GrafcetChartSpec> smc2;
  const std::optional<GrafcetChartSpec>* of(const QString& controller) const;  // nullptr: no such controller
  std::optional<GrafcetChartSpec>* of(const QString& controller);

  bool operator==(const SupervisorChartsSpec&) const = default;
};

// "supervisor": supervisory control of face milling.
struct SupervisorSection {
  std::optional<QString> tool;
  std::optional<double> spindle_rpm;
  std::optional<double> programmed_feed_mm_s;
  std::optional<SupervisorPartSpec> part;
  std::optional<SupervisorPassesSpec> passes_mm;
  std::optional<double> scan_period_ms;
  std::optional<double> reference_force_N;
  std::optional<double> power_margin;
  std::optional<double> chatter_threshold_N;
  std::optional<SupervisorModelControllerSpec> model_controller;
  std::optional<std::vector<SupervisorEventSpec>> events;
  std::optional<SupervisorChartsSpec> charts;
  bool operator==(const SupervisorSection&) const = default;
};

// A power law K V^a b^b s_t^c (V [m/min], b [mm], s_t [mm/tooth]).
struct PowerLawSpec {
  double K = 0.0;
  double speed_exponent = 0.0;
  double depth_exponent = 0.0;
  double feed_exponent = 0.0;
  bool operator==(const PowerLawSpec&) const = default;
};

struct ParetoFineSpec {
  std::optional<double> divisions;  // integer in [1, 100], default 5
  bool operator==(const ParetoFineSpec&) const = default;
};

struct ParetoAutoWeightsSpec {
  std::optional<double> step;
  std::optional<double> tolerance;
  std::optional<double> max_iterations;
  bool operator==(const ParetoAutoWeightsSpec&) const = default;
};

// "pareto.economics": Gilbert's machining economics (cost and time per part), shop units.
struct ParetoEconomicsSpec {
  double machine_rate_per_h = 0.0;  // machine and operator cost per hour, in the shop's currency
  double tool_cost = 0.0;           // cost of one tool (or cutting edge) life, same currency
  double tool_change_min = 0.0;     // time to change the tool
  double removal_volume_cm3 = 0.0;  // material removed per part
  bool operator==(const ParetoEconomicsSpec&) const = default;
};

// "pareto.requirements": Rule 11 requirements the selected point must meet (shop defaults apply).
struct ParetoRequirementsSpec {
  std::optional<double> min_mrr_cm3_s;       // absolute minimum MRR
  std::optional<double> min_mrr_fraction;    // minimum MRR as a share of Q's largest, default 0.25
  std::optional<double> max_time_min;        // machining time for removal_volume_cm3
  std::optional<double> removal_volume_cm3;  // default: pareto.economics.removal_volume_cm3
  bool operator==(const ParetoRequirementsSpec&) const = default;
};

// "pareto": the Pareto expert system.
struct ParetoSection {
  std::optional<QString> tool;
  std::optional<PowerLawSpec> taylor;     // required
  std::optional<PowerLawSpec> roughness;  // required
  std::optional<std::vector<double>> weights;
  std::optional<ParetoFineSpec> fine;
  std::optional<ParetoAutoWeightsSpec> auto_weights;
  std::optional<QString> normalisation;  // "minmax" | "max" | "log" (default "log")
  std::optional<QString> objective;      // "weighted" (default) | "min_cost" | "max_rate"
  std::optional<ParetoEconomicsSpec> economics;
  std::optional<ParetoRequirementsSpec> requirements;
  bool operator==(const ParetoSection&) const = default;
};

}  // namespace mx::app
