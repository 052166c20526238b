// millexpert-cli rank PROJECT [--c c1,c2,c3] [--cr c1r,c2r,c3r] [--no-simulation] [--method zoa|sdm]
//                 [--dynamics modal|measured] [--chatter-at SPEED:DEPTH[:FREQ_HZ]]... [--chatter-tool ID]
// The 2006 expert system (section 3): Rule 4 tool ranking by minimum tool cost (eq. 13), q* of the
// selected tool, Rule 5 q** by C_resultant (eq. 18-20) from a pattern search around q* (seeded with the
// best K points by C, every point simulated in the time domain), Rule 6 malfunction loop. Prints
//   {"selected", "ranking": [{"tool","min_cost","q":{...},"power_W","peak_force_N","max_force_N" (F_allow,
//    null: none),"mrr_mm3_min","dNs_rpm"}...],
//    "q_star", "q_star_star" (null with --no-simulation), "malfunction_iterations",
//    "c" (the weights after Rule 6), "method", "dynamics_used": {tool: "modal"|"measured"},
//    "excluded": [{"tool","reason"}...], "reported_chatter": [{"tool","speed_rpm","depth_mm","freq_Hz",
//    "region","holds_chosen_point"}...], "reported_chatter_iterations", "malfunction_limit_reached",
//    "rule5": {"candidates" (points scored), "seeds" (of them the best K by C), "iterations",
//              "converged" (steps below the resolutions), "simulations" (run, not from the cache),
//              "c_resultant" (at q**)} (null with --no-simulation),
//    "notes" (when the ZOA leaves a material's process damping out; services/cutting_data_json.h)}.
//    Tools with a tap test use it with --dynamics measured.
// Rule 6 on evidence: chatter observed at the machine (the project's expert.reported_chatter and each
//   --chatter-at, rpm:mm[:Hz], of --chatter-tool, default the tool Rule 4 selects at the given weights)
//   steps the weights until the chosen point (q**, q* with --no-simulation) leaves every reported
//   region of its tool (+-2 % in speed, the reported depth and deeper). Exit 1, after the JSON, when
//   the loop stops at expert.max_malfunction_iterations with the point still in a region.
// Module VII operator rules (Rule 18, docs/operator-rules.md), when the project has "operator_rules":
//   each tool's rules are evaluated in its own context; fired constraints on the point variables
//   restrict that tool's points (a tool left without points is "excluded" with the reason "operator
//   rules"), fired weight.c1/c2/c3 bounds (over all tools) bound c before Rule 4; added key "rules":
//   the fired rules and advice at the selected tool's q* (as in `pareto`).
// Exit 2: weights off the simplex, a bad project or operator rules; exit 1: empty admissible space
// (message names the constraint that emptied it) or the operator rules exclude every point.
#include <QJsonArray>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_computations.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "expert/expert_session.h"
#include "model/cutting_force.h"
#include "services/cutting_data_json.h"
#include "services/expert_request.h"
#include "services/expert_rules.h"
#include "services/pareto_request.h"
#include "services/pareto_rules.h"
#include "services/reported_chatter.h"

