#include "learning_worker.h"

#include <QFileInfo>
#include <algorithm>
#include <exception>
#include <mutex>

#include "engine_channel.h"
#include "services/learning_database.h"

namespace mx::gui {

namespace {

// 1234567 -> "1 234 567": a count read at a glance, in any locale.
QString groupedCount(qint64 n) {
  QString digits = QString::number(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, QChar(' '));
  return digits;
}

bool matches(const LearningHistoryRequest& request, const app::LearningRecord& r) {
  return (request.tool.isEmpty() || r.tool.id == request.tool) &&
         (request.material.isEmpty() || r.material == request.material) &&
         (request.machine.isEmpty() || r.machine.name.value_or(QString()) == request.machine) &&
         (request.source.isEmpty() || app::learningSourceName(r.source) == request.source);
}

LearningHistoryResult queryHistory(const app::LearningDatabase& db, const LearningHistoryRequest& request) {
  LearningHistoryResult result;
  std::vector<app::LearningRecord> records;
  if (request.mrr_lo && request.mrr_hi) {
    records = db.withMrrIn(*request.mrr_lo, *request.mrr_hi, request.limit);
  } else {
    app::LearningHistoryQuery query;
    if (!request.tool.isEmpty()) query.tool = request.tool;
    if (!request.material.isEmpty()) query.material = request.material;
    if (!request.machine.isEmpty()) query.machine = request.machine;
    query.limit = request.limit;
    records = db.history(query);
  }
  for (app::LearningRecord& r : records)
    if (matches(request, r)) result.records.push_back(std::move(r));
  result.tools = db.facetValues(app::LearningFacet::Tool);
  result.materials = db.facetValues(app::LearningFacet::Material);
  result.machines = db.facetValues(app::LearningFacet::Machine);
  for (QStringList* choices : {&result.tools, &result.materials, &result.machines}) choices->sort();
  result.total = db.count();
  result.location = db.location();
  return result;
}

}  // namespace

LearningWorker::LearningWorker(QObject* parent) : QObject(parent) {}

LearningWorker::~LearningWorker() = default;

app::LearningDatabase& LearningWorker::database(const QString& location) {
  if (!db_ || location_ != location) {
    db_.reset();
    db_ = std::make_unique<app::LearningDatabase>(location);
    location_ = location;
  }
  return *db_;
}

void LearningWorker::record(quint64 generation, const QString& location, const app::LearningRecord& record) {
  try {
    app::LearningDatabase& db = database(location);
    const qint64 id = db.insert(record);
    const std::lock_guard hand_over(handOverMutex());  // the queued copy is read on the GUI thread
    emit recorded(generation, id, db.location());
  } catch (const std::exception& e) {
    db_.reset();  // the next request connects again
    const std::lock_guard hand_over(handOverMutex());
    emit recordFailed(generation, QString::fromStdString(e.what()));
  }
}

void LearningWorker::loadHistory(quint64 generation, const QString& location, const LearningHistoryRequest& request) {
  try {
    const LearningHistoryResult result = queryHistory(database(location), request);
    const std::lock_guard hand_over(handOverMutex());
    emit historyLoaded(generation, result);
  } catch (const std::exception& e) {
    db_.reset();
    const std::lock_guard hand_over(handOverMutex());
    emit historyFailed(generation, QString::fromStdString(e.what()));
  }
}

void LearningWorker::close() {
  db_.reset();
}

LearningConnectionReport testLearningConnection(const QString& location) {
  try {
    const app::LearningLocation where = app::parseLearningLocation(location);
    if (where.backend == app::LearningBackend::Sqlite && !QFileInfo::exists(where.file))
      return {true, QObject::tr("No file yet at %1: it is created with the first recorded point").arg(where.file)};
    const app::LearningDatabase db(location, app::LearningDatabase::OpenMode::ExistingOnly);
    return {true, QObject::tr("Connected to %1: schema %2, %3 records")
                      .arg(db.location())
                      .arg(db.schemaVersion())
                      .arg(groupedCount(db.count()))};
  } catch (const std::exception& e) {
    return {false, QString::fromStdString(e.what())};
  }
}

}  // namespace mx::gui
