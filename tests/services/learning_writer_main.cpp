// Test-only helper for services.learning_database: inserts learning records into DB_FILE in a loop (each
// one transaction) and prints the running count after every commit, until killed or COUNT reached.
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
    for (long long i = 0; limit < 0 || i < limit; ++i) {
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
      db.insert(r);
      out << (i + 1) << Qt::endl;  // flushed: the test waits for the first commit
    }
  } catch (const std::exception& e) {
    QTextStream(stderr) << e.what() << Qt::endl;
    return 1;
  }
  return 0;
}
