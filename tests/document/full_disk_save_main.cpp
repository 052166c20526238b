// Test-only helper for document.save_faults, the full disk: loads PROJECT into a ProjectDocument, applies
// variant 0 (tests/support/crash_variants.h) and writes its autosave, applies variant 1, then lowers the
// file-size limit (RLIMIT_FSIZE) to LIMIT bytes with SIGXFSZ ignored, so that a write past it fails with
// EFBIG as one on a full disk fails with ENOSPC, and tries to save and to autosave. A process of its
// own, because the limit holds for every file the process writes. Prints one JSON object:
// {"save_error", "autosave_error", "dirty"}.
//   full_disk_save PROJECT LIMIT_BYTES
#include <sys/resource.h>

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <clocale>
#include <csignal>
#include <exception>
#include <stdexcept>

#include "document/project_document.h"
#include "support/crash_variants.h"

namespace {

void limitFileSize(rlim_t bytes) {
  std::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead of killing the process
  rlimit limit{};
  getrlimit(RLIMIT_FSIZE, &limit);
  limit.rlim_cur = bytes;
  if (setrlimit(RLIMIT_FSIZE, &limit) != 0) throw std::runtime_error("setrlimit(RLIMIT_FSIZE) failed");
}

void applyVariant(mx::app::ProjectDocument& doc, int k) {
  const QString refused = doc.applyEdit(mx::test::crashVariant(doc.project(), k), "crash-safety variant");
  if (!refused.isEmpty()) throw mx::app::ProjectError(refused);
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_ALL, "C");
  const QStringList args = QCoreApplication::arguments();
  if (args.size() != 3) {
    QTextStream(stderr) << "usage: full_disk_save PROJECT LIMIT_BYTES\n";
    return 2;
  }
  try {
    mx::app::ProjectDocument doc;
    doc.setAutosaveInterval(0);
    doc.load(args[1]);
    applyVariant(doc, 0);
    const QString first_autosave = doc.writeAutosave();
    if (!first_autosave.isEmpty()) throw mx::app::ProjectError(first_autosave);
    applyVariant(doc, 1);
    limitFileSize(args[2].toULongLong());
    QString save_error;
    try {
      doc.save();
    } catch (const mx::app::ProjectError& e) {
      save_error = QString::fromStdString(e.what());
    }
    const QString autosave_error = doc.writeAutosave();
    QTextStream(stdout) << QJsonDocument(QJsonObject{{"save_error", save_error},
                                                     {"autosave_error", autosave_error},
                                                     {"dirty", doc.isDirty()}})
                               .toJson(QJsonDocument::Compact)
                        << Qt::endl;
  } catch (const std::exception& e) {
    QTextStream(stderr) << e.what() << Qt::endl;
    return 1;
  }
  return 0;
}
