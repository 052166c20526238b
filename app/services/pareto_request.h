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
//   }
//   "operator_rules": ["if tool.diameter_mm < 10 then speed_rpm <= 8000", ...]
//       optional top-level array of strings, element i = rule line i + 1 (Rule 18; pareto_rules.h)
#include <QString>
#include <QStringList>
#include <optional>

#include "document/project.h"
#include "pareto/empirical_models.h"
#include "pareto/pareto_selector.h"
#include "pareto/pareto_weights.h"
#include "pareto/weight_modulation.h"

namespace mx::app {

struct ParetoRequest {
  QString tool;
  ParetoModels models;
  ParetoWeights weights{0.25, 0.25, 0.25, 0.25};
  FineSearchSettings fine;
  GradientAscentSettings ascent;
  QStringList operator_rules;  // the project's "operator_rules", as written
};

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
