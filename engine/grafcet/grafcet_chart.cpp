#include "grafcet/grafcet_chart.h"

namespace mx {

const GrafcetStep* GrafcetChart::step(int id) const {
  for (const GrafcetStep& s : steps)
    if (s.id == id) return &s;
  return nullptr;
}

const GrafcetTransition* GrafcetChart::transition(int id) const {
  for (const GrafcetTransition& t : transitions)
    if (t.id == id) return &t;
  return nullptr;
}

int GrafcetChart::stepIndex(int id) const {
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (steps[i].id == id) return static_cast<int>(i);
  return -1;
}

bool isImpulseAction(std::string_view action) {
  return !action.empty() && action.back() == '*';
}

std::string_view actionVariable(std::string_view action) {
  if (isImpulseAction(action)) action.remove_suffix(1);
  return action;
}

}  // namespace mx