namespace mx::app {

namespace {

// Grid values without the noise of the unit conversions: 12 significant digits.
double rounded(double value) {
  return QString::number(value, 'g', 12).toDouble();
}

QJsonObject pointJson(const ExpertPoint& q) {
  return {{"speed_rpm", rounded(revPerSToRpm(q.speed_rev_per_s))},
          {"depth_mm", rounded(q.depth_m * 1e3)},
          {"feed_mm_per_tooth", rounded(q.feed_per_tooth_m * 1e3)}};
}

// The Rule 5 pattern search (rule5_search.h) behind q**.
QJsonObject rule5Json(const Refinement& r) {
  return {{"candidates", static_cast<qint64>(r.candidates.size())},
          {"seeds", static_cast<qint64>(r.seed_count)},
          {"iterations", r.search_iterations},
          {"converged", r.search_converged},
          {"simulations", static_cast<qint64>(r.simulations_run)},
          {"c_resultant", r.chosen().resultant}};
}

// The --chatter-at reports, for --chatter-tool or the tool Rule 4 selects at the request's weights.
std::vector<ChatterReportSpec> commandLineReports(const QCommandLineParser& parser, const ExpertRequest& request,
                                                  const ExpertSession& session) {
  const QStringList texts = parser.values("chatter-at");
  if (texts.isEmpty()) return {};
  QString tool = parser.value("chatter-tool");
  if (!parser.isSet("chatter-tool")) {
    const Ranking r = session.rank(request.weights.c);
    if (r.tools.empty())
      throw CliError("--chatter-at: no tool has an admissible point to report it on", kExitComputationFailed);
    tool = request.tool_ids[static_cast<qsizetype>(r.selected().tool)];
  } else if (!request.tool_ids.contains(tool)) {
    throw CliError(
        QString("--chatter-tool = %1: must be one of %2").arg(quoted(tool), shortened(request.tool_ids.join(", "))),
        kExitBadInput);
  }
  std::vector<ChatterReportSpec> out;
  for (const QString& t : texts) out.push_back(parseChatterAt(t, tool));
  return out;
}

QJsonArray reportedChatterArray(const std::vector<ChatterReportSpec>& reports, const ExpertResult& result,
                                const QStringList& tool_ids) {
  QJsonArray out;
  for (const ChatterReportSpec& c : reports) out.append(reportedChatterJson(c, result, tool_ids));
  return out;
}

}  // namespace

QList<QCommandLineOption> rankOptions() {
  return {
      {"c", "Tool-cost weights c1,c2,c3 (power, MRR, Delta N_s); sum 1. Default: the project's.", "C1,C2,C3"},
      {"cr", "Resultant-cost weights c1r,c2r,c3r (C, C_t, C_f); sum 1. Default: the project's.", "C1R,C2R,C3R"},
      {"no-simulation", "Rule 4 only: no time-domain refinement (q_star_star null, no Rule 6)."},
      {"method", "Lobes: zoa (default) or sdm; default: the project's expert.method.", "METHOD"},
      dynamicsCommandOption(),
      {"chatter-at",
       "Chatter observed at the machine at SPEED [rpm] and DEPTH [mm] (FREQ_HZ: its frequency); repeatable. "
       "Rule 6 moves the weights until the chosen point leaves +-2 % of SPEED at DEPTH and deeper.",
       "SPEED:DEPTH[:FREQ_HZ]"},
      {"chatter-tool", "The tool of the --chatter-at reports (default: the tool Rule 4 selects).", "ID"},
  };
}

RankWeightFlags readRankWeights(const QCommandLineParser& parser) {
  RankWeightFlags weights;
  if (parser.isSet("c")) weights.c = parseWeightList("c", parser.value("c"), 3);
  if (parser.isSet("cr")) weights.cr = parseWeightList("cr", parser.value("cr"), 3);
  return weights;
}

RankOutput rankJson(const QCommandLineParser& parser, const Project& project) {
  const RankWeightFlags weights = readRankWeights(parser);
  ExpertRequest request = expertRequestFromProject(project);
  applyMethodOption(parser, request.settings);
  const bool simulate = !parser.isSet("no-simulation");
  const std::vector<DynamicsChoice> dynamics = applyExpertDynamics(project, request, dynamicsOption(parser), simulate);
  QJsonObject dynamics_used;
  for (qsizetype i = 0; i < request.tool_ids.size(); ++i) {
    reportDynamicsNote(dynamics[static_cast<std::size_t>(i)], request.tool_ids[i]);
    dynamics_used.insert(request.tool_ids[i], dynamicsName(dynamics[static_cast<std::size_t>(i)].used));
  }
  if (weights.c) std::copy(weights.c->begin(), weights.c->end(), request.weights.c.begin());
  if (weights.cr) std::copy(weights.cr->begin(), weights.cr->end(), request.weights.cr.begin());

  const ExpertRules rules(project, request.tool_ids);
  request.weights.c = rules.boundWeights(request.weights.c);

  ExpertSession session(request.tools, request.settings, request.tool_force_limits_n);
  if (session.empty()) throw CliError(QString::fromStdString(session.emptyReason()), kExitComputationFailed);
  if (!rules.empty()) {
    rules.filter(session);
    if (ExpertRules::excludeEverything(session))
      throw CliError("the operator rules exclude every admissible point of every tool", kExitComputationFailed);
  }
  std::vector<ChatterReportSpec> reports = project.requireExpert().reported_chatter;
  const std::vector<ChatterReportSpec> flagged = commandLineReports(parser, request, session);
  reports.insert(reports.end(), flagged.begin(), flagged.end());
  const ExpertResult result = session.run(request.weights, simulate, engineChatterReports(reports, request.tool_ids));

  QJsonArray ranking;
  for (const ToolChoice& t : result.ranking.tools) {
    const AdmissibleGrid& grid = session.grid(t.tool);
    const double force_limit = grid.settings().limits.max_tool_force_n;
    ranking.append(
        QJsonObject{{"tool", request.tool_ids[static_cast<qsizetype>(t.tool)]},
                    {"min_cost", t.min_cost},
                    {"q", pointJson(t.q)},
                    {"power_W", t.q.power_w},
                    {"peak_force_N",
                     evaluateCut(grid.setup(), {t.q.speed_rev_per_s, t.q.depth_m, t.q.feed_per_tooth_m}).peak_force_n},
                    {"max_force_N", std::isfinite(force_limit) ? QJsonValue(force_limit) : QJsonValue()},
                    {"mrr_mm3_min", t.q.mrr_m3_per_s * 1e9 * 60.0},
                    {"dNs_rpm", revPerSToRpm(t.q.speed_security)}});
  }
  QJsonArray excluded;
  for (std::size_t t : result.ranking.excluded)
    excluded.append(
        QJsonObject{{"tool", request.tool_ids[static_cast<qsizetype>(t)]},
                    {"reason", session.filteredOut(t)
                                   ? QString("operator rules: no admissible point satisfies the fired constraints")
                                   : QString::fromStdString(describeConstraint(session.grid(t).funnel().emptiedBy(),
                                                                               session.grid(t).settings()))}});
  const ToolChoice& selected = result.ranking.selected();
  QJsonObject out{
      {"selected", request.tool_ids[static_cast<qsizetype>(selected.tool)]},
      {"ranking", ranking},
      {"q_star", pointJson(selected.q)},
      {"q_star_star", result.refinement ? QJsonValue(pointJson(result.refinement->chosen().q)) : QJsonValue()},
      {"malfunction_iterations", result.malfunction_iterations},
      {"c", QJsonArray{result.weights.c[0], result.weights.c[1], result.weights.c[2]}},
      {"method", request.settings.stability.method == StabilityMethod::ZeroOrder ? "zoa" : "sdm"},
      {"dynamics_used", dynamics_used},
      {"excluded", excluded},
      {"reported_chatter", reportedChatterArray(reports, result, request.tool_ids)},
      {"reported_chatter_iterations", result.reported_chatter_iterations},
      {"malfunction_limit_reached", result.malfunction_limit_reached}};
  out.insert("rule5", result.refinement ? QJsonValue(rule5Json(*result.refinement)) : QJsonValue());
  for (const MillingSetup& tool : request.tools) {  // once: every tool cuts the project's material
    const QString note = processDampingNote(request.settings.stability.method, tool);
    if (note.isEmpty()) continue;
    out.insert("notes", QJsonArray{note});
    break;
  }
  if (!rules.empty()) {
    QJsonObject fired =
        rulesJson(rules.tool(selected.tool), paretoPointOf(selected.q), request.tools[selected.tool].teeth);
    fired.insert("tool", out.value("selected"));
    out.insert("rules", fired);
  }
  return {out, unresolvedChatterMessage(result, reports, request.tool_ids,
                                        request.settings.refinement.max_malfunction_iterations)};
}

int runRankCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Rank the project's tools and select the cutting parameters (expert system).");
  parser.addHelpOption();
  parser.addOptions(rankOptions());
  const QString path = parseSubcommand(parser, arguments);
  readRankWeights(parser);  // a bad flag is reported before a bad project
  const RankOutput output = rankJson(parser, loadProject(path));
  printJson(output.json);
  if (!output.unresolved_chatter.isEmpty()) throw CliError(output.unresolved_chatter, kExitComputationFailed);
  return kExitOk;
}

}  // namespace mx::app
