#pragma once
// The batch-study picture: File > Batch study over the open project, its two tools and three
// materials, run here by the real millexpert-cli, with its merged table shown.
class QDialog;
class QString;

namespace mx::gui {
class MainWindow;
}

namespace mx::e2e {

// The dialog after its run ended and its table is shown; the manifest and results go to `folder`.
QDialog* batchStudyDialog(gui::MainWindow& window, const QString& folder, int timeout_ms);

}  // namespace mx::e2e
