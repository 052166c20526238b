#pragma once
// The two back ends of the learning database a test runs against, as the global data of a QtTest
// class (rows "sqlite" and "postgresql"): call addRows() from initTestCase_data(), then location(name)
// in a test gives a new, empty database of the current row: a file in the test's folder, or a new
// database on a real PostgreSQL server started on first use (postgres_server.h), which QVERIFY2
// reports when it cannot start.
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "support/postgres_server.h"

namespace mx::test {

class LearningBackends {
 public:
  static void addRows() {
    QTest::addColumn<bool>("postgres");
    QTest::newRow("sqlite") << false;
    QTest::newRow("postgresql") << true;
  }

  static bool postgres() {
    QFETCH_GLOBAL(bool, postgres);
    return postgres;
  }

  // A new database named after `name` (letters, digits, '_'); empty (and a QTest failure recorded)
  // when the server cannot start or create it.
  QString location(const QString& name) {
    if (!postgres()) return dir_.filePath(name + ".sqlite");
    if (!startServer()) return {};
    const QString database = QString("%1_%2").arg(name.toLower()).arg(++databases_);
    QString why;
    if (!server_->createDatabase(database, &why)) {
      QTest::qFail(qPrintable("CREATE DATABASE " + database + ": " + why), __FILE__, __LINE__);
      return {};
    }
    return server_->url(database);
  }

  PostgresServer* server() { return startServer() ? server_.get() : nullptr; }
  const QTemporaryDir& folder() const { return dir_; }

 private:
  bool startServer() {
    if (server_) return true;
    if (!failure_.isEmpty()) {
      QTest::qFail(qPrintable("the PostgreSQL server did not start: " + failure_), __FILE__, __LINE__);
      return false;
    }
    auto server = std::make_unique<PostgresServer>();
    failure_ = server->start();
    if (!failure_.isEmpty()) {
      QTest::qFail(qPrintable("the PostgreSQL server did not start: " + failure_), __FILE__, __LINE__);
      return false;
    }
    server_ = std::move(server);
    return true;
  }

  QTemporaryDir dir_;
  std::unique_ptr<PostgresServer> server_;
  QString failure_;
  int databases_ = 0;
};

// A statement on a LearningDatabase's own connection (same thread), behind the class's back: the first
// value of its first row, or an invalid QVariant.
template <typename Database>
QVariant rawScalar(const Database& db, const QString& sql) {
  QSqlQuery q(QSqlDatabase::database(db.connectionName(), false));
  if (!q.exec(sql) || !q.next()) return {};
  return q.value(0);
}

}  // namespace mx::test

// In a test of a class with a LearningBackends member backends_: a new empty database of the current
// back end in `var`, or return from the test (the failure is recorded).
#define MX_NEW_DATABASE(var, name)              \
  const QString var = backends_.location(name); \
  if ((var).isEmpty()) return
