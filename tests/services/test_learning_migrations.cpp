// The versioned schema of the learning database (app/services/learning_migrations.h), against both
// back ends: a database of the previous version (schema 1: tests/data/learning/schema-v1.sqlite, 25
// records written by the version-1 build; on PostgreSQL, the same rows in a schema-1 database) is
// migrated on opening and keeps every record field for field, with valid checksums, no machine and its
// checksum as uid; two clients opening it at once migrate it once; the migrations are numbered 1..n.
#include <QFile>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QSqlRecord>
#include <atomic>
#include <thread>

#include "services/learning_database.h"
#include "services/learning_migrations.h"
#include "support/learning_backends.h"
#include "test_registry.h"

using mx::app::LearningDatabase;

namespace {

constexpr int kVersion1Records = 25;
const char* const kVersion1Columns =
    "id, time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material, spindle_power_w, max_spindle_rpm,"
    " speed_rpm, depth_mm, feed_mm_per_tooth, mrr_cm3_s, objectives_json, weight_count, checksum";

// Every row of a table as text, one string a row: what "keeps every record" compares.
QStringList rowsOf(const QString& connection, const QString& sql) {
  QStringList rows;
  QSqlQuery q(QSqlDatabase::database(connection, false));
  if (!q.exec(sql)) return {"query failed: " + sql};
  while (q.next()) {
    QStringList fields;
    for (int i = 0; i < q.record().count(); ++i)
      fields << (q.value(i).isNull()                        ? QString("NULL")
                 : q.value(i).typeId() == QMetaType::Double ? QString::number(q.value(i).toDouble(), 'g', 17)
                                                            : q.value(i).toString());
    rows << fields.join('|');
  }
  return rows;
}

QString entriesSql() {
  return QString("SELECT %1 FROM learning_entry ORDER BY id").arg(kVersion1Columns);
}

const char* const kWeightsSql = "SELECT entry_id, position, value FROM learning_weight ORDER BY entry_id, position";

// A connection to the fixture, read-only.
struct Fixture {
  Fixture() {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", name);
    db.setDatabaseName(QString(MX_TEST_DATA_DIR) + "/learning/schema-v1.sqlite");
    db.setConnectOptions("QSQLITE_OPEN_READONLY");
    db.open();
  }
  ~Fixture() {
    { QSqlDatabase::database(name, false).close(); }
    QSqlDatabase::removeDatabase(name);
  }
  QString name = "schema_v1_fixture";
};

}  // namespace

class TestLearningMigrations : public QObject {
  Q_OBJECT
  mx::test::LearningBackends backends_;

  // A database of schema version 1 holding the fixture's records, or empty (failure recorded).
  QString version1Database(const QString& name) {
    QString location = backends_.location(name);
    if (location.isEmpty()) return {};
    if (!backends_.postgres()) {
      QFile::remove(location);
      if (!QFile::copy(QString(MX_TEST_DATA_DIR) + "/learning/schema-v1.sqlite", location)) return {};
      QFile(location).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
      return location;
    }
    LearningDatabase v1(location, LearningDatabase::OpenMode::CreateIfMissing, 1);
    Fixture fixture;
    QSqlQuery in(QSqlDatabase::database(fixture.name, false));
    QSqlQuery out(QSqlDatabase::database(v1.connectionName(), false));
    const auto copy = [&](const QString& select, const QString& insert, int columns) {
      if (!in.exec(select)) return false;
      while (in.next()) {
        out.prepare(insert);
        for (int i = 0; i < columns; ++i) out.addBindValue(in.value(i));
        if (!out.exec()) return false;
      }
      return true;
    };
    const bool copied =
        copy(entriesSql(),
             QString("INSERT INTO learning_entry (%1) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
                 .arg(kVersion1Columns),
             16) &&
        copy(kWeightsSql, "INSERT INTO learning_weight (entry_id, position, value) VALUES (?, ?, ?)", 3) &&
        out.exec("SELECT setval(pg_get_serial_sequence('learning_entry', 'id'), (SELECT MAX(id) FROM learning_entry))");
    return copied ? location : QString();
  }

 private slots:
  void initTestCase_data() { mx::test::LearningBackends::addRows(); }

  void migrationsAreNumberedOneByOne() {
    const auto& migrations = mx::app::learningMigrations();
    for (std::size_t i = 0; i < migrations.size(); ++i) {
      QCOMPARE(migrations[i].version, static_cast<int>(i) + 1);
      QVERIFY(!migrations[i].statements.empty());
    }
    QCOMPARE(mx::app::latestLearningSchemaVersion(), static_cast<int>(migrations.size()));
  }

  void previousVersionKeepsEveryRecord() {
    const QString location = version1Database("previous");
    QVERIFY(!location.isEmpty());
    Fixture fixture;
    const QStringList entries = rowsOf(fixture.name, entriesSql());
    const QStringList weights = rowsOf(fixture.name, kWeightsSql);
    QCOMPARE(entries.size(), kVersion1Records);
    QCOMPARE(weights.size(), 4 * kVersion1Records);
    {
      LearningDatabase v1(location, LearningDatabase::OpenMode::ExistingOnly, 1);
      QCOMPARE(v1.schemaVersion(), 1);  // opening at version 1 migrates nothing
    }

    LearningDatabase db(location, LearningDatabase::OpenMode::ExistingOnly);
    QCOMPARE(db.schemaVersion(), 2);
    QCOMPARE(rowsOf(db.connectionName(), entriesSql()), entries);  // field for field
    QCOMPARE(rowsOf(db.connectionName(), kWeightsSql), weights);
    const mx::app::LearningConsistency c = db.checkConsistency();
    QVERIFY2(c.ok(), qPrintable(c.problems.join("; ")));  // the version-1 checksums still hold
    QCOMPARE(c.entries, kVersion1Records);
    for (const mx::app::LearningRecord& r : db.history({std::nullopt, std::nullopt, std::nullopt, 0})) {
      QVERIFY(!r.machine.name);
      QCOMPARE(r.uid.size(), 64);  // the SHA-256 checksum
    }
    mx::app::LearningRecord next = db.history().front();
    next.uid.clear();
    next.machine.name = "DMU-50";
    QVERIFY(db.insert(next) > kVersion1Records);
    QCOMPARE(db.count(), kVersion1Records + 1);
  }

  // Two clients that open a version-1 database at the same moment apply migration 2 once between them.
  void simultaneousOpeningsMigrateOnce() {
    const QString location = version1Database("simultaneous");
    QVERIFY(!location.isEmpty());
    std::atomic<int> failures{0};
    std::vector<std::thread> clients;
    clients.reserve(4);
    for (int i = 0; i < 4; ++i)
      clients.emplace_back([&] {
        try {
          LearningDatabase db(location, LearningDatabase::OpenMode::ExistingOnly);
          if (db.schemaVersion() != 2) ++failures;
        } catch (const std::exception& e) {
          qWarning("%s", e.what());
          ++failures;
        }
      });
    for (std::thread& c : clients) c.join();
    QCOMPARE(failures.load(), 0);
    LearningDatabase db(location, LearningDatabase::OpenMode::ExistingOnly);
    QCOMPARE(db.count(), kVersion1Records);
    QVERIFY(db.checkConsistency().ok());
  }
};

MX_REGISTER_TEST(TestLearningMigrations)
#include "test_learning_migrations.moc"
