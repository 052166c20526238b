#pragma once
// The operator's timed inputs of a supervised run (feed hold, the chatter key), handed out in time
// order as the simulated clock reaches them; events injected while the run goes on are due at once.
#include <cstddef>
#include <optional>
#include <vector>

namespace mx {

enum class OperatorEventType { FeedHoldOn, FeedHoldOff, ChatterSignal };

struct OperatorEvent {
  double t_s = 0.0;
  OperatorEventType type = OperatorEventType::FeedHoldOn;
};

const char* operatorEventText(OperatorEventType type);  // "feed hold on", "feed hold off", "chatter key"

class OperatorEventQueue {
 public:
  // Sorted by time; events at the same time keep their given order.
  explicit OperatorEventQueue(std::vector<OperatorEvent> events);

  // Makes each event due at t_s and puts it at the head of the queue, so that it is popped before
  // the pending ones (the events of one call thus come out last first).
  void injectAt(double t_s, const std::vector<OperatorEvent>& injected);

  // The next event due at t_s (its time within 1e-12 s of t_s or earlier), removed from the queue.
  std::optional<OperatorEvent> popDue(double t_s);

  std::size_t pending() const { return events_.size() - next_; }

 private:
  std::vector<OperatorEvent> events_;
  std::size_t next_ = 0;  // events_[next_ ..] are pending
};

}  // namespace mx
