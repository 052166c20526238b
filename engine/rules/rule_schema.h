#pragma once
// What a rule may mention: the context paths it can test (with their type) and the decision
// variables it can bound. RuleSchema::standard() is the schema of docs/operator-rules.md; callers
// may extend it (add paths or variables) before parsing.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mx {

enum class RuleValueType { Number, String };

class RuleSchema {
 public:
  // The documented paths (tool.*, material.*, operation.*, machine.*) and variables.
  static const RuleSchema& standard();

  void addPath(const std::string& path, RuleValueType type) { paths_[path] = type; }
  void addVariable(const std::string& variable) { variables_[variable] = true; }

  std::optional<RuleValueType> pathType(const std::string& path) const;
  bool hasVariable(const std::string& variable) const { return variables_.count(variable) != 0; }

  std::vector<std::string> paths() const;      // sorted
  std::vector<std::string> variables() const;  // sorted
  // The known paths that share the first component of `path` ("tool.teeth, tool.diameter_mm, ..."),
  // or the known roots when the root itself is unknown; used in error messages.
  std::string describeNear(const std::string& path) const;

 private:
  std::map<std::string, RuleValueType> paths_;
  std::map<std::string, bool> variables_;
};

}  // namespace mx
