#include "grafcet/grafcet_validation.h"

#include <map>

#include "grafcet/grafcet_expression.h"

namespace mx {

std::string GrafcetIssue::describe() const {
  std::string where;
  switch (element) {
    case GrafcetElement::Chart:
      where = "chart";
      break;
    case GrafcetElement::Step:
      where = "step " + std::to_string(id);
      break;
    case GrafcetElement::Transition:
      where = "transition " + std::to_string(id);
      break;
  }
  if (!field.empty()) where += " (" + field + ")";
  return where + ": " + message;
}

namespace {

GrafcetIssue stepIssue(GrafcetIssueKind kind, std::size_t index, const GrafcetStep& s, std::string field,
                       std::string message) {
  return {kind, GrafcetElement::Step, static_cast<int>(index), s.id, std::move(field), std::move(message)};
}

GrafcetIssue transitionIssue(GrafcetIssueKind kind, std::size_t index, const GrafcetTransition& t, std::string field,
                             std::string message) {
  return {kind, GrafcetElement::Transition, static_cast<int>(index), t.id, std::move(field), std::move(message)};
}

bool badAction(const std::string& a) {
  if (actionVariable(a).empty()) return true;
  for (char c : a)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') return true;
  return a.find('*') != a.size() - 1 && a.find('*') != std::string::npos;
}

std::vector<GrafcetIssue> validate(const GrafcetChart& chart, const std::set<std::string>* known) {
  std::vector<GrafcetIssue> issues;
  if (chart.steps.empty())
    issues.push_back({GrafcetIssueKind::NoSteps, GrafcetElement::Chart, -1, 0, "steps", "the chart has no step"});

  // Steps: ids, names, actions.
  std::map<int, std::size_t> stepById;
  std::map<std::string, int> stepByName;
  bool anyInitial = false;
  for (std::size_t i = 0; i < chart.steps.size(); ++i) {
    const GrafcetStep& s = chart.steps[i];
    if (auto [it, fresh] = stepById.emplace(s.id, i); !fresh)
      issues.push_back(stepIssue(GrafcetIssueKind::DuplicateStepId, i, s, "id",
                                 "duplicate step id " + std::to_string(s.id) + " (also step #" +
                                     std::to_string(it->second + 1) + " in the list)"));
    if (s.name.empty()) {
      issues.push_back(stepIssue(GrafcetIssueKind::EmptyStepName, i, s, "name", "the step has no name"));
    } else if (auto [it, fresh] = stepByName.emplace(s.name, s.id); !fresh) {
      issues.push_back(
          stepIssue(GrafcetIssueKind::DuplicateStepName, i, s, "name",
                    "duplicate step name '" + s.name + "' (also step " + std::to_string(it->second) + ")"));
    }
    for (const std::string& a : s.actions)
      if (badAction(a))
        issues.push_back(stepIssue(GrafcetIssueKind::BadAction, i, s, "actions",
                                   "bad action '" + a + "': a name, with a trailing '*' for an impulse action"));
    anyInitial = anyInitial || s.initial;
  }
  if (!chart.steps.empty() && !anyInitial)
    issues.push_back({GrafcetIssueKind::EmptyInitialSituation, GrafcetElement::Chart, -1, 0, "initial",
                      "empty initial situation: no step is marked initial"});

  // Transitions: ids, arcs, receptivities.
  std::map<int, std::size_t> transitionById;
  for (std::size_t i = 0; i < chart.transitions.size(); ++i) {
    const GrafcetTransition& t = chart.transitions[i];
    if (auto [it, fresh] = transitionById.emplace(t.id, i); !fresh)
      issues.push_back(transitionIssue(GrafcetIssueKind::DuplicateTransitionId, i, t, "id",
                                       "duplicate transition id " + std::to_string(t.id) + " (also transition #" +
                                           std::to_string(it->second + 1) + " in the list)"));
    if (t.from.empty())
      issues.push_back(transitionIssue(GrafcetIssueKind::TransitionWithoutSource, i, t, "from",
                                       "the transition has no source step"));
    if (t.to.empty())
      issues.push_back(
          transitionIssue(GrafcetIssueKind::TransitionWithoutTarget, i, t, "to", "the transition has no target step"));
    for (const char* field : {"from", "to"})
      for (int id : std::string(field) == "from" ? t.from : t.to)
        if (!stepById.count(id))
          issues.push_back(
              transitionIssue(GrafcetIssueKind::UnknownStep, i, t, field, "unknown step " + std::to_string(id)));
    try {
      const GrafcetExpression e = GrafcetExpression::parse(t.receptivity);
      if (known)
        for (const std::string& s : e.signalNames())
          if (!known->count(s))
            issues.push_back(
                transitionIssue(GrafcetIssueKind::UnknownSignal, i, t, "receptivity", "unknown signal '" + s + "'"));
    } catch (const GrafcetParseError& e) {
      issues.push_back(transitionIssue(GrafcetIssueKind::BadReceptivity, i, t, "receptivity", e.what()));
    }
  }

  // Reachability: a step is reachable when it is initial, or a target of a transition whose source
  // steps are all reachable (a fixpoint; receptivities are not considered).
  if (anyInitial) {
    std::vector<char> reach(chart.steps.size(), 0);
    for (std::size_t i = 0; i < chart.steps.size(); ++i) reach[i] = chart.steps[i].initial ? 1 : 0;
    for (bool changed = true; changed;) {
      changed = false;
      for (const GrafcetTransition& t : chart.transitions) {
        if (t.from.empty()) continue;
        bool ok = true;
        for (int id : t.from) {
          const auto it = stepById.find(id);
          ok = ok && it != stepById.end() && reach[it->second];
        }
        if (!ok) continue;
        for (int id : t.to)
          if (const auto it = stepById.find(id); it != stepById.end() && !reach[it->second])
            reach[it->second] = 1, changed = true;
      }
    }
    for (std::size_t i = 0; i < chart.steps.size(); ++i)
      if (!reach[i] && stepById[chart.steps[i].id] == i)
        issues.push_back(stepIssue(
            GrafcetIssueKind::UnreachableStep, i, chart.steps[i], "",
            "unreachable step '" + chart.steps[i].name + "': no transition from the initial situation leads to it"));
  }
  return issues;
}

}  // namespace

std::vector<GrafcetIssue> validateGrafcetChart(const GrafcetChart& chart) {
  return validate(chart, nullptr);
}

std::vector<GrafcetIssue> validateGrafcetChart(const GrafcetChart& chart, const std::set<std::string>& knownSignals) {
  return validate(chart, &knownSignals);
}

}  // namespace mx
