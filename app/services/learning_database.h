#pragma once
// Rule 14 learning database (Rubio et al., Pareto expert system): every programmed point with the
// weights that produced it, in SQLite through Qt Sql. Schema, durability and the similarity rule:
// docs/learning-database.md.
//
// - One SQLite connection per instance, under a unique Qt connection name: several instances (on the
//   same or different files) coexist, and each thread uses its own instance (a Qt Sql connection must
//   only be used from the thread that opened it).
// - WAL journal, synchronous=FULL, busy timeout 10 s; each insert is ONE "BEGIN IMMEDIATE"
//   transaction (the entry row and its weight rows), so a killed writer leaves either the whole
//   record or nothing.
// - Every error throws LearningDatabaseError naming the file.
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "services/learning_database_error.h"
#include "services/learning_record.h"
#include "services/weight_suggestion.h"

class QSqlQuery;
class QVariant;

namespace mx::app {

struct LearningHistoryQuery {
  std::optional<QString> tool;      // exact tool id
  std::optional<QString> material;  // exact material name
  int limit = 100;                  // newest first; <= 0: no limit
};

// Result of checkConsistency(): SQLite's integrity_check and foreign_key_check, plus every entry
// checked for completeness (its weight rows = weight_count) and its per-row SHA-256 checksum.
struct LearningConsistency {
  QString integrity;  // "ok" when PRAGMA integrity_check is clean
  qint64 entries = 0;
  QStringList problems;  // empty when consistent
  bool ok() const { return integrity == QLatin1String("ok") && problems.isEmpty(); }
};

class LearningDatabase {
 public:
  enum class OpenMode { CreateIfMissing, ExistingOnly };
  static constexpr int kSchemaVersion = 1;           // PRAGMA user_version
  static constexpr int kApplicationId = 0x4D584C44;  // PRAGMA application_id, "MXLD"

  // learning.sqlite in the AppDataLocation of the MillExpert application (organisation and
  // application "MillExpert", whichever executable asks), so the GUI and the CLI share one file.
  static QString defaultPath();

  // Opens (and with CreateIfMissing creates, with its folder) the database and brings its schema to
  // kSchemaVersion. Throws LearningDatabaseError: missing file (ExistingOnly), cannot open, not a
  // database / corrupt, a foreign SQLite file, a newer schema.
  explicit LearningDatabase(const QString& path = defaultPath(), OpenMode mode = OpenMode::CreateIfMissing);
  ~LearningDatabase();
  LearningDatabase(const LearningDatabase&) = delete;
  LearningDatabase& operator=(const LearningDatabase&) = delete;

  const QString& path() const { return path_; }
  const QString& connectionName() const { return connection_; }
  int schemaVersion() const;
  QString journalMode() const;

  // Validates and stores one record in one transaction; returns its id. An invalid time is replaced
  // by "now". Throws LearningDatabaseError (invalid record, or the write failed: rolled back).
  qint64 insert(const LearningRecord& record);

  std::vector<LearningRecord> history(const LearningHistoryQuery& query = {}) const;
  // The records (with their weights) whose MRR [cm^3/s] lies in [lo, hi], newest first.
  std::vector<LearningRecord> withMrrIn(double lo_cm3_s, double hi_cm3_s, int limit = 100) const;
  // Weights of the k most similar past jobs (weight_suggestion.h); nullopt when none qualifies.
  std::optional<WeightSuggestion> suggestInitialWeights(const JobFeatures& job, int k = 3) const;
  qint64 count() const;
  LearningConsistency checkConsistency() const;

 private:
  void open(OpenMode mode);
  void configure();
  void migrate();
  void closeConnection();
  [[noreturn]] void fail(const QString& what) const;
  QSqlQuery run(const QString& sql, const QList<QVariant>& binds = {}) const;
  QVariant scalar(const QString& sql) const;
  std::vector<LearningRecord> select(const QString& where, const QList<QVariant>& binds, int limit,
                                     QStringList* problems = nullptr) const;

  QString path_;
  QString connection_;
};

}  // namespace mx::app
