// Test-only writer of the learning database, for services.learning_crash_safety and
// services.learning_concurrency:
//   learning_writer LOCATION [COUNT] [--machine NAME] [--batch]
// opens LOCATION (a file or a postgresql:// URL), prints "ready", then inserts learning records,
// printing "begin i" before and "end i" after each, until killed or COUNT inserts are done (each one
// transaction). The index i (also stored in the objectives as "writer_index") continues from the rows
// of the same machine already stored, so over many runs it counts 0, 1, 2... --machine names the
// records' machine (one writer per machine: its rows are its own). --batch inserts the COUNT records
// in ONE transaction instead, printing "begin batch" before and "end batch" after it.
#include <QCoreApplication>
#include <QTextStream>
#include <clocale>
#include <exception>

#include "services/learning_database.h"

namespace {

mx::app::LearningRecord recordNumber(long long i, const std::optional<QString>& machine) {
  mx::app::LearningRecord r;
  r.weights = {0.1, 0.2, 0.3, 0.4};
  r.tool = {QString("W%1").arg(i % 5), 8.0 + static_cast<double>(i % 5), 2 + static_cast<int>(i % 3)};
  r.material = "Aluminium";
  r.machine = {machine, 2745.3, 12000.0};
  r.q = {1000.0 + static_cast<double>(i), 1.0, 0.1};
  r.objectives = QJsonObject{{"tol", 10.0},
                             {"mrr_cm3_s", 0.001 * static_cast<double>(i)},
                             {"surf", 1.5},
                             {"ros", 0.5},
                             {"writer_index", static_cast<double>(i)}};
  r.source = mx::app::LearningSource::Automatic;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_ALL, "C");
  QStringList args = QCoreApplication::arguments();
  const bool batch = args.removeAll("--batch") > 0;
  std::optional<QString> machine;
  if (const qsizetype at = args.indexOf("--machine"); at > 0 && at + 1 < args.size()) {
    machine = args.at(at + 1);
    args.remove(at, 2);
  }
  if (args.size() < 2) {
    QTextStream(stderr) << "usage: learning_writer LOCATION [COUNT] [--machine NAME] [--batch]\n";
    return 2;
  }
  const long long limit = args.size() > 2 ? args.at(2).toLongLong() : -1;
  QTextStream out(stdout);
  try {
    mx::app::LearningDatabase db(args.at(1));
    mx::app::LearningHistoryQuery mine;
    mine.machine = machine;
    mine.limit = 0;
    const long long first = machine ? static_cast<long long>(db.history(mine).size()) : db.count();
    out << "ready" << Qt::endl;  // flushed: the test times its kills from here
    if (batch) {
      std::vector<mx::app::LearningRecord> records;
      for (long long i = first; i < first + limit; ++i) records.push_back(recordNumber(i, machine));
      out << "begin batch" << Qt::endl;
      db.insertAll(records);
      out << "end batch" << Qt::endl;
      return 0;
    }
    for (long long i = first; limit < 0 || i < first + limit; ++i) {
      const mx::app::LearningRecord r = recordNumber(i, machine);
      out << "begin " << i << Qt::endl;
      db.insert(r);
      out << "end " << i << Qt::endl;
    }
  } catch (const std::exception& e) {
    QTextStream(stderr) << e.what() << Qt::endl;
    return 1;
  }
  return 0;
}
