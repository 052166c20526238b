// The Rule 14 learning database on both back ends (app/services/learning_database.h): one record
// stored (one transaction: the entry and its 4 weight rows), and the history view's query of 500
// records with their weights (one joined query in one snapshot). SQLite runs on a file in a temporary
// folder (WAL, synchronous=FULL); PostgreSQL on a real server started for the benchmark on loopback
// (tests/support/postgres_server.h, fsync off: the cost measured is the client's and the protocol's).
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <memory>

#include "services/learning_database.h"
#include "support/postgres_server.h"

namespace {

QCoreApplication& application() {
  static int argc = 1;
  static char name[] = "millexpert-bench";
  static char* argv[] = {name, nullptr};
  static QCoreApplication app(argc, argv);
  return app;
}

mx::app::LearningRecord benchRecord(int i) {
  mx::app::LearningRecord r;
  r.weights = {0.1, 0.2, 0.3, 0.4};
  r.tool = {QString("T%1").arg(i % 50), 10.0, 3};
  r.material = "Aluminium";
  r.machine = {QString("DMU-50"), 15000.0, 18000.0};
  r.q = {5000.0 + i, 1.0, 0.1};
  r.objectives = QJsonObject{{"tol", 40.0}, {"mrr_cm3_s", 1.0 + 0.001 * i}, {"surf", 1.2}, {"ros", 0.8}};
  return r;
}

// The location of an empty database of the back end, or "" with the reason in `why`.
QString benchLocation(bool postgres, QString* why) {
  application();
  static QTemporaryDir dir;
  static int databases = 0;
  ++databases;
  if (!postgres) return dir.filePath(QString("bench-%1.sqlite").arg(databases));
  static std::unique_ptr<mx::test::PostgresServer> server;
  static QString failure;
  if (!server && failure.isEmpty()) {
    server = std::make_unique<mx::test::PostgresServer>();
    failure = server->start();
  }
  if (!failure.isEmpty()) {
    *why = failure;
    return {};
  }
  const QString name = QString("bench_%1").arg(databases);
  return server->createDatabase(name, why) ? server->url(name) : QString();
}

// A new database of the benchmark's back end (argument 1: PostgreSQL), or none (the run is skipped with
// the reason).
std::unique_ptr<mx::app::LearningDatabase> benchDatabase(benchmark::State& state) {
  QString why;
  const QString location = benchLocation(state.range(0) == 1, &why);
  if (location.isEmpty()) {
    state.SkipWithError(qPrintable("no database: " + why));
    return nullptr;
  }
  return std::make_unique<mx::app::LearningDatabase>(location);
}

void BM_LearningInsert(benchmark::State& state) {
  const auto db = benchDatabase(state);
  if (!db) return;
  int i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(db->insert(benchRecord(i++)));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LearningInsert)->ArgName("postgres")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_LearningHistory500(benchmark::State& state) {
  const auto db = benchDatabase(state);
  if (!db) return;
  std::vector<mx::app::LearningRecord> records;
  for (int i = 0; i < 2000; ++i) records.push_back(benchRecord(i));
  db->insertAll(records);
  for (auto _ : state) {
    const auto history = db->history({std::nullopt, std::nullopt, std::nullopt, 500});
    if (history.size() != 500 || history.front().weights.size() != 4) state.SkipWithError("wrong history");
  }
  state.SetItemsProcessed(state.iterations() * 500);
}
BENCHMARK(BM_LearningHistory500)->ArgName("postgres")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
