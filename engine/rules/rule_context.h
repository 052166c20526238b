#pragma once
// The facts the operator rules test: a map from a context path (tool.diameter_mm, material.name,
// ...) to a number or a string, filled by the caller from the project and the selected tool.
// A path the rules mention but the context lacks makes the comparison unknown (see rule_evaluator.h).
#include <map>
#include <string>

#include "rules/rule_ast.h"

namespace mx {

class RuleContext {
 public:
  RuleContext& set(const std::string& path, double value);
  RuleContext& set(const std::string& path, std::string value);
  RuleContext& set(const std::string& path, const char* value) { return set(path, std::string(value)); }
  void erase(const std::string& path) { values_.erase(path); }

  bool has(const std::string& path) const { return values_.count(path) != 0; }
  const RuleValue* find(const std::string& path) const;
  const std::map<std::string, RuleValue>& values() const { return values_; }

 private:
  std::map<std::string, RuleValue> values_;
};

}  // namespace mx
