#pragma once
// The project's "pareto" section in engine form. The section is typed in
// document/process_sections.h and range-checked when the project is loaded (ProjectError, exit 2,
// naming the field, the value and the allowed range):
//   "pareto": {
//     "tool": "R1",                                   optional; default the first tool
//     "taylor":    {"K", "speed_exponent", "depth_exponent", "feed_exponent"},   TOL [min] (eq. 10)
//     "roughness": {"K", "speed_exponent", "depth_exponent", "feed_exponent"},   SURF [um] (eq. 12)
//         V [m/min], b [mm], s_t [mm/tooth]; K > 0, |exponent| <= 10; other keys (printed_K) ignored
//     "weights": [w_tol, w_mrr, w_surf, w_ros],       on the simplex (Rule 8)
//     "fine": {"divisions": 5},                       [1, 100] (Rule 10.2)
//     "auto_weights": {"step": 0.05, "tolerance": 1e-4, "max_iterations": 200}   (Rule 12)
//     "normalisation": "log" | "minmax" | "max",      Rule 9 (objective_table.h); default "log"
//     "objective": "weighted" | "min_cost" | "max_rate",   default "weighted" (J of eq. 9)
//     "economics": {"machine_rate_per_h", "tool_cost", "tool_change_min", "removal_volume_cm3"}
//         Gilbert's cost and time per part (pareto/machining_economics.h); needed by min_cost, max_rate
//     "requirements": one of {"min_mrr_cm3_s"}, {"min_mrr_fraction"} (of Q's largest MRR),
//         {"max_time_min", "removal_volume_cm3"}: the Rule 11 minimum MRR; default min_mrr_fraction 0.25
//   }
//   "operator_rules": ["if tool.diameter_mm < 10 then speed_rpm <= 8000", ...]
//       optional top-level array of strings, element i = rule line i + 1 (Rule 18; pareto_rules.h)
#include <QString>
#include <QStringList>
#include <optional>

#include "document/project.h"
#include "pareto/empirical_models.h"
#include "pareto/machining_economics.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_selector.h"
#include "pareto/pareto_weights.h"
#include "pareto/weight_modulation.h"

namespace mx::app {

enum class ParetoObjectiveKind { Weighted, MinCost, MaxRate };

// The Rule 11 minimum MRR of the project (a shop default when the project says nothing), so that
// weights favouring tool life and roughness cannot select a cut that removes almost nothing.
struct MinimumMrr {
  enum class Basis { FractionOfMax, Absolute, TimeForVolume };
  Basis basis = Basis::FractionOfMax;
  double value = 0.25;     // fraction, m^3/s, or the time [s]
  double volume_m3 = 0.0;  // TimeForVolume
  QString field = "pareto.requirements.min_mrr_fraction";
  bool is_default = true;                         // not written in the project
  double resolve(double max_mrr_m3_per_s) const;  // the bound [m^3/s]
  QString describe(double max_mrr_m3_per_s) const;
};

inline constexpr double kDefaultMinMrrFraction = 0.25;

struct ParetoRequest {
  QString tool;
  ParetoModels models;
  ParetoWeights weights{0.25, 0.25, 0.25, 0.25};
  FineSearchSettings fine;
  GradientAscentSettings ascent;
  QStringList operator_rules;  // the project's "operator_rules", as written
  ParetoNormalisation normalisation = ParetoNormalisation::Log;
  ParetoObjectiveKind objective = ParetoObjectiveKind::Weighted;
  std::optional<MachiningEconomics> economics;
  MinimumMrr minimum_mrr;
};

// "minmax" | "max" | "log"; InputError naming `field` otherwise.
ParetoNormalisation paretoNormalisationFromName(const QString& name, const QString& field);
QString paretoNormalisationName(ParetoNormalisation n);
// "weighted" | "min_cost" | "max_rate".
ParetoObjectiveKind paretoObjectiveFromName(const QString& name, const QString& field);
QString paretoObjectiveName(ParetoObjectiveKind k);

ParetoRequest paretoRequestFrom(const ParetoSection& section, const Project& project);
// The project's pareto section; ProjectError when it has none.
ParetoRequest paretoRequestFromProject(const Project& project);

// The project's top-level "operator_rules" (empty when absent).
QStringList operatorRulesFromProject(const Project& project);

// "--w a,b,c,d": four weights on the simplex.
ParetoWeights parseParetoWeights(const QString& text);

// "--require KEY=LO:HI" with KEY one of mrr_cm3_s, tol, surf, ros; converted to engine units.
ObjectiveRequirement parseRequirement(const QString& text);

}  // namespace mx::app
