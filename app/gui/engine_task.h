#pragma once
// One-shot engine-thread tasks for the GUI: `work` runs on the engine pool, `done` on the channel
// owner's (GUI) thread. Exceptions from `work` reach `done` as an error message. Callers tag requests
// with a generation id and ignore stale results in `done`.
#include <QString>
#include <QThreadPool>
#include <exception>
#include <functional>
#include <optional>

#include "engine_channel.h"

namespace mx::gui {

template <class T>
struct TaskResult {
  std::optional<T> value;
  QString error;  // set when work threw
};

template <class T>
void runEngineTask(EngineChannel& channel, QThreadPool* pool, std::function<T()> work,
                   std::function<void(TaskResult<T>)> done) {
  channel.start(pool, [work = std::move(work), done = std::move(done)](const EngineReply& reply) {
    TaskResult<T> r;
    try {
      r.value = work();
    } catch (const std::exception& e) {
      r.error = QString::fromStdString(e.what());
    }
    reply([done, r = std::move(r)]() mutable { done(std::move(r)); });
  });
}

}  // namespace mx::gui
