// RingBuffer: bounded memory, keeps the newest values, oldest first by index.
#include <vector>

#include "ring_buffer.h"
#include "test_registry.h"

using mx::widgets::RingBuffer;

class TestRingBuffer : public QObject {
  Q_OBJECT
 private slots:
  void fillsUpToCapacity() {
    RingBuffer<double> b(5);
    QVERIFY(b.empty());
    for (int i = 0; i < 3; ++i) b.push(i);
    QCOMPARE(b.size(), std::size_t{3});
    QCOMPARE(b.front(), 0.0);
    QCOMPARE(b.back(), 2.0);
    QCOMPARE(b[1], 1.0);
  }

  void tenTimesCapacityKeepsSizeAndLatestValues() {
    const std::size_t capacity = 1000;
    RingBuffer<double> b(capacity);
    const std::size_t pushed = 10 * capacity;
    for (std::size_t i = 0; i < pushed; ++i) b.push(static_cast<double>(i));
    QCOMPARE(b.size(), capacity);
    QCOMPARE(b.capacity(), capacity);
    QCOMPARE(b.totalPushed(), pushed);
    // The last `capacity` values, in order: 9000 .. 9999.
    for (std::size_t i = 0; i < capacity; ++i) QCOMPARE(b[i], static_cast<double>(pushed - capacity + i));
    QCOMPARE(b.front(), 9000.0);
    QCOMPARE(b.back(), 9999.0);
    const std::vector<double> v = b.toVector();
    QCOMPARE(v.size(), capacity);
    QCOMPARE(v.front(), 9000.0);
    QCOMPARE(v.back(), 9999.0);
  }

  void spanPushLongerThanCapacity() {
    RingBuffer<int> b(4);
    b.push(-1);
    const std::vector<int> values{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    b.push(std::span<const int>(values));
    QCOMPARE(b.size(), std::size_t{4});
    QCOMPARE(b.totalPushed(), std::size_t{11});
    QCOMPARE(b.toVector(), (std::vector<int>{6, 7, 8, 9}));
    b.push(std::span<const int>(values).first(2));
    QCOMPARE(b.toVector(), (std::vector<int>{8, 9, 0, 1}));
  }

  void clearEmpties() {
    RingBuffer<double> b(3);
    for (int i = 0; i < 7; ++i) b.push(i);
    b.clear();
    QVERIFY(b.empty());
    QCOMPARE(b.totalPushed(), std::size_t{0});
    b.push(42.0);
    QCOMPARE(b.size(), std::size_t{1});
    QCOMPARE(b.front(), 42.0);
  }

  void zeroCapacityIsRefused() { QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RingBuffer<double>(0)); }
};

MX_REGISTER_TEST(TestRingBuffer)
#include "test_ring_buffer.moc"
