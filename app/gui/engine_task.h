#pragma once
// One-shot engine-thread tasks for the GUI: `work` runs on the engine pool, `done` on the GUI thread
// (queued, through a QFutureWatcher parented to `context`). Exceptions from `work` reach `done` as an
// error message. Callers tag requests with a generation id and ignore stale results in `done`.
#include <QFutureWatcher>
#include <QString>
#include <QThreadPool>
#include <QtConcurrent>
#include <functional>
#include <optional>

namespace mx::gui {

template <class T>
struct TaskResult {
  std::optional<T> value;
  QString error;  // set when work threw
};

template <class T>
void runEngineTask(QThreadPool* pool, QObject* context, std::function<T()> work,
                   std::function<void(TaskResult<T>)> done) {
  auto* watcher = new QFutureWatcher<TaskResult<T>>(context);
  QObject::connect(watcher, &QFutureWatcher<TaskResult<T>>::finished, context, [watcher, done] {
    TaskResult<T> r = watcher->result();
    watcher->deleteLater();
    done(std::move(r));
  });
  watcher->setFuture(QtConcurrent::run(pool, [work] {
    TaskResult<T> r;
    try {
      r.value = work();
    } catch (const std::exception& e) {
      r.error = QString::fromStdString(e.what());
    }
    return r;
  }));
}

}  // namespace mx::gui
