// EngineChannel: a job runs on the pool, not on the owner's thread; its calls come back on the owner's
// thread in posting order; once the owner is gone nothing more is delivered and nothing crashes.
#include <QThread>
#include <QThreadPool>
#include <atomic>
#include <thread>

#include "engine_channel.h"
#include "test_registry.h"

using namespace mx::gui;

class TestEngineChannel : public QObject {
  Q_OBJECT
 private slots:
  void jobRunsOnThePoolAndRepliesOnTheOwnersThread() {
    QThreadPool pool;
    QObject owner;
    EngineChannel channel(&owner);
    QThread* job_thread = nullptr;
    QThread* reply_thread = nullptr;
    int result = 0;
    channel.start(&pool, [&job_thread, &reply_thread, &result, input = 21](const EngineReply& reply) {
      job_thread = QThread::currentThread();
      reply([&reply_thread, &result, value = 2 * input] {
        reply_thread = QThread::currentThread();
        result = value;
      });
    });
    QTRY_COMPARE(result, 42);
    QVERIFY(job_thread != nullptr);
    QVERIFY(job_thread != QThread::currentThread());
    QCOMPARE(reply_thread, QThread::currentThread());
  }

  void repliesArriveInPostingOrder() {
    QThreadPool pool;
    QObject owner;
    EngineChannel channel(&owner);
    std::vector<int> order;
    constexpr int kCalls = 200;
    channel.start(&pool, [&order](const EngineReply& reply) {
      for (int i = 0; i < kCalls; ++i) reply([&order, i] { order.push_back(i); });
    });
    QTRY_COMPARE(static_cast<int>(order.size()), kCalls);
    for (int i = 0; i < kCalls; ++i) QCOMPARE(order[static_cast<size_t>(i)], i);
  }

  void nothingIsDeliveredOnceTheOwnerIsGone() {
    QThreadPool pool;
    std::atomic<bool> release{false};
    std::atomic<bool> posted{false};
    int delivered = 0;
    {
      QObject owner;
      EngineChannel channel(&owner);
      channel.start(&pool, [&](const EngineReply& reply) {
        reply([&delivered] { ++delivered; });  // queued while the owner lives, discarded with it
        while (!release.load()) std::this_thread::yield();
        reply([&delivered] { ++delivered; });  // the owner is gone: dropped at once
        posted.store(true);
      });
      QTRY_VERIFY(pool.activeThreadCount() == 1);
    }
    release.store(true);
    QVERIFY(pool.waitForDone(10000));
    QVERIFY(posted.load());
    QCoreApplication::processEvents();
    QCOMPARE(delivered, 0);
  }
};

MX_REGISTER_TEST(TestEngineChannel)
#include "test_engine_channel.moc"
