#include "supervisor/operator_event_queue.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace mx {

const char* operatorEventText(OperatorEventType type) {
  switch (type) {
    case OperatorEventType::FeedHoldOn:
      return "feed hold on";
    case OperatorEventType::FeedHoldOff:
      return "feed hold off";
    default:
      return "chatter key";
  }
}

OperatorEventQueue::OperatorEventQueue(std::vector<OperatorEvent> events) : events_(std::move(events)) {
  std::stable_sort(events_.begin(), events_.end(), [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
}

void OperatorEventQueue::injectAt(double t_s, const std::vector<OperatorEvent>& injected) {
  for (OperatorEvent e : injected) {
    e.t_s = t_s;
    events_.insert(events_.begin() + static_cast<std::ptrdiff_t>(next_), e);
  }
}

std::optional<OperatorEvent> OperatorEventQueue::popDue(double t_s) {
  if (next_ < events_.size() && events_[next_].t_s <= t_s + 1e-12) return events_[next_++];
  return std::nullopt;
}

}  // namespace mx
