#pragma once
// Rule 14 learning database (Rubio et al., Pareto expert system): every programmed point with the
// weights that produced it and the machine that ran it, in SQLite (one file, the default) or on a
// shared PostgreSQL server, through Qt Sql and one code path. Schema, migrations, durability and the
// similarity rule: docs/learning-database.md.
//
// - One connection per instance, under a unique Qt connection name: several instances (on the same or
//   different databases) coexist, and each thread uses its own instance (a Qt Sql connection must
//   only be used from the thread that opened it).
// - Every write is ONE transaction (the entry rows and their weight rows), so a killed writer leaves
//   whole records or nothing; a record's uid is unique, so a retried or re-imported record is stored
//   once. Reads run in one snapshot, so a reader never sees half a record.
// - SQLite: WAL journal, synchronous=FULL, busy timeout 60 s.
// - Every error throws LearningDatabaseError naming the file or the URL.
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "services/learning_database_error.h"
#include "services/learning_location.h"
#include "services/learning_record.h"
#include "services/learning_sql.h"
#include "services/weight_suggestion.h"

class QSqlQuery;
class QVariant;

namespace mx::app {

struct LearningHistoryQuery {
  std::optional<QString> tool;      // exact tool id
  std::optional<QString> material;  // exact material name
  std::optional<QString> machine;   // exact machine name
  int limit = 100;                  // newest first; <= 0: no limit
};

// Result of checkConsistency(): SQLite's integrity_check and foreign_key_check ("ok" on PostgreSQL,
// whose server enforces both), plus every entry checked for completeness (its weight rows =
// weight_count), its uid and its per-row SHA-256 checksum.
struct LearningConsistency {
  QString integrity;  // "ok" when clean
  qint64 entries = 0;
  QStringList problems;  // empty when consistent
  bool ok() const { return integrity == QLatin1String("ok") && problems.isEmpty(); }
};

// What the history can be filtered by: each has the distinct values stored (facetValues).
enum class LearningFacet { Tool, Material, Machine };

class LearningDatabase {
 public:
  enum class OpenMode { CreateIfMissing, ExistingOnly };
  static constexpr int kApplicationId = 0x4D584C44;  // SQLite's PRAGMA application_id, "MXLD"

  // learning.sqlite in the AppDataLocation of the MillExpert application (organisation and
  // application "MillExpert", whichever executable asks), so the GUI and the CLI share one file.
  static QString defaultPath();
  // The user's choice (the setting learning/database, learning_location.h), else defaultPath().
  static QString configuredOrDefault();

  // Opens the database at a file path or a postgresql:// URL (learning_location.h) and brings its
  // schema to the latest version, one migration per version. With CreateIfMissing a missing SQLite
  // file (and its folder, for the default file) is created; a PostgreSQL database must exist, its
  // tables are created. Throws LearningDatabaseError: bad location, missing file (ExistingOnly),
  // cannot connect, not a database / corrupt, a foreign file or table, a newer schema.
  explicit LearningDatabase(const QString& location = defaultPath(), OpenMode mode = OpenMode::CreateIfMissing);
  // Migrates only up to target_version (0 < target <= latest): how a test builds an older schema.
  LearningDatabase(const QString& location, OpenMode mode, int target_version);
  ~LearningDatabase();
  LearningDatabase(const LearningDatabase&) = delete;
  LearningDatabase& operator=(const LearningDatabase&) = delete;

  // The file path or the URL without options (never a password).
  QString location() const { return location_.display(); }
  LearningBackend backend() const { return location_.backend; }
  const QString& connectionName() const { return connection_; }
  int schemaVersion() const;
  QString journalMode() const;  // SQLite's journal mode; "" on PostgreSQL

  // Validates and stores one record in one transaction; returns its id. An invalid time is replaced
  // by "now", an empty uid by a new UUID; a record whose uid is stored already is not stored again
  // (its stored id is returned). Throws LearningDatabaseError (invalid record, or the write failed:
  // rolled back).
  qint64 insert(const LearningRecord& record);
  // Several records in ONE transaction: all of them are stored, or none.
  std::vector<qint64> insertAll(const std::vector<LearningRecord>& records);

  std::vector<LearningRecord> history(const LearningHistoryQuery& query = {}) const;
  // The records (with their weights) whose MRR [cm^3/s] lies in [lo, hi], newest first.
  std::vector<LearningRecord> withMrrIn(double lo_cm3_s, double hi_cm3_s, int limit = 100) const;
  // Weights of the k most similar past jobs (weight_suggestion.h); nullopt when none qualifies.
  std::optional<WeightSuggestion> suggestInitialWeights(const JobFeatures& job, int k = 3) const;
  qint64 count() const;
  // The distinct values of a facet over every record (records naming no machine add none): one query,
  // whatever the number of records.
  QStringList facetValues(LearningFacet facet) const;
  LearningConsistency checkConsistency() const;

 private:
  void open(OpenMode mode);
  void configureSqlite();
  struct StoredSchema {
    int version = 0;         // 0: an empty database
    bool has_table = false;  // the version table exists (SQLite files of version 1 lack it)
  };
  StoredSchema storedSchema() const;
  void createSchemaTable(int version);
  void migrate(int target_version);
  void applyMigration(int target_version);
  qint64 insertInTransaction(const LearningRecord& record);
  void closeConnection();
  [[noreturn]] void fail(const QString& what) const;
  QSqlQuery run(const QString& sql, const QList<QVariant>& binds = {}) const;
  QVariant scalar(const QString& sql, const QList<QVariant>& binds = {}) const;
  bool tableExists(const char* name) const;
  template <typename Work>
  auto inTransaction(const char* begin, Work work) const;
  std::vector<LearningRecord> select(const QString& where, const QList<QVariant>& binds, int limit,
                                     QStringList* problems = nullptr) const;

  LearningLocation location_;
  LearningSqlDialect sql_;
  QString connection_;
};

}  // namespace mx::app
