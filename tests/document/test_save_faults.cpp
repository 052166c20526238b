// Saves that cannot succeed (docs/reliability.md, "Crash safety"): a full disk (a file-size limit in a
// child process, full_disk_save), a read-only folder and a project file replaced by a directory. Each
// gives an error naming the file and the cause, and nothing is lost: the document stays dirty, the
// project file keeps its old bytes, the previous autosave survives and recovery offers it.
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <utility>

#include "document/project.h"
#include "document/project_document.h"
#include "support/crash_variants.h"
#include "support/project_files.h"
#include "support/read_only_folder.h"
#include "test_registry.h"

using namespace mx;

namespace {

const QString kProject = MX_PROJECTS_DIR "/library-20-tools.mxproj";

QString errorOfSave(app::ProjectDocument& doc) {
  try {
    doc.save();
  } catch (const app::ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestSaveFaults : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString folder_, path_, autosave_;
  QByteArray original_, autosaved_;

  // A document on folder/p.mxproj with variant 0 autosaved, then variant 1 applied (dirty, unsaved).
  void openEdited(app::ProjectDocument& doc) {
    doc.setAutosaveInterval(0);
    doc.load(path_);
    QCOMPARE(doc.applyEdit(test::crashVariant(doc.project(), 0), "variant 0"), QString());
    QCOMPARE(doc.writeAutosave(), QString());
    autosaved_ = test::readBytes(autosave_);
    QCOMPARE(doc.applyEdit(test::crashVariant(doc.project(), 1), "variant 1"), QString());
    QVERIFY(doc.isDirty());
  }

  // Nothing lost: the old project bytes, the autosave of variant 0 offered and recovered, no stray files.
  void verifyNothingLost(bool project_is_a_file = true) {
    if (project_is_a_file) QCOMPARE(test::readBytes(path_), original_);
    QCOMPARE(test::readBytes(autosave_), autosaved_);
    QStringList expected{"p.mxproj", "p.mxproj.autosave"};
    QCOMPARE(QDir(folder_).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot), expected);
    if (!project_is_a_file) return;
    QCOMPARE(app::ProjectDocument::recoveryCandidate(path_), autosave_);
    app::ProjectDocument recovered;
    recovered.setAutosaveInterval(0);
    recovered.recover(path_);
    QVERIFY(recovered.isDirty());
    QCOMPARE(recovered.project().name, test::crashVariant(app::loadProject(path_), 0).name);
  }

 private slots:
  void init() {
    folder_ = dir_.filePath(QTest::currentTestFunction());
    QVERIFY(QDir().mkpath(folder_));
    path_ = folder_ + "/p.mxproj";
    autosave_ = path_ + ".autosave";
    QVERIFY(QFile::copy(kProject, path_));
    QFile(path_).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    original_ = test::readBytes(path_);
  }

  void fullDisk() {
    {
      app::ProjectDocument doc;
      openEdited(doc);  // the autosave of variant 0, written here as the child's will be
    }
    QFile::remove(autosave_);
    QProcess child;  // the limit holds for the whole process: a child of its own
    child.start(MX_FULL_DISK_SAVE_PATH, {path_, "4096"});
    QVERIFY(child.waitForFinished(30000));
    QVERIFY2(child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0, child.readAllStandardError());
    const QJsonObject out = QJsonDocument::fromJson(child.readAllStandardOutput()).object();
    const QString save_error = out["save_error"].toString(), autosave_error = out["autosave_error"].toString();
    QVERIFY2(save_error.startsWith(path_ + ": cannot write project file: File too large"), qPrintable(save_error));
    QVERIFY2(autosave_error.startsWith(autosave_ + ": cannot write project file: File too large"),
             qPrintable(autosave_error));
    qInfo("full disk: %s | %s", qPrintable(save_error), qPrintable(autosave_error));
    QCOMPARE(out["dirty"].toBool(false), true);
    verifyNothingLost();
  }

  void readOnlyFolder() {
    app::ProjectDocument doc;
    openEdited(doc);
    QString save_error, autosave_error;
    {
      test::ReadOnlyFolder read_only(folder_);
      QVERIFY2(!read_only.writable(), "the folder is still writable: the test would prove nothing");
      if (read_only.asRoot()) qInfo("running as root: CAP_DAC_OVERRIDE dropped for this thread");
      save_error = errorOfSave(doc);
      autosave_error = doc.writeAutosave();
    }
    qInfo("read-only folder: %s | %s", qPrintable(save_error), qPrintable(autosave_error));
    // The folder check names it; as root, access() still says writable and the OS refuses the write.
    for (const auto& [error, file] : {std::pair{save_error, path_}, std::pair{autosave_error, autosave_}})
      QVERIFY2(error.startsWith(file + ": cannot write project file: ") &&
                   (error.contains("is not writable") || error.endsWith("Permission denied")),
               qPrintable(error));
    QVERIFY(doc.isDirty());
    verifyNothingLost();
  }

  void fileReplacedByADirectory() {
    app::ProjectDocument doc;
    openEdited(doc);
    QVERIFY(QFile::remove(path_) && QDir().mkpath(path_ + "/inside"));
    const QString error = errorOfSave(doc);
    qInfo("directory: %s", qPrintable(error));
    QVERIFY2(error.startsWith(path_ + ": cannot write project file: ") && error.contains("directory"),
             qPrintable(error));
    QVERIFY(doc.isDirty());
    QVERIFY(QFileInfo(path_ + "/inside").isDir());  // the directory and what it holds are untouched
    verifyNothingLost(false);
    doc.save(folder_ + "/elsewhere.mxproj");  // Save As elsewhere still works, and loses nothing
    QVERIFY(!doc.isDirty());
    QCOMPARE(app::loadProject(folder_ + "/elsewhere.mxproj").name, test::crashVariant(doc.project(), 1).name);
  }
};

MX_REGISTER_TEST(TestSaveFaults)
#include "test_save_faults.moc"
