#include "rules/rule_schema.h"

#include <set>

namespace mx {

const RuleSchema& RuleSchema::standard() {
  static const RuleSchema schema = [] {
    RuleSchema s;
    const RuleValueType N = RuleValueType::Number;
    const RuleValueType S = RuleValueType::String;
    // The tool being selected for (project `tools[]`).
    s.addPath("tool.id", S);
    s.addPath("tool.teeth", N);
    s.addPath("tool.diameter_mm", N);
    s.addPath("tool.helix_deg", N);
    s.addPath("tool.Kt_N_mm2", N);
    s.addPath("tool.Kr", N);
    s.addPath("tool.modes", N);  // number of modes in x plus y
    // Work-piece material.
    s.addPath("material.name", S);
    s.addPath("material.Kt_N_mm2", N);
    s.addPath("material.Kr", N);
    // The operation.
    s.addPath("operation.milling", S);  // "up" or "down"
    s.addPath("operation.radial_immersion", N);
    s.addPath("operation.radial_depth_mm", N);
    s.addPath("operation.max_feed_per_tooth_mm", N);
    // The machine.
    s.addPath("machine.name", S);
    s.addPath("machine.spindle_power_W", N);
    s.addPath("machine.max_spindle_rpm", N);
    s.addPath("machine.max_feed_mm_s", N);
    s.addPath("machine.max_torque_Nm", N);
    // Decision variables: the cutting point and the cost weights.
    for (const char* v :
         {"speed_rpm", "depth_mm", "feed_mm_per_tooth", "feed_velocity_mm_s", "mrr_cm3_s", "power_W", "weight.c1",
          "weight.c2", "weight.c3", "weight.tol", "weight.mrr", "weight.surf", "weight.ros"})
      s.addVariable(v);
    return s;
  }();
  return schema;
}

std::optional<RuleValueType> RuleSchema::pathType(const std::string& path) const {
  const auto it = paths_.find(path);
  if (it == paths_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> RuleSchema::paths() const {
  std::vector<std::string> out;
  for (const auto& [path, type] : paths_) out.push_back(path);
  return out;
}

std::vector<std::string> RuleSchema::variables() const {
  std::vector<std::string> out;
  for (const auto& [variable, present] : variables_) out.push_back(variable);
  return out;
}

std::string RuleSchema::describeNear(const std::string& path) const {
  const std::string root = path.substr(0, path.find('.'));
  std::string same;
  std::set<std::string> roots;
  for (const auto& [known, type] : paths_) {
    const std::string knownRoot = known.substr(0, known.find('.'));
    roots.insert(knownRoot + ".*");
    if (knownRoot == root) same += (same.empty() ? "" : ", ") + known;
  }
  if (!same.empty()) return same;
  std::string all;
  for (const std::string& r : roots) all += (all.empty() ? "" : ", ") + r;
  return all;
}

}  // namespace mx
