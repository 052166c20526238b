// millexpert-cli pareto PROJECT [--w tol,mrr,surf,ros] [--fine] [--require mrr_cm3_s=LO:HI] [--auto-weights]
//                    [--objective weighted|min_cost|max_rate] [--normalisation log|minmax|max] [--no-requirement]
// The Pareto expert system (module V): objectives TOL, MRR, SURF, ROS over the admissible space Q of
// the project's pareto.tool, Rule 9 normalisation, J = sum w_i n_i (Rule 8 weights), Rule 10.1 coarse
// selection, Rule 10.2 fine search (--fine), Rule 11 requirement bounds (--require, modifies the MRR
// weight, Rule 13 variant 2), Rule 12 gradient ascent on the weights (--auto-weights; Rule 13 variant 1).
// --dynamics modal|measured: the lobes of Q on the tool's modes or its tap-test FRF ("dynamics_used").
// Prints {"q", "feed_velocity_mm_s", "mrr_cm3_s", "tol", "surf", "ros", "eta", "power_W", "weights",
//   "pareto_set": [{"q", "tol", "mrr_cm3_s", "surf", "ros"}...]} plus "j", "coarse_j", "points",
//   "requirement" ({"key","lo","hi","satisfied"}, with --require) and "ascent" (with --auto-weights).
// eta: time-domain simulation of q (expert.simulated revolutions of the refinement settings).
// With the operator rules and weight pipeline (Pareto paper, modules VI and VII):
//   "rules" (when the project has "operator_rules"): Rule 18, pareto_rules.h. Order of the weights:
//     --w or pareto.weights -> weight.* rules (projection onto the simplex within the bounds)
//     -> Rule 11 (--require) -> Rule 12 (--auto-weights) -> weight.* rules again (final weights obey
//     them). Point constraints filter the coarse selection; with --fine, the fine optimum is kept only
//     when it obeys them (else the coarse one, "fine_rejected_by_rules": true). Rules 11/12 modulate the
//     weights without the point rules.
//   --feedback: module VI. Rule 15 on q's simulation (chip_ratio >= 1.25); on chatter, the Rule 16
//     Smith-Tlusty speed nearest q's inside the grid's speed range, then a coarse re-selection restricted
//     to the points of Q whose speed lies within +-2 % of it (the grid speed nearest it when none does),
//     and the operator rules. "feedback": {"chatter", "chip_ratio", "chatter_frequency_Hz",
//     "suggested_speed_rpm", "k", "reselected": {"q", "mrr_cm3_s", "tol", "surf", "ros", "j", "eta",
//     "chip_ratio", "chatter"} or null}.
//   --chatter-hz F: the operator reports chatter at F Hz (Module VI "reported by the operator"): Rule 16
//     and the re-selection as above without the Rule 15 check; "feedback" adds "reported_by": "operator".
//   --front-limit N: at most N points in "pareto_set" (default 2000, 0: all), the best J first; added
//     keys "pareto_set_size" (the whole set) and "pareto_set_truncated".
//   --db FILE|URL: records q (source "automatic") and the re-selected point (source "feedback"; ids in the
//     added key "recorded") in the
//     Rule 14 learning database; without --db nothing is recorded.
// Rule 11 by default: the project's minimum MRR (pareto.requirements; shop default 25 % of Q's largest
// MRR) unless --require replaces it or --no-requirement drops it; "requirement" adds "source", "binding"
// (the selection would differ without it) and "text". "binding": [{"key", "direction", "text"}]: the
// requirement when binding, operator rules q sits on, and the limits of Q one more step of depth or feed
// would break. "objective" and "normalisation" as used; "economics" (with pareto.economics):
// {"machining_time_min", "tool_changes_per_part", "time_per_part_min", "cost_per_part", "tool_life_min",
// "gilbert_tool_life_min"} (the tool life of Gilbert's optimum over speed alone; minimum cost for
// "weighted"; null when the Taylor speed exponent is >= -1).
// --objective min_cost|max_rate: q minimises Gilbert's cost or time per part instead of maximising J.
// Exit 2: bad project/pareto section/flags/operator rules (parse error or contradiction); exit 1: empty
// admissible space, or the operator rules exclude every point of it.
#include <QJsonArray>
#include <algorithm>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/project.h"
#include "expert/admissible_grid.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_front.h"
#include "pareto/pareto_selector.h"
#include "pareto/weight_modulation.h"
#include "services/expert_request.h"
#include "services/learning_database.h"
#include "services/pareto_request.h"
#include "services/pareto_rules.h"
#include "services/pareto_study.h"
#include "simulation/simulation.h"
#include "simulation/smith_tlusty.h"

