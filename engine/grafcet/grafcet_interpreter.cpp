#include "grafcet/grafcet_interpreter.h"

#include <algorithm>
#include <numeric>
#include <set>

#include "core/invalid_input.h"
#include "grafcet/grafcet_validation.h"

namespace mx {

GrafcetInterpreter::GrafcetInterpreter(GrafcetChart chart, GrafcetSettings settings)
    : chart_(std::move(chart)), settings_(settings) {
  if (settings_.iteration_limit < 1)
    throw InvalidInput("Grafcet iteration limit = " + std::to_string(settings_.iteration_limit) + ": must be >= 1");
  const std::vector<GrafcetIssue> issues = validateGrafcetChart(chart_);
  if (!issues.empty()) {
    std::string msg = "Grafcet chart '" + chart_.name + "': ";
    for (std::size_t i = 0; i < issues.size(); ++i) msg += (i ? "; " : "") + issues[i].describe();
    throw InvalidInput(msg);
  }

  // Actions.
  steps_.resize(chart_.steps.size());
  for (std::size_t i = 0; i < chart_.steps.size(); ++i)
    for (const std::string& a : chart_.steps[i].actions) {
      auto it = std::find(action_names_.begin(), action_names_.end(), a);
      const int index = static_cast<int>(it - action_names_.begin());
      if (it == action_names_.end()) action_names_.push_back(a);
      auto& list = isImpulseAction(a) ? steps_[i].impulse : steps_[i].level;
      if (std::find(list.begin(), list.end(), index) == list.end()) list.push_back(index);
    }

  // Transitions: compiled receptivities on the sorted signal list, ranks by (priority, id).
  std::vector<GrafcetExpression> expressions;
  std::set<std::string> names;
  for (const GrafcetTransition& t : chart_.transitions) {
    expressions.push_back(GrafcetExpression::parse(t.receptivity));
    names.insert(expressions.back().signalNames().begin(), expressions.back().signalNames().end());
  }
  signals_.assign(names.begin(), names.end());
  std::vector<int> order(chart_.transitions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const GrafcetTransition &ta = chart_.transitions[static_cast<std::size_t>(a)],
                            &tb = chart_.transitions[static_cast<std::size_t>(b)];
    return ta.priority != tb.priority ? ta.priority < tb.priority : ta.id < tb.id;
  });
  transitions_.resize(chart_.transitions.size());
  for (std::size_t r = 0; r < order.size(); ++r)
    transitions_[static_cast<std::size_t>(order[r])].rank = static_cast<int>(r);
  for (std::size_t i = 0; i < chart_.transitions.size(); ++i) {
    const GrafcetTransition& t = chart_.transitions[i];
    Transition& c = transitions_[i];
    for (int id : t.from) c.sources.push_back(chart_.stepIndex(id));
    for (int id : t.to) c.targets.push_back(chart_.stepIndex(id));
    std::sort(c.sources.begin(), c.sources.end());
    c.sources.erase(std::unique(c.sources.begin(), c.sources.end()), c.sources.end());
    std::sort(c.targets.begin(), c.targets.end());
    c.targets.erase(std::unique(c.targets.begin(), c.targets.end()), c.targets.end());
    std::vector<int> cells;
    for (const std::string& s : expressions[i].signalNames())
      cells.push_back(static_cast<int>(std::lower_bound(signals_.begin(), signals_.end(), s) - signals_.begin()));
    c.receptivity = std::move(expressions[i]);
    c.receptivity.bindSlots(std::move(cells));
    for (int s : c.sources) steps_[static_cast<std::size_t>(s)].downstream.push_back(static_cast<int>(i));
  }
  for (Step& s : steps_)
    std::sort(s.downstream.begin(), s.downstream.end(), [&](int a, int b) {
      return transitions_[static_cast<std::size_t>(a)].rank < transitions_[static_cast<std::size_t>(b)].rank;
    });

