#pragma once
// Where the Rule 14 learning database lives: an SQLite file (the embedded default, zero set-up) or a
// shared PostgreSQL server given by a URL, postgresql://[user@]host[:port]/database[?options]
// (docs/learning-database.md). A password is never part of a location: libpq takes it from
// PGPASSWORD or ~/.pgpass (PGPASSFILE), so it never lands in a project, the settings or a log.
#include <QString>

class QSettings;

namespace mx::app {

enum class LearningBackend { Sqlite, PostgreSql };

struct LearningLocation {
  LearningBackend backend = LearningBackend::Sqlite;
  QString file;      // Sqlite
  QString user;      // PostgreSql; empty: libpq's default (PGUSER, else the login name)
  QString host;      // PostgreSql
  int port = 5432;   // PostgreSql
  QString database;  // PostgreSql
  // libpq options of the URL's query, "key=value;key=value" as Qt's QPSQL connect options take them.
  QString connect_options;

  // The file path, or the URL without options: what messages, the history view and logs show.
  QString display() const;
};

// A text starting with postgresql:// or postgres:// is a URL, anything else a file path. Throws
// std::invalid_argument naming the text and what is wrong: an empty text, a password in the URL, no
// host or database, a port outside 1..65535, an option other than sslmode, sslrootcert, sslcert,
// sslkey, connect_timeout (1..3600 s) or target_session_attrs.
LearningLocation parseLearningLocation(const QString& text);
// Whether the text is a postgresql:// or postgres:// URL (and not a file path), valid or not.
bool isLearningUrl(const QString& text);
// The text with any password replaced by "***": what an error message may show of it.
QString redactedLearningLocation(QString text);

// The user's learning database: the setting "learning/database" of MillExpert (a path or a URL),
// read by the GUI and millexpert-cli alike; empty when not set.
inline constexpr const char* kLearningDatabaseSetting = "learning/database";
QString configuredLearningDatabase();
void setConfiguredLearningDatabase(const QString& location);  // empty: back to the default file

}  // namespace mx::app
