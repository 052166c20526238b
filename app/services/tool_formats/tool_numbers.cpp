#include "services/tool_formats/tool_numbers.h"

#include <QRegularExpression>
#include <set>

namespace mx::app {

std::optional<int> toolNumberOfId(const QString& id) {
  static const QRegularExpression pattern(QStringLiteral(R"(^T([0-9]{1,10})$)"));
  const QRegularExpressionMatch match = pattern.match(id);
  if (!match.hasMatch()) return std::nullopt;
  bool ok = false;
  const int number = match.captured(1).toInt(&ok);
  return ok ? std::optional<int>(number) : std::nullopt;
}

std::vector<int> exportToolNumbers(const std::vector<ToolSpec>& tools,
                                   std::optional<int> (*imported)(const ToolSpec& tool)) {
  std::vector<std::optional<int>> numbers(tools.size());
  std::set<int> taken;
  // The ids first: "T7" keeps 7 even when an earlier tool was imported as number 7.
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const std::optional<int> wanted = toolNumberOfId(tools[i].id);
    if (wanted && taken.insert(*wanted).second) numbers[i] = wanted;
  }
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const std::optional<int> wanted = numbers[i] ? std::nullopt : imported(tools[i]);
    if (wanted && *wanted >= 0 && taken.insert(*wanted).second) numbers[i] = wanted;
  }
  std::vector<int> result;
  int next = 1;
  for (const std::optional<int>& number : numbers) {
    if (number) {
      result.push_back(*number);
      continue;
    }
    while (taken.count(next) != 0) ++next;
    taken.insert(next);
    result.push_back(next);
  }
  return result;
}

}  // namespace mx::app
