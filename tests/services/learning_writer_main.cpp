// Test-only helper for services.learning_crash_safety: opens DB_FILE, prints "ready", then inserts
// learning records in a loop (each one transaction), printing "begin i" before and "end i" after each
// insert, until killed or COUNT inserts are done. The writer index i (also stored in the objectives as
// "writer_index") continues from the rows already in the file, so over many runs it counts 0, 1, 2...
//   learning_writer DB_FILE [COUNT]
#include <QCoreApplication>
#include <QTextStream>
#include <clocale>
#include <exception>

#include "services/learning_database.h"

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_ALL, "C");
  const QStringList args = QCoreApplication::arguments();
  if (args.size() < 2) {
    QTextStream(stderr) << "usage: learning_writer DB_FILE [COUNT]\n";
    return 2;
  }
  const long long limit = args.size() > 2 ? args.at(2).toLongLong() : -1;
  QTextStream out(stdout);
  try {
    mx::app::LearningDatabase db(args.at(1));
    const long long first = db.count();
    out << "ready" << Qt::endl;  // flushed: the test times its kills from here
    for (long long i = first; limit < 0 || i < first + limit; ++i) {
      mx::app::LearningRecord r;
      r.weights = {0.1, 0.2, 0.3, 0.4};
      r.tool = {QString("W%1").arg(i % 5), 8.0 + static_cast<double>(i % 5), 2 + static_cast<int>(i % 3)};
      r.material = "Aluminium";
      r.machine = {2745.3, 12000.0};
      r.q = {1000.0 + static_cast<double>(i), 1.0, 0.1};
      r.objectives = QJsonObject{{"tol", 10.0},
                                 {"mrr_cm3_s", 0.001 * static_cast<double>(i)},
                                 {"surf", 1.5},
                                 {"ros", 0.5},
                                 {"writer_index", static_cast<double>(i)}};
      r.source = mx::app::LearningSource::Automatic;
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