namespace mx::app {

namespace {

double rounded(double value) {
  return QString::number(value, 'g', 12).toDouble();
}

QJsonObject qJson(const ParetoPoint& p) {
  return {{"speed_rpm", rounded(revPerSToRpm(p.speed_rev_per_s))},
          {"depth_mm", rounded(p.depth_m * 1e3)},
          {"feed_mm_per_tooth", rounded(p.feed_per_tooth_m * 1e3)}};
}

QJsonArray weightsJson(const ParetoWeights& w) {
  return {w[0], w[1], w[2], w[3]};
}

double operatorChatter(const QCommandLineParser& parser) {
  const std::optional<double> f = numberOption(parser, "chatter-hz", 1e-3, 1e6);
  return *f;
}

std::size_t frontLimit(const QCommandLineParser& parser) {
  if (!parser.isSet("front-limit")) return 2000;
  bool ok = false;
  const int n = parser.value("front-limit").toInt(&ok);
  if (!ok || n < 0)
    throw CliError(
        QString("--front-limit = %1: must be an integer >= 0 (0: no limit)").arg(parser.value("front-limit")),
        kExitBadInput);
  return static_cast<std::size_t>(n);
}

// Gilbert's optimal tool life of the objective (min_cost for "weighted"), from the Taylor speed exponent.
QJsonValue gilbertJson(const ParetoStudy& study, ParetoObjectiveKind objective) {
  const EconomicObjective o =
      objective == ParetoObjectiveKind::MaxRate ? EconomicObjective::MaxRate : EconomicObjective::MinCost;
  const std::optional<double> t =
      gilbertToolLife(*study.request().economics, study.request().models.tool_life.speed_exponent, o);
  return t ? QJsonValue(*t / 60.0) : QJsonValue();
}

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
      {"feedback", "Module VI: Rule 15 chatter check of q; on chatter, Rule 16 speed and a re-selection."},
      {"db",
       "Record the programmed point(s) in this Rule 14 learning database: an SQLite file or "
       "postgresql://user@host[:port]/db (the password from PGPASSWORD or ~/.pgpass).",
       "FILE|URL"},
      {"chatter-hz", "Module VI: the operator reports chatter at F Hz at q (implies --feedback; Rule 16).", "F"},
      {"front-limit", "At most N points in pareto_set, the best J first (default 2000; 0: all).", "N"},
      {"objective", "weighted, min_cost or max_rate (default: pareto.objective, else weighted).", "KIND"},
      {"normalisation", "Rule 9: log, minmax or max (default: pareto.normalisation, else log).", "KIND"},
      {"no-requirement", "Apply no Rule 11 requirement, not even the project's minimum MRR."},
      dynamicsCommandOption(),
  });
  const QString path = parseSubcommand(parser, arguments);
  std::optional<ParetoWeights> w_flag;
  if (parser.isSet("w")) w_flag = parseParetoWeights(parser.value("w"));
  std::optional<ObjectiveRequirement> requirement;
  if (parser.isSet("require")) requirement = parseRequirement(parser.value("require"));

  std::optional<ParetoObjectiveKind> objective;
  if (parser.isSet("objective")) objective = paretoObjectiveFromName(parser.value("objective"), "--objective");
  if (parser.isSet("normalisation"))
    paretoNormalisationFromName(parser.value("normalisation"), "--normalisation");  // checks the name

  const std::optional<DynamicsSource> dynamics = dynamicsOption(parser);
  OutputPaths files;
  if (parser.isSet("db") && !isLearningUrl(parser.value("db"))) files.outputOption(parser, "db");  // a file we write
  Project project = files.loadProject(path);
  if (parser.isSet("normalisation") && project.pareto) project.pareto->normalisation = parser.value("normalisation");
  const ParetoStudy study(std::move(project), dynamics);
  reportDynamicsNote(study.dynamics(), study.request().tool);
  requireFittedModes(study.tool(), "the time-domain simulation of q (eta)");
  const ExpertRequest& expert = study.expert();
  const ParetoRequest& request = study.request();
  const MillingSetup& setup = study.setup();
  const std::optional<ParetoRules>& rules = study.rules();
  const ObjectiveTable& table = study.table();

  ParetoChoiceOptions choose_options;
  choose_options.weights = w_flag;
  choose_options.requirement = requirement;
  choose_options.fine = parser.isSet("fine");
  choose_options.auto_weights = parser.isSet("auto-weights");
  choose_options.project_requirement = !parser.isSet("no-requirement");
  choose_options.objective = objective;
  const ParetoChoice choice = study.choose(choose_options);
  const ParetoWeights weights = choice.weights;
  const ParetoSelection& chosen = choice.selection;
  const double coarse_j = choice.coarse_j;
  QJsonObject out;
  if (choice.requirement) {
    const ObjectiveRequirement& r = *choice.requirement;
    const double scale = r.objective == Objective::Mrr ? 1e6 : 1.0;
    QJsonObject rj{{"key", requirement ? parser.value("require").section('=', 0, 0) : QString("mrr_cm3_s")},
                   {"lo", r.lo * scale},
                   {"hi", jsonNumberOrNull(r.hi * scale)},
                   {"satisfied", choice.requirement_satisfied},
                   {"weights_changed", choice.requirement_changed},
                   {"binding", choice.requirement_binding},
                   {"source", choice.requirement_source}};
    if (!choice.requirement_text.isEmpty()) rj.insert("text", choice.requirement_text);
    out.insert("requirement", rj);
  }
  QJsonArray binding;
  for (const BindingLimit& b : choice.binding)
    binding.append(QJsonObject{{"key", b.key}, {"direction", b.direction}, {"text", b.text}});
  out.insert("binding", binding);
  out.insert("objective", paretoObjectiveName(choice.objective));
  out.insert("normalisation", paretoNormalisationName(study.request().normalisation));
  if (choice.economics) {
    const PartEconomics& e = *choice.economics;
    out.insert("economics", QJsonObject{{"machining_time_min", e.machining_time_s / 60.0},
                                        {"tool_changes_per_part", e.tool_changes},
                                        {"time_per_part_min", e.time_per_part_s / 60.0},
                                        {"cost_per_part", e.cost_per_part},
                                        {"tool_life_min", choice.point().tol()},
                                        {"gilbert_tool_life_min", gilbertJson(study, choice.objective)}});
  }
  if (choice.ascent)
    out.insert("ascent",
               QJsonObject{{"iterations", choice.ascent->iterations}, {"converged", choice.ascent->converged}});
  if (choice.fine_rejected_by_rules) out.insert("fine_rejected_by_rules", true);

  // eta of q from the time-domain simulation (Rule 15's chip ratio is reported beside it).
  SimulationOptions options;
  options.revolutions = expert.settings.refinement.revolutions;
  options.evaluated_revolutions = expert.settings.refinement.evaluated_revolutions;
  const ParetoPoint& q = chosen.point;
  const SimulationResult sim = simulateMilling(setup, {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}, options);

  if (rules) out.insert("rules", rulesJson(*rules, q, setup.teeth));

  // Module VI feedback.
  std::optional<ParetoPoint> reselectedPoint;
  double reselectedEta = 0.0;
  if (parser.isSet("feedback") || parser.isSet("chatter-hz")) {
    const ChatterIndicators& ind = sim.indicators;
    const bool chatter = ind.chatter_by_chip_ratio;
    QJsonObject fb{{"chatter", chatter},
                   {"chip_ratio", ind.chip_ratio},
                   {"chatter_frequency_Hz",
                    chatter && ind.chatter_frequency_hz ? QJsonValue(*ind.chatter_frequency_hz) : QJsonValue()},
                   {"suggested_speed_rpm", QJsonValue()},
                   {"k", QJsonValue()},
                   {"reselected", QJsonValue()}};
    double chatter_hz = 0.0;  // 0: no chatter to act on
    if (parser.isSet("chatter-hz"))
      chatter_hz = operatorChatter(parser);
    else if (chatter && ind.chatter_frequency_hz)
      chatter_hz = *ind.chatter_frequency_hz;
    if (parser.isSet("chatter-hz")) {
      fb.insert("reported_by", "operator");
      fb.insert("chatter", true);
      fb.insert("chatter_frequency_Hz", chatter_hz);
    }
    if (const auto r =
            chatter_hz > 0.0 ? study.reselectAfterChatter(weights, requirement, chatter_hz, q) : std::nullopt) {
      fb.insert("suggested_speed_rpm", revPerSToRpm(r->suggested_rev_per_s));
      fb.insert("k", r->k);
      fb.insert("speed_window", r->within_window ? "within 2 %" : "nearest grid speed");
      if (r->selection) {
        const ParetoPoint& p = r->selection->point;
        const SimulationResult rsim =
            simulateMilling(setup, {p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m}, options);
        reselectedPoint = p;
        reselectedEta = rsim.indicators.eta;
        fb.insert("reselected", QJsonObject{{"q", qJson(p)},
                                            {"mrr_cm3_s", p.mrr() * 1e6},
                                            {"tol", p.tol()},
                                            {"surf", p.surf()},
                                            {"ros", jsonNumberOrNull(p.ros())},
                                            {"power_W", p.power_w},
                                            {"j", r->selection->j},
                                            {"eta", rsim.indicators.eta},
                                            {"chip_ratio", rsim.indicators.chip_ratio},
                                            {"chatter", rsim.indicators.chatter_by_chip_ratio}});
      }
    }
    out.insert("feedback", fb);
  }
  if (parser.isSet("db")) {
    try {
      LearningDatabase db(parser.value("db"));
      QJsonArray ids;
      ids.append(db.insert(study.learningRecord(weights, q, sim.indicators.eta, LearningSource::Automatic)));
      if (reselectedPoint)
        ids.append(db.insert(study.learningRecord(weights, *reselectedPoint, reselectedEta, LearningSource::Feedback)));
      out.insert("recorded", ids);
    } catch (const LearningDatabaseError& e) {
      throw CliError(QString::fromStdString(e.what()), kExitBadInput);
    }
  }

  // The non-dominated set, best J first when it is longer than --front-limit.
  std::vector<std::size_t> shown = study.front();
  const std::size_t limit = frontLimit(parser);
  if (limit > 0 && shown.size() > limit) {
    std::partial_sort(shown.begin(), shown.begin() + static_cast<std::ptrdiff_t>(limit), shown.end(),
                      [&](std::size_t a, std::size_t b) {
                        return objectiveJ(weights, table.scores()[a]) > objectiveJ(weights, table.scores()[b]);
                      });
    shown.resize(limit);
    std::sort(shown.begin(), shown.end());
  }
  QJsonArray front;
  for (std::size_t i : shown) {
    const ParetoPoint& p = table.points()[i];
    front.append(QJsonObject{
        {"q", qJson(p)}, {"tol", p.tol()}, {"mrr_cm3_s", p.mrr() * 1e6}, {"surf", p.surf()}, {"ros", p.ros()}});
  }
  out.insert("pareto_set_size", static_cast<qint64>(study.front().size()));
  out.insert("pareto_set_truncated", shown.size() < study.front().size());
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
  out.insert("dynamics_used", dynamicsName(study.dynamics().used));
  out.insert("points", static_cast<qint64>(table.size()));
  out.insert("pareto_set", front);
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
