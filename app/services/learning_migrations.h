#pragma once
// The versioned schema of the learning database: migration n brings version n-1 to n, each applied in
// its own transaction with the new version (docs/learning-database.md, "Schema and migrations").
// Statements are written once for both back ends, with the tokens of LearningSqlDialect::expand.
#include <vector>

namespace mx::app {

struct LearningMigration {
  int version;  // the schema version after this migration
  std::vector<const char*> statements;
};

// In version order, 1, 2, ...; the last one's version is the schema this build writes.
const std::vector<LearningMigration>& learningMigrations();
int latestLearningSchemaVersion();

// The table that holds the schema version on both back ends (one row), created before the first
// migration; SQLite files of version 1 kept it in PRAGMA user_version only.
inline constexpr const char* kLearningSchemaTable =
    "CREATE TABLE learning_schema ("
    " singleton INTEGER PRIMARY KEY CHECK (singleton = 1),"
    " application TEXT NOT NULL,"
    " version INTEGER NOT NULL)";
inline constexpr const char* kLearningApplication = "MillExpert learning database";

}  // namespace mx::app
