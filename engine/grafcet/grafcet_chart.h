#pragma once
// The data model of a Grafcet (IEC 60848 / SFC) chart, as the supervisory logic controller of
// Landers & Ulsoy is drawn: numbered steps (one or more initial), each with its actions,
// and numbered transitions from source steps to target steps, each with a Boolean receptivity over
// named signals (grafcet_expression.h) and the designer's priority for conflicts. Charts are data
// (JSON in the project, app/document/project_grafcet_io.h); grafcet_validation.h checks them and
// grafcet_interpreter.h runs them. docs/grafcet.md describes the format and the semantics.
#include <string>
#include <string_view>
#include <vector>

namespace mx {

struct GrafcetStep {
  int id = 0;                        // unique among the chart's steps
  std::string name;                  // e.g. "No Contact and No Chatter"
  bool initial = false;              // part of the initial situation (double box)
  std::vector<std::string> actions;  // level "A", or impulse "L*" (a trailing asterisk)

  bool operator==(const GrafcetStep&) const = default;
};

struct GrafcetTransition {
  int id = 0;               // unique among the chart's transitions; the "(n)" of the drawing
  std::vector<int> from;    // source step ids (more than one: synchronisation)
  std::vector<int> to;      // target step ids (more than one: parallel divergence)
  std::string receptivity;  // e.g. "b and a'" (grafcet_expression.h)
  int priority = 1;         // conflicts on a shared source step: the lowest number fires, then the lowest id

  bool operator==(const GrafcetTransition&) const = default;
};

struct GrafcetChart {
  std::string name;
  std::vector<GrafcetStep> steps;
  std::vector<GrafcetTransition> transitions;

  // The first step / transition with this id, or nullptr.
  const GrafcetStep* step(int id) const;
  const GrafcetTransition* transition(int id) const;
  // Index in `steps` of the first step with this id, or -1.
  int stepIndex(int id) const;

  bool operator==(const GrafcetChart&) const = default;
};

// "L*" is an impulse action, "L" a level action.
bool isImpulseAction(std::string_view action);
// The action's variable without the impulse asterisk: "L*" -> "L".
std::string_view actionVariable(std::string_view action);

}  // namespace mx
