#include "services/learning_migrations.h"

namespace mx::app {

namespace {

// Version 1: the Rule 14 record (Rubio et al., Pareto expert system): one entry row per programmed
// point and its weight vector, one row per component.
const LearningMigration kVersion1{
    1,
    {
        "CREATE TABLE learning_entry ("
        " id {ID},"
        " time_utc TEXT NOT NULL,"
        " source TEXT NOT NULL CHECK (source IN ('operator', 'automatic', 'rule', 'feedback')),"
        " tool_id TEXT NOT NULL CHECK (tool_id <> ''),"
        " tool_diameter_mm {REAL} NOT NULL CHECK (tool_diameter_mm > 0),"
        " tool_teeth INTEGER NOT NULL CHECK (tool_teeth >= 1),"
        " material TEXT NOT NULL CHECK (material <> ''),"
        " spindle_power_w {REAL} NOT NULL,"
        " max_spindle_rpm {REAL},"
        " speed_rpm {REAL} NOT NULL,"
        " depth_mm {REAL} NOT NULL,"
        " feed_mm_per_tooth {REAL} NOT NULL,"
        " mrr_cm3_s {REAL},"
        " objectives_json TEXT NOT NULL {OBJECTIVES_JSON_CHECK},"
        " weight_count INTEGER NOT NULL CHECK (weight_count >= 1),"
        " checksum TEXT NOT NULL)",
        "CREATE TABLE learning_weight ("
        " entry_id {ID_REF} NOT NULL REFERENCES learning_entry(id) ON DELETE CASCADE,"
        " position INTEGER NOT NULL CHECK (position >= 0),"
        " value {REAL} NOT NULL,"
        " PRIMARY KEY (entry_id, position)){WITHOUT_ROWID}",
        "CREATE INDEX learning_entry_tool ON learning_entry(tool_id, time_utc)",
        "CREATE INDEX learning_entry_material ON learning_entry(material, time_utc)",
        "CREATE INDEX learning_entry_mrr ON learning_entry(mrr_cm3_s)",
        "CREATE INDEX learning_entry_time ON learning_entry(time_utc)",
    }};

// Version 2, the shared database: each record names its machine, and carries a unique id that its
// writer chooses, so that a retried or re-imported record is stored once. Version-1 rows take their
// checksum as that id (equal rows from two files are one record; a repeat within one file gets its
// row id appended).
constexpr const char* kFirstOfEachChecksumKeepsIt =
    "UPDATE learning_entry SET record_uid = checksum WHERE id IN (SELECT MIN(id) FROM learning_entry GROUP BY "
    "checksum)";
const LearningMigration kVersion2{
    2,
    {
        "ALTER TABLE learning_entry ADD COLUMN machine TEXT CHECK (machine <> '')",
        "ALTER TABLE learning_entry ADD COLUMN record_uid TEXT",
        kFirstOfEachChecksumKeepsIt,
        "UPDATE learning_entry SET record_uid = checksum || '-' || id WHERE record_uid IS NULL",
        "CREATE UNIQUE INDEX learning_entry_uid ON learning_entry(record_uid)",
        "CREATE INDEX learning_entry_machine ON learning_entry(machine, time_utc)",
    }};

}  // namespace

const std::vector<LearningMigration>& learningMigrations() {
  static const std::vector<LearningMigration> migrations{kVersion1, kVersion2};
  return migrations;
}

int latestLearningSchemaVersion() {
  return learningMigrations().back().version;
}

}  // namespace mx::app