  values_.assign(signals_.size(), 0.0);
  bindSignals(signals_);
  seen_.assign(transitions_.size(), 0);
  receptivity_stamp_.assign(transitions_.size(), 0);
  receptivity_value_.assign(transitions_.size(), 0);
  claimed_.assign(steps_.size(), 0);
  newly_stamp_.assign(steps_.size(), 0);
  activated_stamp_.assign(steps_.size(), 0);
  action_stamp_.assign(action_names_.size(), 0);
  reset();
}

void GrafcetInterpreter::reset() {
  active_.assign(chart_.steps.size(), 0);
  active_list_.clear();
  for (std::size_t i = 0; i < chart_.steps.size(); ++i)
    if (chart_.steps[i].initial) {
      active_[i] = 1;
      active_list_.push_back(static_cast<int>(i));
    }
  initial_pending_ = true;  // the initial steps' impulse actions fire at the first scan
  situation_ = GrafcetSituation{};
  situation_.active_steps = active_list_;
}

void GrafcetInterpreter::bindSignals(const std::vector<std::string>& names) {
  std::vector<int> pos(signals_.size(), -1);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto it = std::lower_bound(signals_.begin(), signals_.end(), names[k]);
    if (it != signals_.end() && *it == names[k] && pos[static_cast<std::size_t>(it - signals_.begin())] < 0)
      pos[static_cast<std::size_t>(it - signals_.begin())] = static_cast<int>(k);
  }
  for (std::size_t j = 0; j < pos.size(); ++j)
    if (pos[j] < 0)
      throw InvalidInput("Grafcet chart '" + chart_.name + "' reads signal '" + signals_[j] +
                         "', which is not among the bound signals");
  bound_names_ = names;
  bound_pos_ = std::move(pos);
}

ScanOutput GrafcetInterpreter::scan(const SignalValues& values) {
  for (std::size_t j = 0; j < signals_.size(); ++j) {
    const auto it = values.find(signals_[j]);
    values_[j] = it == values.end() ? 0.0 : it->second;
  }
  run();
  return output();
}

ScanOutput GrafcetInterpreter::scanValues(const std::vector<double>& values) {
  evolve(values);
  return output();
}

const GrafcetSituation& GrafcetInterpreter::evolve(const std::vector<double>& values) {
  if (values.size() != bound_names_.size())
    throw InvalidInput("Grafcet scan: " + std::to_string(values.size()) + " values for " +
                       std::to_string(bound_names_.size()) + " bound signals");
  for (std::size_t j = 0; j < values_.size(); ++j) values_[j] = values[static_cast<std::size_t>(bound_pos_[j])];
  run();
  return situation_;
}

