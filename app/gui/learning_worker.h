#pragma once
// The Rule 14 learning database off the GUI thread. A PostgreSQL connection can take its whole
// connect_timeout to fail, and a Qt Sql connection may only be used by the thread that opened it, so
// the database lives on one dedicated thread: LearningWorker is the QObject there that owns the
// connection to the current location, reopening it when the location changes (or after an error:
// the server may have gone away). LearningClient (learning_client.h) is its GUI-side face.
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>
#include <vector>

#include "services/learning_record.h"

namespace mx::app {
class LearningDatabase;
}

namespace mx::gui {

// What the history view asks for: exact tool, material, machine and source ("" = any) and an MRR band
// [cm³/s] (both bounds or none).
struct LearningHistoryRequest {
  QString tool, material, machine, source;
  std::optional<double> mrr_lo, mrr_hi;
  int limit = 500;
};

struct LearningHistoryResult {
  std::vector<app::LearningRecord> records;  // newest first, filtered
  QStringList tools, materials, machines;    // every value stored, sorted: the filter choices
  qint64 total = 0;                          // records in the database
  QString location;                          // file path or URL (never a password)
};

class LearningWorker : public QObject {
  Q_OBJECT
 public:
  explicit LearningWorker(QObject* parent = nullptr);
  ~LearningWorker() override;

  // Called on the learning thread only (queued by LearningClient).
  void record(quint64 generation, const QString& location, const app::LearningRecord& record);
  void loadHistory(quint64 generation, const QString& location, const LearningHistoryRequest& request);
  void close();  // before the thread ends: the connection is removed on the thread that opened it

 signals:
  void recorded(quint64 generation, qint64 id, const QString& location);
  void historyLoaded(quint64 generation, const mx::gui::LearningHistoryResult& result);
  void recordFailed(quint64 generation, const QString& message);
  void historyFailed(quint64 generation, const QString& message);

 private:
  app::LearningDatabase& database(const QString& location);

  std::unique_ptr<app::LearningDatabase> db_;
  QString location_;  // what db_ was opened with
};

// Opens `location` on the calling thread, reads its schema version and counts its records: what
// Settings > Learning database's Test connection reports. A missing SQLite file is not created.
struct LearningConnectionReport {
  bool ok = false;
  QString text;  // "Connected to <location>: schema 2, 1 234 records", or the error
};
LearningConnectionReport testLearningConnection(const QString& location);

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::LearningHistoryResult)
