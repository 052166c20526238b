#include "rules/rule_context.h"

#include <utility>

namespace mx {

RuleContext& RuleContext::set(const std::string& path, double value) {
  values_[path] = value;
  return *this;
}

RuleContext& RuleContext::set(const std::string& path, std::string value) {
  values_[path] = std::move(value);
  return *this;
}

const RuleValue* RuleContext::find(const std::string& path) const {
  const auto it = values_.find(path);
  return it == values_.end() ? nullptr : &it->second;
}

}  // namespace mx
