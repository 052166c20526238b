#pragma once
// The SQL of the learning database that differs between SQLite and PostgreSQL, all of it: the column
// types and checks the migrations write as tokens, the transactions, the catalogue queries, the
// limits. Everything else is one text for both back ends (docs/learning-database.md, "Back ends").
#include <QString>

#include "services/learning_location.h"

namespace mx::app {

class LearningSqlDialect {
 public:
  explicit LearningSqlDialect(LearningBackend backend) : backend_(backend) {}
  LearningBackend backend() const { return backend_; }
  bool isSqlite() const { return backend_ == LearningBackend::Sqlite; }

  const char* driver() const;  // the Qt SQL driver: QSQLITE or QPSQL
  // A migration statement with its tokens replaced: {ID} the auto-numbered key, {ID_REF} a column
  // referencing it, {REAL} a double, {OBJECTIVES_JSON_CHECK} the check that objectives_json is JSON,
  // {WITHOUT_ROWID} SQLite's clustered-table clause.
  QString expand(const char* statement) const;

  // A write transaction that takes the write lock at once (SQLite's deferred BEGIN would upgrade the
  // lock later and could fail with "database is locked" when two writers race).
  const char* beginWrite() const;
  // A read transaction: one snapshot for every statement of a query.
  const char* beginRead() const;
  // Serialises migrations between clients inside their transaction ("" when beginWrite already does).
  const char* lockForMigration() const;
  // SELECT COUNT(*) of the tables named by the one bind value.
  const char* tableExists() const;
  // " LIMIT n", or "" for no limit (limit <= 0).
  QString limit(int rows) const;

 private:
  LearningBackend backend_;
};

}  // namespace mx::app
