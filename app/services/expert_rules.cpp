#include "services/expert_rules.h"

#include <algorithm>

#include "services/pareto_request.h"

namespace mx::app {

ExpertRules::ExpertRules(const Project& project, const QStringList& tool_ids) {
  const QStringList texts = operatorRulesFromProject(project);
  if (texts.isEmpty()) return;
  for (const QString& id : tool_ids) tools_->push_back(evaluateParetoRules(texts, project, *project.findTool(id)));
}

std::array<double, 3> ExpertRules::boundWeights(const std::array<double, 3>& c) const {
  if (empty()) return c;
  std::vector<const RuleOutcome*> outcomes;
  outcomes.reserve(tools_->size());
  for (const ParetoRules& r : *tools_) outcomes.push_back(&r.outcome);
  const std::vector<double> bounded =
      applyWeightBounds(outcomes, {"weight.c1", "weight.c2", "weight.c3"}, {c.begin(), c.end()});
  std::array<double, 3> out{};
  std::copy(bounded.begin(), bounded.end(), out.begin());
  return out;
}

void ExpertRules::filter(ExpertSession& session) const {
  if (empty()) return;
  std::vector<int> teeth;
  for (std::size_t t = 0; t < session.toolCount(); ++t) teeth.push_back(session.grid(t).setup().teeth);
  session.setPointFilter([tools = tools_, teeth = std::move(teeth)](std::size_t tool, const ExpertPoint& q) {
    return (*tools)[tool].admits(paretoPointOf(q), teeth[tool]);
  });
}

bool ExpertRules::excludeEverything(const ExpertSession& session) {
  for (std::size_t t = 0; t < session.toolCount(); ++t)
    if (!session.grid(t).empty() && !session.filteredOut(t)) return false;
  return true;
}

ParetoPoint paretoPointOf(const ExpertPoint& q) {
  ParetoPoint p;
  p.speed_rev_per_s = q.speed_rev_per_s;
  p.depth_m = q.depth_m;
  p.feed_per_tooth_m = q.feed_per_tooth_m;
  p.power_w = q.power_w;
  p.objectives[index(Objective::Mrr)] = q.mrr_m3_per_s;
  return p;
}

}  // namespace mx::app
