#pragma once
// The interface between a supervisory logic controller (the Grafcet interpreter, Landers & Ulsoy)
// and the machining modules it coordinates. At each scan the logic reads named signals
// (Table 2 receptivities such as "a" feed hold requested, "b" contact, ...; numbers allowed for
// comparisons, booleans as 0/1), evolves to its stable situation, and reports which actions are
// active: level actions (Table 1 module letters, active while a step that carries them is active)
// and impulse actions (fired once, at the scan where a step carrying them is activated; by
// convention "L*" = reset/initialise module L).
#include <map>
#include <set>
#include <string>
#include <vector>

namespace mx {

using SignalValues = std::map<std::string, double>;

struct ScanOutput {
  std::vector<std::string> active_steps;     // step names, in chart order
  std::set<std::string> level_actions;       // e.g. {"A", "B", "I", "J"}
  std::vector<std::string> impulse_actions;  // e.g. {"L*"}, fired at this scan
  bool stable = true;                        // false: no stable situation within the iteration limit
  int iterations = 0;                        // evolution iterations of this scan
};

class SupervisorLogic {
 public:
  virtual ~SupervisorLogic() = default;
  virtual void reset() = 0;                                 // back to the initial situation
  virtual ScanOutput scan(const SignalValues& values) = 0;  // one scan
};

}  // namespace mx