void GrafcetInterpreter::run() {
  const std::uint64_t scan = ++scan_stamp_;
  activated_.clear();
  if (initial_pending_) {
    for (int s : active_list_) {
      activated_stamp_[static_cast<std::size_t>(s)] = scan;
      activated_.push_back(s);
    }
    initial_pending_ = false;
  }
  int iterations = 0;
  bool stable = true;
  for (;;) {
    const std::uint64_t evo = ++evolution_stamp_;
    // Fireable transitions: enabled (all sources active) and receptivity true.
    fireable_.clear();
    for (int s : active_list_)
      for (int t : steps_[static_cast<std::size_t>(s)].downstream) {
        const auto ti = static_cast<std::size_t>(t);
        if (seen_[ti] == evo) continue;
        seen_[ti] = evo;
        const Transition& tr = transitions_[ti];
        bool enabled = true;
        for (int src : tr.sources) enabled = enabled && active_[static_cast<std::size_t>(src)];
        if (!enabled) continue;
        if (receptivity_stamp_[ti] != scan) {  // inputs are constant within a scan
          receptivity_stamp_[ti] = scan;
          receptivity_value_[ti] = tr.receptivity.evaluate(values_.data()) ? 1 : 0;
        }
        if (receptivity_value_[ti]) fireable_.push_back(t);
      }
    if (fireable_.empty()) break;
    if (iterations == settings_.iteration_limit) {
      stable = false;
      break;
    }
    // Conflicts: in (priority, id) order, a transition fires unless a source step of it is already
    // claimed by a transition chosen before it in this evolution.
    std::sort(fireable_.begin(), fireable_.end(), [&](int a, int b) {
      return transitions_[static_cast<std::size_t>(a)].rank < transitions_[static_cast<std::size_t>(b)].rank;
    });
    chosen_.clear();
    for (int t : fireable_) {
      const Transition& tr = transitions_[static_cast<std::size_t>(t)];
      bool free = true;
      for (int src : tr.sources) free = free && claimed_[static_cast<std::size_t>(src)] != evo;
      if (!free) continue;
      for (int src : tr.sources) claimed_[static_cast<std::size_t>(src)] = evo;
      chosen_.push_back(t);
    }
    // Simultaneous clearing and activation; a step both cleared and activated stays active.
    newly_.clear();
    for (int t : chosen_)
      for (int x : transitions_[static_cast<std::size_t>(t)].targets) {
        const auto xi = static_cast<std::size_t>(x);
        if (!active_[xi] && newly_stamp_[xi] != evo) {
          newly_stamp_[xi] = evo;
          newly_.push_back(x);
        }
      }
    for (int t : chosen_)
      for (int src : transitions_[static_cast<std::size_t>(t)].sources) active_[static_cast<std::size_t>(src)] = 0;
    for (int t : chosen_)
      for (int x : transitions_[static_cast<std::size_t>(t)].targets) active_[static_cast<std::size_t>(x)] = 1;
    kept_.clear();
    for (int s : active_list_)
      if (active_[static_cast<std::size_t>(s)]) kept_.push_back(s);
    kept_.insert(kept_.end(), newly_.begin(), newly_.end());
    active_list_.swap(kept_);
    for (int x : newly_)
      if (activated_stamp_[static_cast<std::size_t>(x)] != scan) {
        activated_stamp_[static_cast<std::size_t>(x)] = scan;
        activated_.push_back(x);
      }
    ++iterations;
  }
  std::sort(active_list_.begin(), active_list_.end());

  GrafcetSituation& out = situation_;
  out.stable = stable;
  out.iterations = iterations;
  out.active_steps.assign(active_list_.begin(), active_list_.end());
  out.impulse_actions.clear();
  for (int x : activated_)
    for (int a : steps_[static_cast<std::size_t>(x)].impulse)
      if (action_stamp_[static_cast<std::size_t>(a)] != scan) {
        action_stamp_[static_cast<std::size_t>(a)] = scan;
        out.impulse_actions.push_back(a);
      }
  out.level_actions.clear();
  for (int s : active_list_)
    for (int a : steps_[static_cast<std::size_t>(s)].level)
      if (action_stamp_[static_cast<std::size_t>(a)] != scan) {
        action_stamp_[static_cast<std::size_t>(a)] = scan;
        out.level_actions.push_back(a);
      }
  std::sort(out.level_actions.begin(), out.level_actions.end());
}

ScanOutput GrafcetInterpreter::output() const {
  ScanOutput o;
  o.stable = situation_.stable;
  o.iterations = situation_.iterations;
  for (int s : situation_.active_steps) o.active_steps.push_back(chart_.steps[static_cast<std::size_t>(s)].name);
  for (int a : situation_.level_actions) o.level_actions.insert(action_names_[static_cast<std::size_t>(a)]);
  for (int a : situation_.impulse_actions) o.impulse_actions.push_back(action_names_[static_cast<std::size_t>(a)]);
  return o;
}

bool GrafcetInterpreter::isActive(int stepId) const {
  const int i = chart_.stepIndex(stepId);
  return i >= 0 && active_[static_cast<std::size_t>(i)];
}

std::vector<int> GrafcetInterpreter::activeStepIds() const {
  std::vector<int> ids;
  for (std::size_t i = 0; i < active_.size(); ++i)
    if (active_[i]) ids.push_back(chart_.steps[i].id);
  return ids;
}

}  // namespace mx
