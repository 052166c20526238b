// MainWindow: new, open (with autosave recovery), save, save as, title and dirty marker.
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStatusBar>

#include "feature_context.h"
#include "main_window.h"
#include "window_feature.h"

namespace mx::gui {

bool MainWindow::openProject(const QString& path) {
  try {
    const QString autosave = app::ProjectDocument::recoveryCandidate(path);
    bool recover = false;
    if (!autosave.isEmpty()) {
      if (recovery_ == RecoveryPolicy::Ask && !quiet_) {
        recover = QMessageBox::question(this, tr("Recover unsaved changes?"),
                                        tr("An autosave of %1 is newer than the file (MillExpert did not close "
                                           "normally). Recover the unsaved changes?")
                                            .arg(QFileInfo(path).fileName())) == QMessageBox::Yes;
      } else {
        recover = recovery_ == RecoveryPolicy::Recover;
      }
    }
    // Read first: a file refused (malformed, over 64 MB, a FIFO) leaves the open project, its point and
    // the views as they are.
    app::loadProject(recover ? autosave : path);
    replaceProject();
    if (recover) {
      doc_.recover(path);
    } else {
      doc_.load(path);
      if (!autosave.isEmpty()) QFile::remove(autosave);
    }
  } catch (const app::ProjectError& e) {
    showError(tr("Cannot open project"), QString::fromStdString(e.what()));
    return false;
  }
  addRecentFile(path);
  return true;
}

bool MainWindow::saveProject(const QString& path) {
  try {
    doc_.save(path);
  } catch (const app::ProjectError& e) {
    showError(tr("Cannot save project"), QString::fromStdString(e.what()));
    return false;
  }
  addRecentFile(doc_.filePath());
  statusBar()->showMessage(tr("Saved %1").arg(doc_.filePath()), 5000);
  return true;
}

// Another project is about to be loaded: no point and no run of the new one is shown yet.
void MainWindow::replaceProject() {
  context_->setDefaultPoint(std::nullopt);
  doc_.initPoint({});
  for (WindowFeature* feature : features_) feature->projectReplaced();
}

void MainWindow::onNew() {
  if (!maybeSave()) return;
  replaceProject();
  doc_.newProject();
}

void MainWindow::onOpen() {
  if (!maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), QFileInfo(doc_.filePath()).path(),
                                                    tr("MillExpert projects (*.mxproj);;All files (*)"));
  if (!path.isEmpty()) openProject(path);
}

bool MainWindow::onSave() {
  return doc_.filePath().isEmpty() ? onSaveAs() : saveProject();
}

bool MainWindow::onSaveAs() {
  QString path =
      QFileDialog::getSaveFileName(this, tr("Save project as"), doc_.filePath(), tr("MillExpert projects (*.mxproj)"));
  if (path.isEmpty()) return false;
  if (!path.endsWith(".mxproj")) path += ".mxproj";
  return saveProject(path);
}

// true when it is fine to discard the document (saved, discarded, or clean).
bool MainWindow::maybeSave() {
  if (!doc_.isDirty() || quiet_) return true;
  const auto answer = QMessageBox::warning(this, tr("Unsaved changes"), tr("Save the changes to the project?"),
                                           QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save) return onSave();
  return answer == QMessageBox::Discard;
}

void MainWindow::updateTitle() {
  const QString file = doc_.filePath().isEmpty() ? tr("untitled") : QFileInfo(doc_.filePath()).fileName();
  setWindowTitle(QString("MillExpert \u2014 %1 [%2][*]").arg(doc_.project().name, file));
  setWindowModified(doc_.isDirty());
}

}  // namespace mx::gui
