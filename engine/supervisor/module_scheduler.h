#pragma once
// Multi-rate scheduler of the machining modules on the simulated time axis (Landers & Ulsoy, Table 1).
// applyScan() takes the supervisory logic's ScanOutput: impulse actions "X*" reset module X at once;
// level actions switch modules on and off (deactivate() runs when a module drops out). tick(ctx) is
// called at every sample (0.5 ms): each active module runs when its period has elapsed since it last
// ran (its first run is at the tick it becomes active); period 0 means every tick. Within a tick the
// modules run in registration order (makeStandardModules: signal chain first, feedrate routine last).
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "supervisor/machining_modules.h"
#include "supervisor/supervisor_logic.h"

namespace mx {

class ModuleScheduler {
 public:
  explicit ModuleScheduler(std::vector<std::unique_ptr<MachiningModule>> modules);  // unique letters, else throws

  void applyScan(const ScanOutput& scan, MachiningContext& ctx);
  void tick(MachiningContext& ctx);
  void resetCounters();

  bool isActive(char letter) const { return active_.count(letter) > 0; }
  std::string activeLetters() const;           // e.g. "ABIJ"
  long long runs(char letter) const;           // calls of run() since construction / resetCounters
  long long resets(char letter) const;         // impulse resets
  MachiningModule* module(char letter) const;  // nullptr when absent

 private:
  struct Slot {
    std::unique_ptr<MachiningModule> module;
    double next_due = 0.0;
    long long runs = 0, resets = 0;
  };
  Slot* slot(char letter);
  const Slot* slot(char letter) const;
  std::vector<Slot> slots_;
  std::set<char> active_;
};

}  // namespace mx
