#include "supervisor/module_scheduler.h"

#include <algorithm>

#include "core/invalid_input.h"

namespace mx {

ModuleScheduler::ModuleScheduler(std::vector<std::unique_ptr<MachiningModule>> modules) {
  std::set<char> seen;
  for (auto& m : modules) {
    if (!m) throw InvalidInput("module scheduler: module = null: must be a module");
    if (!seen.insert(m->letter()).second)
      throw InvalidInput(std::string("module scheduler: letter = ") + m->letter() + ": must be unique");
    if (!(m->period() >= 0.0))
      throw InvalidInput(std::string("module scheduler: period of ") + m->letter() + ": must be >= 0");
    slots_.push_back(Slot{std::move(m)});
  }
}

ModuleScheduler::Slot* ModuleScheduler::slot(char letter) {
  for (auto& s : slots_)
    if (s.module->letter() == letter) return &s;
  return nullptr;
}

const ModuleScheduler::Slot* ModuleScheduler::slot(char letter) const {
  for (const auto& s : slots_)
    if (s.module->letter() == letter) return &s;
  return nullptr;
}

void ModuleScheduler::applyScan(const ScanOutput& scan, MachiningContext& ctx) {
  for (const auto& impulse : scan.impulse_actions) {
    // "X*" resets module X; an unknown letter is ignored (the chart may name modules this machine lacks).
    if (impulse.size() == 2 && impulse[1] == '*') {
      if (Slot* s = slot(impulse[0])) {
        s->module->reset(ctx);
        s->next_due = ctx.t_s;
        ++s->resets;
      }
    }
  }
  std::set<char> next;
  for (const auto& action : scan.level_actions)
    if (action.size() == 1 && slot(action[0])) next.insert(action[0]);
  for (auto& s : slots_) {
    const char l = s.module->letter();
    const bool was = active_.count(l) > 0, now = next.count(l) > 0;
    if (was && !now) s.module->deactivate(ctx);
    if (!was && now) {
      s.next_due = ctx.t_s;  // first run at the next tick
      s.module->activate(ctx);
    }
  }
  active_ = std::move(next);
}

void ModuleScheduler::tick(MachiningContext& ctx) {
  const double eps = 1e-9;
  for (auto& s : slots_) {
    if (!active_.count(s.module->letter())) continue;
    if (ctx.t_s + eps < s.next_due) continue;
    s.module->run(ctx);
    ++s.runs;
    const double p = s.module->period();
    if (p > 0.0) {
      s.next_due += p;
      if (s.next_due + eps < ctx.t_s) s.next_due = ctx.t_s + p;  // fell behind: no burst of catch-up runs
    } else {
      s.next_due = ctx.t_s;
    }
  }
}

void ModuleScheduler::resetCounters() {
  for (auto& s : slots_) s.runs = s.resets = 0;
}

std::string ModuleScheduler::activeLetters() const {
  std::string out;
  for (const auto& s : slots_)
    if (active_.count(s.module->letter())) out += s.module->letter();
  std::sort(out.begin(), out.end());
  return out;
}

long long ModuleScheduler::runs(char letter) const {
  const Slot* s = slot(letter);
  return s ? s->runs : 0;
}

long long ModuleScheduler::resets(char letter) const {
  const Slot* s = slot(letter);
  return s ? s->resets : 0;
}

MachiningModule* ModuleScheduler::module(char letter) const {
  const Slot* s = slot(letter);
  return s ? s->module.get() : nullptr;
}

}  // namespace mx
