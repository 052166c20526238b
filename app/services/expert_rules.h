#pragma once
// Module VII operator rules (Rule 18, docs/operator-rules.md) in the 2006 expert system, the same for
// `millexpert-cli rank` and the GUI's tool ranking: each tool's rules are evaluated in its own context;
// fired weight.c1/c2/c3 bounds (over all tools) bound c before Rule 4; fired constraints on the point
// variables restrict each tool's admissible points (ExpertSession's point filter).
#include <QStringList>
#include <array>
#include <memory>
#include <vector>

#include "document/project.h"
#include "expert/expert_session.h"
#include "services/pareto_rules.h"

namespace mx::app {

class ExpertRules {
 public:
  ExpertRules() = default;
  // ProjectError (exit 2) on a parse error or a contradiction in the project's operator rules.
  ExpertRules(const Project& project, const QStringList& tool_ids);

  bool empty() const { return tools_->empty(); }
  const ParetoRules& tool(std::size_t index) const { return (*tools_)[index]; }
  // c projected onto the simplex within the fired bounds (unchanged without rules; ProjectError when
  // the bounds leave no weights).
  std::array<double, 3> boundWeights(const std::array<double, 3>& c) const;
  // Installs the point filter (each tool's teeth from its grid's setup); the filter shares these rules.
  void filter(ExpertSession& session) const;
  // After filter(): no tool of the session keeps an admissible point.
  static bool excludeEverything(const ExpertSession& session);

 private:
  std::shared_ptr<std::vector<ParetoRules>> tools_ = std::make_shared<std::vector<ParetoRules>>();
};

// The rules' point variables of an expert point (MRR in the objective slot).
ParetoPoint paretoPointOf(const ExpertPoint& q);

}  // namespace mx::app
