// OperatorEventQueue: the operator's events in time order, due once the clock reaches them; events
// injected during the run are due at once, ahead of the pending ones.
#include <string>
#include <vector>

#include "supervisor/operator_event_queue.h"
#include "test_registry.h"

using namespace mx;

namespace {
std::vector<OperatorEvent> drain(OperatorEventQueue& q, double t) {
  std::vector<OperatorEvent> out;
  while (const auto e = q.popDue(t)) out.push_back(*e);
  return out;
}
}  // namespace

class TestOperatorEventQueue : public QObject {
  Q_OBJECT
 private slots:
  // Sorted by time; the two events at 0.3 s keep their given order.
  void timeOrderStableForTies() {
    OperatorEventQueue q({{0.3, OperatorEventType::FeedHoldOn},
                          {0.1, OperatorEventType::FeedHoldOff},
                          {0.3, OperatorEventType::ChatterSignal},
                          {0.2, OperatorEventType::FeedHoldOn}});
    QCOMPARE(q.pending(), std::size_t{4});
    const auto out = drain(q, 1.0);
    QCOMPARE(out.size(), std::size_t{4});
    QCOMPARE(out[0].t_s, 0.1);
    QCOMPARE(out[1].t_s, 0.2);
    QCOMPARE(out[2].t_s, 0.3);
    QCOMPARE(out[3].t_s, 0.3);
    QVERIFY(out[0].type == OperatorEventType::FeedHoldOff);
    QVERIFY(out[2].type == OperatorEventType::FeedHoldOn);
    QVERIFY(out[3].type == OperatorEventType::ChatterSignal);
    QCOMPARE(q.pending(), std::size_t{0});
  }

  // An event is due when the clock is within 1e-12 s of its time or past it, and only once.
  void dueWhenTheClockReachesIt() {
    OperatorEventQueue q({{0.5, OperatorEventType::FeedHoldOn}, {0.75, OperatorEventType::FeedHoldOff}});
    QVERIFY(!q.popDue(0.25));
    QVERIFY(!q.popDue(0.5 - 1e-11));
    const auto first = q.popDue(0.5 - 1e-13);
    QVERIFY(first.has_value());
    QCOMPARE(first->t_s, 0.5);
    QVERIFY(!q.popDue(0.5));
    QCOMPARE(q.pending(), std::size_t{1});
    QCOMPARE(drain(q, 2.0).size(), std::size_t{1});
  }

  // Popped by a clock advancing in steps, the event times never decrease and each is popped at the
  // first step at or past it.
  void monotoneClock() {
    std::vector<OperatorEvent> events;
    events.reserve(50);
    for (int i = 0; i < 50; ++i) events.push_back({((i * 37) % 50) * 0.01, OperatorEventType::ChatterSignal});
    OperatorEventQueue q(events);
    double last = -1.0;
    int popped = 0;
    for (int step = 0; step <= 100; ++step) {
      const double t = step * 0.005;
      for (const OperatorEvent& e : drain(q, t)) {
        QVERIFY(e.t_s >= last);
        QVERIFY(e.t_s <= t + 1e-12);
        QVERIFY(e.t_s > t - 0.005);
        last = e.t_s;
        ++popped;
      }
    }
    QCOMPARE(popped, 50);
  }

  // Injected events take the current time and come out before the pending ones due now; those of one
  // call come out last first (each goes to the head of the queue).
  void injectedAreDueAtOnce() {
    OperatorEventQueue q({{0.1, OperatorEventType::FeedHoldOn}, {0.9, OperatorEventType::FeedHoldOff}});
    q.injectAt(0.2, {{5.0, OperatorEventType::ChatterSignal}, {7.0, OperatorEventType::FeedHoldOff}});
    QCOMPARE(q.pending(), std::size_t{4});
    const auto out = drain(q, 0.2);
    QCOMPARE(out.size(), std::size_t{3});
    QVERIFY(out[0].type == OperatorEventType::FeedHoldOff);
    QVERIFY(out[1].type == OperatorEventType::ChatterSignal);
    QVERIFY(out[2].type == OperatorEventType::FeedHoldOn);
    QCOMPARE(out[0].t_s, 0.2);
    QCOMPARE(out[1].t_s, 0.2);
    QCOMPARE(out[2].t_s, 0.1);
    QCOMPARE(q.pending(), std::size_t{1});
  }

  void texts() {
    QCOMPARE(std::string(operatorEventText(OperatorEventType::FeedHoldOn)), std::string("feed hold on"));
    QCOMPARE(std::string(operatorEventText(OperatorEventType::FeedHoldOff)), std::string("feed hold off"));
    QCOMPARE(std::string(operatorEventText(OperatorEventType::ChatterSignal)), std::string("chatter key"));
  }
};

MX_REGISTER_TEST(TestOperatorEventQueue)
#include "test_operator_event_queue.moc"
