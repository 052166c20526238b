#pragma once
// The tool library's files in the window (docs/tool-libraries.md): Import reads a Fusion 360, FreeCAD,
// LinuxCNC, CSV or JSON library on the engine thread, shows its tools to choose from, and merges the
// chosen ones into the project as one undoable edit; Export writes the project's tools in one of those
// formats. The same services as millexpert-cli library-import / library-export.
#include <QObject>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

#include "engine_channel.h"
#include "feature_context.h"
#include "services/tool_formats/tool_library_transfer.h"

class QWidget;

namespace mx::gui {

class ToolLibraryTransfer : public QObject {
  Q_OBJECT
 public:
  ToolLibraryTransfer(FeatureContext& context, QWidget* dialogParent);

  // What the user chose in the import dialog; the interactive path fills it from ToolImportDialog.
  struct Choice {
    QStringList ids;  // empty: every tool
    bool replace = false;
  };
  using Chooser = std::function<std::optional<Choice>(const QString& file, const app::ImportedLibrary& library)>;
  // Reads `path` on the engine thread, then asks `choose` (the dialog when null) and requests the
  // merged project. Ends with importFinished (error "" on success, or "cancelled").
  void importFile(const QString& path, std::optional<app::ToolLibraryFormat> format,
                  const app::ToolImportOptions& options, const Chooser& choose = {});
  // Writes the project's tools; "" or the reason.
  QString exportFile(const QString& path, app::ToolLibraryFormat format) const;
  bool importRunning() const { return running_; }

 public slots:
  void chooseImport();  // file dialog, then importFile
  void chooseExport();  // file (or folder for FreeCAD) dialog, then exportFile

 signals:
  void editRequested(const mx::app::Project& edited, const QString& description);
  // After every importFile: error is "" on success; summary says what was imported, renamed, skipped.
  void importFinished(const QString& error, const QString& summary);
  void statusMessage(const QString& text);  // after an interactive import or an export

 private:
  void onLibraryRead(const QString& path, const app::ImportedLibrary& library, const Chooser& choose);
  std::optional<Choice> askChoice(const QString& file, const app::ImportedLibrary& library) const;
  void fail(const QString& error);
  void showOutcome(const QString& error, const QString& summary);

  struct Interactive {
    QString path;
    std::optional<app::ToolLibraryFormat> format;
    bool askedTeeth = false;
  };
  std::optional<Interactive> interactive_;  // set while an import started from the dialog runs

  FeatureContext& context_;
  QWidget* dialog_parent_;
  EngineChannel channel_;
  quint64 generation_ = 0;
  bool running_ = false;
};

}  // namespace mx::gui
