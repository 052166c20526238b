// Test-only helper for document.crash_safety: loads PROJECT into a ProjectDocument, prints "ready", then
// in a loop applies variant k % 2 (tests/support/crash_variants.h) and writes it the way the GUI does,
// ProjectDocument::save (save) or ProjectDocument::writeAutosave (autosave), printing "begin k" before
// and "end k" after each write, until killed or COUNT writes are done.
//   document_writer save|autosave PROJECT [COUNT]
#include <QCoreApplication>
#include <QTextStream>
#include <clocale>
#include <exception>

#include "document/project_document.h"
#include "support/crash_variants.h"

namespace {

void writeOnce(mx::app::ProjectDocument& doc, bool autosave) {
  if (!autosave) {
    doc.save();
    return;
  }
  const QString error = doc.writeAutosave();
  if (!error.isEmpty()) throw mx::app::ProjectError(error);
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_ALL, "C");
  const QStringList args = QCoreApplication::arguments();
  if (args.size() < 3 || (args[1] != "save" && args[1] != "autosave")) {
    QTextStream(stderr) << "usage: document_writer save|autosave PROJECT [COUNT]\n";
    return 2;
  }
  const bool autosave = args[1] == "autosave";
  const long long limit = args.size() > 3 ? args[3].toLongLong() : -1;
  QTextStream out(stdout);
  try {
    mx::app::ProjectDocument doc;
    doc.setAutosaveInterval(0);  // the loop writes; no timer races it
    doc.load(args[2]);
    doc.undoStack()->setUndoLimit(4);  // an endless loop of edits in bounded memory
    out << "ready" << Qt::endl;        // flushed: the test times its kills from here
    for (long long k = 0; limit < 0 || k < limit; ++k) {
      const QString refused = doc.applyEdit(mx::test::crashVariant(doc.project(), k), "crash-safety variant");
      if (!refused.isEmpty()) throw mx::app::ProjectError(refused);
      out << "begin " << k << Qt::endl;
      writeOnce(doc, autosave);
      out << "end " << k << Qt::endl;
    }
  } catch (const std::exception& e) {
    QTextStream(stderr) << e.what() << Qt::endl;
    return 1;
  }
  return 0;
}
