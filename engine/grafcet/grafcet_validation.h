#pragma once
// Checks a Grafcet chart before it runs. Each issue names its element (the chart, a step
// or a transition, by id and by position in the chart) and the field at fault, so the JSON reader
// (app/document/project_grafcet_io.h) and the chart editor can point at it.
#include <set>
#include <string>
#include <vector>

#include "grafcet/grafcet_chart.h"

namespace mx {

enum class GrafcetIssueKind {
  NoSteps,                  // chart: no step at all
  EmptyInitialSituation,    // chart: no initial step
  DuplicateStepId,          // step: id already used by an earlier step
  DuplicateStepName,        // step: name already used by an earlier step
  EmptyStepName,            // step: name is empty
  BadAction,                // step: empty action, "*" alone, or whitespace in an action
  UnreachableStep,          // step: no evolution from the initial situation can activate it
  DuplicateTransitionId,    // transition: id already used by an earlier transition
  TransitionWithoutSource,  // transition: "from" is empty
  TransitionWithoutTarget,  // transition: "to" is empty
  UnknownStep,              // transition: "from"/"to" names a step id the chart does not have
  BadReceptivity,           // transition: receptivity syntax error (message has line and column)
  UnknownSignal,            // transition: the receptivity reads a signal that is not known
};

enum class GrafcetElement { Chart, Step, Transition };

struct GrafcetIssue {
  GrafcetIssueKind kind;
  GrafcetElement element;
  int index = -1;       // position in chart.steps / chart.transitions; -1 for the chart
  int id = 0;           // the step's or transition's id
  std::string field;    // "id", "name", "initial", "actions", "from", "to", "receptivity", "steps"
  std::string message;  // e.g. "line 1, column 5: expected ')'" or "unknown signal 'z'"

  // "transition 3 (receptivity): line 1, column 5: expected ')'", "step 6: unreachable ...".
  std::string describe() const;
};

// Structural checks and receptivity syntax; signals are not checked.
std::vector<GrafcetIssue> validateGrafcetChart(const GrafcetChart& chart);
// The same, plus: every signal read by a receptivity is in `knownSignals`.
std::vector<GrafcetIssue> validateGrafcetChart(const GrafcetChart& chart, const std::set<std::string>& knownSignals);

}  // namespace mx
