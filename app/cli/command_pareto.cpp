// millexpert-cli pareto PROJECT [--w tol,mrr,surf,ros] [--fine] [--require mrr_cm3_s=LO:HI] [--auto-weights]
// The Pareto expert system (module V): objectives TOL, MRR, SURF, ROS over the admissible space Q of
// the project's pareto.tool, Rule 9 normalisation, J = sum w_i n_i (Rule 8 weights), Rule 10.1 coarse
// selection, Rule 10.2 fine search (--fine), Rule 11 requirement bounds (--require, modifies the MRR
// weight, Rule 13 variant 2), Rule 12 gradient ascent on the weights (--auto-weights; Rule 13 variant 1).
// Prints {"q", "feed_velocity_mm_s", "mrr_cm3_s", "tol", "surf", "ros", "eta", "power_W", "weights",
//   "pareto_set": [{"q", "tol", "mrr_cm3_s", "surf", "ros"}...]} plus "j", "coarse_j", "points",
//   "requirement" ({"key","lo","hi","satisfied"}, with --require) and "ascent" (with --auto-weights).
// eta: time-domain simulation of q (expert.simulated revolutions of the refinement settings).
// Exit 2: bad project/pareto section/flags; exit 1: empty admissible space.
#include <QJsonArray>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/expert_request.h"
#include "cli/pareto_request.h"
#include "expert/admissible_grid.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_front.h"
#include "pareto/pareto_selector.h"
#include "pareto/weight_modulation.h"
#include "project/project.h"
#include "simulation/simulation.h"

namespace mx::app {

namespace {

double rounded(double value) { return QString::number(value, 'g', 12).toDouble(); }

QJsonObject qJson(const ParetoPoint& p) {
  return {{"speed_rpm", rounded(revPerSToRpm(p.speed_rev_per_s))},
          {"depth_mm", rounded(p.depth_m * 1e3)},
          {"feed_mm_per_tooth", rounded(p.feed_per_tooth_m * 1e3)}};
}

QJsonArray weightsJson(const ParetoWeights& w) { return {w[0], w[1], w[2], w[3]}; }

}  // namespace

int runParetoCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Pareto expert system: TOL, MRR, SURF and ROS objective (Rules 8-13).");
  parser.addHelpOption();
  parser.addOptions({
      {"w", "Weights tol,mrr,surf,ros on the simplex. Default: pareto.weights of the project.", "W1,W2,W3,W4"},
      {"fine", "Rule 10.2: refine around the coarse optimum."},
      {"require", "Rule 11 requirement KEY=LO:HI (KEY mrr_cm3_s, tol, surf or ros).", "KEY=LO:HI"},
      {"auto-weights", "Rule 12: gradient ascent on the weights (pareto.auto_weights step/tolerance)."},
  });
  const QString path = parseSubcommand(parser, arguments);
  std::optional<ParetoWeights> w_flag;
  if (parser.isSet("w")) w_flag = parseParetoWeights(parser.value("w"));
  std::optional<ObjectiveRequirement> requirement;
  if (parser.isSet("require")) requirement = parseRequirement(parser.value("require"));

  const Project project = loadProject(path);
  const ExpertRequest expert = expertRequestFromProject(project);
  const ParetoRequest request = paretoRequestFromProject(project);
  ParetoWeights weights = w_flag.value_or(request.weights);
  const MillingSetup setup = project.setupFor(request.tool);

  const AdmissibleGrid grid(setup, expert.settings);
  if (grid.empty())
    throw CliError(QString("the admissible space of tool '%1' is empty: %2")
                       .arg(request.tool,
                            QString::fromStdString(describeConstraint(grid.funnel().emptiedBy(), expert.settings))),
                   kExitComputationFailed);
  const ObjectiveTable table(grid, request.models);
  const ParetoSelector selector(table);

  QJsonObject out;
  if (requirement) {
    const RequirementResult r = applyRequirement(selector, weights, *requirement);
    weights = r.weights;
    const double scale = requirement->objective == Objective::Mrr ? 1e6 : 1.0;
    out.insert("requirement", QJsonObject{{"key", parser.value("require").section('=', 0, 0)},
                                          {"lo", requirement->lo * scale},
                                          {"hi", requirement->hi * scale},
                                          {"satisfied", r.satisfied},
                                          {"weights_changed", r.changed}});
  }
  if (parser.isSet("auto-weights")) {
    const GradientAscentResult a = ascendWeights(selector, weights, request.ascent, requirement);
    weights = a.weights;
    out.insert("ascent", QJsonObject{{"iterations", a.iterations}, {"converged", a.converged}});
  }
  ParetoSelection chosen = selector.coarse(weights, requirement);
  const double coarse_j = chosen.j;
  if (parser.isSet("fine")) chosen = selector.fine(chosen, weights, request.fine, requirement);
  if (requirement && out.contains("requirement")) {
    QJsonObject req = out.value("requirement").toObject();
    req.insert("satisfied", requirement->satisfiedBy(chosen.point));
    out.insert("requirement", req);
  }

  // eta of q from the time-domain simulation (Rule 15's chip ratio is reported beside it).
  SimulationOptions options;
  options.revolutions = expert.settings.refinement.revolutions;
  options.evaluated_revolutions = expert.settings.refinement.evaluated_revolutions;
  const ParetoPoint& q = chosen.point;
  const SimulationResult sim =
      simulateMilling(setup, {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}, options);

  QJsonArray front;
  for (std::size_t i : nonDominated(table.scores())) {
    const ParetoPoint& p = table.points()[i];
    front.append(QJsonObject{{"q", qJson(p)},
                             {"tol", p.tol()},
                             {"mrr_cm3_s", p.mrr() * 1e6},
                             {"surf", p.surf()},
                             {"ros", p.ros()}});
  }
  out.insert("q", qJson(q));
  out.insert("feed_velocity_mm_s", q.feed_per_tooth_m * setup.teeth * q.speed_rev_per_s * 1e3);
  out.insert("mrr_cm3_s", q.mrr() * 1e6);
  out.insert("tol", q.tol());
  out.insert("surf", q.surf());
  out.insert("ros", jsonNumberOrNull(q.ros()));
  out.insert("eta", sim.indicators.eta);
  out.insert("chip_ratio", sim.indicators.chip_ratio);
  out.insert("power_W", q.power_w);
  out.insert("weights", weightsJson(weights));
  out.insert("j", chosen.j);
  out.insert("coarse_j", coarse_j);
  out.insert("tool", request.tool);
  out.insert("points", static_cast<qint64>(table.size()));
  out.insert("pareto_set", front);
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
