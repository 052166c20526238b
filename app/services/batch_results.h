#pragma once
// The results file of `batch` (JSON Lines): one object per case, appended and flushed line by line so
// that a killed job leaves whole lines behind, and at most one torn last line.
#include <QFile>
#include <QJsonObject>
#include <QSet>
#include <QString>
#include <functional>
#include <mutex>

namespace mx::app {

struct BatchResultsScan {
  qint64 whole_lines = 0;
  qint64 whole_bytes = 0;       // where the whole lines end
  bool torn_last_line = false;  // a last line without its newline, or not a JSON object with "hash"
};

// Calls `line` with each whole line of `path` (none when it does not exist), one at a time so that a
// large file is never held whole. Throws InputError naming the file and line for a bad line before the
// last one: that is not a torn write, and nothing should be appended after it.
BatchResultsScan scanBatchResults(const QString& path, const std::function<void(const QJsonObject&)>& line);

// The hashes already computed in `path`, after cutting a torn last line off the file (so that its case
// is redone).
QSet<QString> resumeBatchResults(const QString& path);

// Appends one line per call, from any thread; each line is written whole and flushed before the next.
class BatchResultsWriter {
 public:
  explicit BatchResultsWriter(const QString& path);  // throws InputError when it cannot open the file
  void append(const QJsonObject& line);              // throws ComputationError when the write fails

 private:
  std::mutex mutex_;
  QFile file_;
};

}  // namespace mx::app
