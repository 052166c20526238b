// millexpert-cli weights-sweep PROJECT --c3 V [--step S]
//   {"c3": V, "c1": [...], "min_cost": {TOOL: [...]}}: minimum tool cost (eq. 13) against c1 with
//   c2 = 1 - c1 - c3 (the 2006 paper's figure 4); c1 = 0, S, 2S, ... and 1 - c3 (default S = 0.025).
// millexpert-cli weights-sweep PROJECT --simplex STEP
//   {"points": [{"c": [c1,c2,c3], "min_cost": {TOOL: x}, "selected": ID}...]} over the simplex
//   c1 = i STEP, c2 = j STEP, c3 = 1 - c1 - c2 >= 0 (figure 5).
// Tools with an empty admissible space get null. Lobes and grids are computed once; every weight is
// only a re-weighing of the cached grids (ExpertSession::minimumCosts). Exit codes as `rank`.
#include <QJsonArray>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "document/project.h"
#include "expert/expert_session.h"
#include "services/expert_request.h"

namespace mx::app {
namespace {

// Each weight vector ranks every tool (about 0.1 ms per tool): at most kMaxSweepRankings rankings, about
// 15 s on a 2-core machine.
constexpr double kMaxSweepRankings = 1.5e5;

void checkSweepSize(const QString& flag, double step, bool line, std::size_t tools) {
  const double n = std::floor(1.0 / step + 1e-9);
  const double vectors = line ? n + 2.0 : (n + 1.0) * (n + 2.0) / 2.0;
  const double rankings = vectors * static_cast<double>(tools);
  if (rankings > kMaxSweepRankings)
    throw CliError(QString("%1 = %2: %3 weight vectors x %4 tools = %5 rankings, at most %6 (about 15 s): raise %1")
                       .arg(flag)
                       .arg(step)
                       .arg(vectors, 0, 'f', 0)
                       .arg(tools)
                       .arg(rankings, 0, 'g', 3)
                       .arg(kMaxSweepRankings, 0, 'g', 3),
                   kExitBadInput);
}

}  // namespace

int runWeightsSweepCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Minimum tool cost of every tool against the weights (figures 4 and 5).");
  parser.addHelpOption();
  parser.addOptions({
      {"c3", "Fixed c3 in [0, 1]; c1 swept, c2 = 1 - c1 - c3 (figure 4).", "V"},
      {"step", "c1 step of the --c3 sweep (default 0.025).", "S"},
      {"simplex", "Grid step over the whole simplex (figure 5), in (0, 1].", "STEP"},
      {"method", "Lobes: zoa (default) or sdm; default: the project's expert.method.", "METHOD"},
  });
  const QString path = parseSubcommand(parser, arguments);
  if (parser.isSet("c3") == parser.isSet("simplex"))
    throw CliError("weights-sweep needs exactly one of --c3 V or --simplex STEP", kExitBadInput);
  const std::optional<double> c3 = numberOption(parser, "c3", 0.0, 1.0);
  const double step = numberOption(parser, "step", 1e-4, 1.0).value_or(0.025);
  const std::optional<double> simplex = numberOption(parser, "simplex", 1e-3, 1.0);
  if (simplex && !(*simplex > 0.0)) throw CliError("--simplex = 0: must be in (0, 1]", kExitBadInput);

  const Project project = loadProject(path);
  ExpertRequest request = expertRequestFromProject(project);
  applyMethodOption(parser, request.settings);
  checkSweepSize(c3 ? QString("--step") : QString("--simplex"), c3 ? step : *simplex, c3.has_value(),
                 request.tools.size());
  const ExpertSession session(request.tools, request.settings, request.tool_force_limits_n);
  if (session.empty()) throw CliError(QString::fromStdString(session.emptyReason()), kExitComputationFailed);
  const auto id = [&](std::size_t t) { return request.tool_ids[static_cast<qsizetype>(t)]; };

  if (c3) {
    const double span = 1.0 - *c3;
    std::vector<double> c1s;
    for (int i = 0; i * step <= span + 1e-12; ++i) c1s.push_back(std::min(i * step, span));
    if (c1s.back() < span - 1e-12) c1s.push_back(span);
    QJsonArray c1_json;
    std::vector<QJsonArray> per_tool(session.toolCount());
    for (double c1 : c1s) {
      c1_json.append(c1);
      const std::vector<double> costs = session.minimumCosts({c1, std::max(0.0, span - c1), *c3});
      for (std::size_t t = 0; t < costs.size(); ++t) per_tool[t].append(jsonNumberOrNull(costs[t]));
    }
    QJsonObject min_cost;
    for (std::size_t t = 0; t < per_tool.size(); ++t) min_cost.insert(id(t), per_tool[t]);
    printJson({{"c3", *c3}, {"c1", c1_json}, {"min_cost", min_cost}});
    return kExitOk;
  }

  const int n = static_cast<int>(std::floor(1.0 / *simplex + 1e-9));
  QJsonArray points;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double c1 = i * *simplex, c2 = j * *simplex;
      const std::array<double, 3> c{c1, c2, std::max(0.0, 1.0 - c1 - c2)};
      const Ranking ranking = session.rank(c);  // Rule 4 with the full tie rule
      QJsonObject min_cost;
      for (const ToolChoice& t : ranking.tools) min_cost.insert(id(t.tool), t.min_cost);
      for (std::size_t t : ranking.excluded) min_cost.insert(id(t), QJsonValue());
      points.append(QJsonObject{{"c", QJsonArray{c[0], c[1], c[2]}},
                                {"min_cost", min_cost},
                                {"selected", QJsonValue(id(ranking.selected().tool))}});
    }
  }
  printJson({{"points", points}});
  return kExitOk;
}

}  // namespace mx::app
