#pragma once
// The Grafcet (IEC 60848 / SFC) interpreter: runs a GrafcetChart as the supervisory logic
// controller of Landers & Ulsoy. At each scan it reads the signals, evolves the chart to its stable
// situation (firing transitions repeatedly with the same inputs, within an iteration limit), and
// reports the active steps, the level actions of the stable situation and the impulse actions of
// every step activated during the scan. Conflicts between fireable transitions sharing a source step
// are resolved by the designer's priority (the paper's "feed hold is checked first").
// docs/grafcet.md states the rules exactly.
//
// Two ways to scan: the SupervisorLogic interface (signals by name), and a fast path for the
// multi-rate simulation and the benchmark: bindSignals(names) once, then evolve(values) (indices) or
// scanValues(values) (names) with values in that order; evolve neither looks up names nor allocates.
#include <cstdint>
#include <string>
#include <vector>

#include "grafcet/grafcet_chart.h"
#include "grafcet/grafcet_expression.h"
#include "supervisor/supervisor_logic.h"

namespace mx {

struct GrafcetSettings {
  int iteration_limit = 100;  // evolutions per scan before the search is abandoned (stable = false)
};

// The fast path's result: indices instead of names.
struct GrafcetSituation {
  std::vector<int> active_steps;     // indices into chart().steps, ascending (chart order)
  std::vector<int> level_actions;    // indices into actionNames(), ascending
  std::vector<int> impulse_actions;  // indices into actionNames(), in order of firing
  bool stable = true;
  int iterations = 0;
};

class GrafcetInterpreter : public SupervisorLogic {
 public:
  // Throws InvalidInput (core/cancellation.h) listing the chart's issues (validateGrafcetChart,
  // without the signal check) when it has any. The interpreter starts in the initial situation.
  explicit GrafcetInterpreter(GrafcetChart chart, GrafcetSettings settings = {});

  void reset() override;
  // Signals absent from the map read 0 (false).
  ScanOutput scan(const SignalValues& values) override;

  // Fast path. bindSignals fixes the order of the values of scanValues / evolve: names may hold
  // more signals than the chart reads, but must hold every one it reads (InvalidInput otherwise).
  // Until bindSignals is called the order is signalNames().
  void bindSignals(const std::vector<std::string>& names);
  ScanOutput scanValues(const std::vector<double>& values);
  const GrafcetSituation& evolve(const std::vector<double>& values);  // InvalidInput on a size mismatch

  const GrafcetChart& chart() const { return chart_; }
  const GrafcetSettings& settings() const { return settings_; }
  const std::vector<std::string>& signalNames() const { return signals_; }  // read by the chart, sorted
  const std::vector<std::string>& boundSignals() const { return bound_names_; }
  // Every distinct action text of the chart ("A", "L*"), in order of first appearance.
  const std::vector<std::string>& actionNames() const { return action_names_; }
  const GrafcetSituation& situation() const { return situation_; }  // after the last scan
  bool isActive(int stepId) const;
  std::vector<int> activeStepIds() const;

 private:
  struct Step {
    std::vector<int> downstream;  // transitions with this step as a source
    std::vector<int> level;       // action indices
    std::vector<int> impulse;
  };
  struct Transition {
    std::vector<int> sources, targets;  // step indices
    GrafcetExpression receptivity;      // slots = indices into signals_
    int rank = 0;                       // position in (priority, id) order
  };

  void run();  // the evolution on values_
  ScanOutput output() const;

  GrafcetChart chart_;
  GrafcetSettings settings_;
  std::vector<Step> steps_;
  std::vector<Transition> transitions_;
  std::vector<std::string> signals_;
  std::vector<std::string> action_names_;
  std::vector<std::string> bound_names_;
  std::vector<int> bound_pos_;  // signals_[j] is values[bound_pos_[j]]
  std::vector<double> values_;  // per signals_

  // State.
  std::vector<char> active_;
  std::vector<int> active_list_;
  bool initial_pending_ = true;
  GrafcetSituation situation_;

  // Scratch (stamps avoid clearing per scan).
  std::uint64_t scan_stamp_ = 0, evolution_stamp_ = 0;
  std::vector<std::uint64_t> seen_, receptivity_stamp_;  // per transition
  std::vector<char> receptivity_value_;
  std::vector<std::uint64_t> claimed_, newly_stamp_, activated_stamp_;  // per step
  std::vector<std::uint64_t> action_stamp_;                             // per action
  std::vector<int> fireable_, chosen_, newly_, activated_, kept_;
};

}  // namespace mx
