#include "tool_library_transfer.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>

#include "count_text.h"
#include "engine_task.h"
#include "tool_import_dialog.h"

namespace mx::gui {

namespace {

struct FilterFormat {
  const char* filter;
  std::optional<app::ToolLibraryFormat> format;  // nullopt: guessed from the file
};

const FilterFormat kImportFilters[] = {
    {"Tool libraries (*.json *.tools *.fctl *.fctb *.tbl *.csv *.mxproj)", std::nullopt},
    {"Fusion 360 tool library (*.json *.tools)", app::ToolLibraryFormat::Fusion},
    {"FreeCAD tool library or bit (*.fctl *.fctb)", app::ToolLibraryFormat::FreeCad},
    {"LinuxCNC tool table (*.tbl)", app::ToolLibraryFormat::LinuxCnc},
    {"MillExpert CSV (*.csv)", app::ToolLibraryFormat::Csv},
    {"MillExpert JSON or project (*.json *.mxproj)", app::ToolLibraryFormat::Json},
};

const FilterFormat kExportFilters[] = {
    {"Fusion 360 tool library, zipped (*.tools)", app::ToolLibraryFormat::Fusion},
    {"Fusion 360 tool library, JSON (*.json)", app::ToolLibraryFormat::Fusion},
    {"FreeCAD tool library (a folder)", app::ToolLibraryFormat::FreeCad},
    {"LinuxCNC tool table (*.tbl)", app::ToolLibraryFormat::LinuxCnc},
    {"MillExpert CSV (*.csv)", app::ToolLibraryFormat::Csv},
    {"MillExpert JSON (*.json)", app::ToolLibraryFormat::Json},
};

template <std::size_t N>
QString filterList(const FilterFormat (&filters)[N]) {
  QStringList list;
  for (const FilterFormat& f : filters) list << QString::fromUtf8(f.filter);
  return list.join(";;");
}

template <std::size_t N>
std::optional<app::ToolLibraryFormat> formatOfFilter(const FilterFormat (&filters)[N], const QString& chosen) {
  for (const FilterFormat& f : filters)
    if (chosen == QString::fromUtf8(f.filter)) return f.format;
  return std::nullopt;
}

QString renamedText(const std::vector<app::RenamedTool>& renamed) {
  QStringList parts;
  for (const app::RenamedTool& r : renamed) parts << QString("%1 → %2").arg(r.from, r.to);
  return parts.join(", ");
}

QString summaryText(const QString& file, const app::LibraryMerge& merge, const app::ImportedLibrary& library) {
  QString text = QObject::tr("%1 from %2").arg(widgets::countText(merge.ids.size(), "tool", "tools"), file);
  if (!merge.renamed.empty()) text += QObject::tr("; renamed: %1").arg(renamedText(merge.renamed));
  if (!library.skipped.empty())
    text += QObject::tr("; %1 left out (not milling cutters)").arg(qsizetype(library.skipped.size()));
  return text;
}

// The reason an import needs a flute count the file does not give (LinuxCNC, FreeCAD bits).
bool needsTeeth(const QString& error) {
  return error.contains("flute", Qt::CaseInsensitive);
}

}  // namespace

ToolLibraryTransfer::ToolLibraryTransfer(FeatureContext& context, QWidget* dialogParent)
    : QObject(dialogParent), context_(context), dialog_parent_(dialogParent), channel_(this) {
  setObjectName("toolLibraryTransfer");
  connect(this, &ToolLibraryTransfer::importFinished, this, &ToolLibraryTransfer::showOutcome);
}

void ToolLibraryTransfer::importFile(const QString& path, std::optional<app::ToolLibraryFormat> format,
                                     const app::ToolImportOptions& options, const Chooser& choose) {
  const quint64 generation = ++generation_;
  running_ = true;
  runEngineTask<app::ImportedLibrary>(
      channel_, context_.enginePool(),
      [path, format, options] {
        return app::readToolLibrary(path, format ? *format : app::guessImportFormat(path), options);
      },
      [this, generation, path, choose](TaskResult<app::ImportedLibrary> r) {
        if (generation != generation_) return;
        running_ = false;
        if (!r.value) return fail(r.error);
        onLibraryRead(path, *r.value, choose);
      });
}

void ToolLibraryTransfer::onLibraryRead(const QString& path, const app::ImportedLibrary& library,
                                        const Chooser& choose) {
  const QString file = QFileInfo(path).fileName();
  if (library.tools.empty()) return fail(tr("%1 holds no milling tools").arg(file));
  const std::optional<Choice> choice = choose ? choose(file, library) : askChoice(file, library);
  if (!choice) return fail(tr("cancelled"));
  try {
    const app::ImportedLibrary chosen = choice->ids.isEmpty() ? library : app::selectTools(library, choice->ids, file);
    const app::LibraryMerge merge = app::mergeImportedTools(context_.project(), chosen.tools, choice->replace);
    emit editRequested(merge.project, choice->replace ? tr("Replace the tool library from %1").arg(file)
                                                      : tr("Add tools from %1").arg(file));
    emit importFinished({}, summaryText(file, merge, library));
  } catch (const app::ProjectError& e) {
    fail(QString::fromStdString(e.what()));
  }
}

std::optional<ToolLibraryTransfer::Choice> ToolLibraryTransfer::askChoice(const QString& file,
                                                                          const app::ImportedLibrary& library) const {
  QStringList skipped;
  for (const app::SkippedTool& s : library.skipped) skipped << QString("%1: %2").arg(s.name, s.reason);
  widgets::ToolImportDialog dialog(file, library.tools, skipped, int(context_.project().tools.size()), context_.units(),
                                   dialog_parent_);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  return Choice{dialog.selectedIds(), dialog.replace()};
}

void ToolLibraryTransfer::fail(const QString& error) {
  emit importFinished(error, {});
}

QString ToolLibraryTransfer::exportFile(const QString& path, app::ToolLibraryFormat format) const {
  try {
    app::writeToolLibrary(context_.project().tools, path, format);
  } catch (const app::ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void ToolLibraryTransfer::chooseImport() {
  QString chosenFilter;
  const QString path = QFileDialog::getOpenFileName(dialog_parent_, tr("Import tool library"), {},
                                                    filterList(kImportFilters), &chosenFilter);
  if (path.isEmpty()) return;
  interactive_ = Interactive{path, formatOfFilter(kImportFilters, chosenFilter), false};
  importFile(path, interactive_->format, {});
}

// The interactive import's end: a status message, or the refusal in a message box; a missing flute
// count is asked for once, and the file read again with it.
void ToolLibraryTransfer::showOutcome(const QString& error, const QString& summary) {
  if (!interactive_) return;
  Interactive run = *interactive_;
  interactive_.reset();
  if (error.isEmpty()) {
    emit statusMessage(tr("Imported %1").arg(summary));
    return;
  }
  if (error == tr("cancelled")) return;
  if (needsTeeth(error) && !run.askedTeeth) {
    bool ok = false;
    const int teeth = QInputDialog::getInt(
        dialog_parent_, tr("Flute count"),
        tr("%1\n\nImport the tools that give no flute count with this many teeth:").arg(error), 4, 1, 100, 1, &ok);
    if (ok) {
      run.askedTeeth = true;
      interactive_ = run;
      return importFile(run.path, run.format, app::ToolImportOptions{teeth});
    }
  }
  QMessageBox::warning(dialog_parent_, tr("Import refused, the library is unchanged"), error);
}

void ToolLibraryTransfer::chooseExport() {
  QString chosenFilter;
  QString path = QFileDialog::getSaveFileName(dialog_parent_, tr("Export tool library"), {}, filterList(kExportFilters),
                                              &chosenFilter);
  if (path.isEmpty()) return;
  const std::optional<app::ToolLibraryFormat> format = formatOfFilter(kExportFilters, chosenFilter);
  if (!format) return;
  if (*format == app::ToolLibraryFormat::FreeCad) {
    path = QFileDialog::getExistingDirectory(dialog_parent_, tr("Folder for the FreeCAD library"),
                                             QFileInfo(path).absolutePath());
    if (path.isEmpty()) return;
  }
  const QString error = exportFile(path, *format);
  if (!error.isEmpty()) {
    QMessageBox::warning(dialog_parent_, tr("Export failed"), error);
  } else {
    emit statusMessage(tr("Exported %1 to %2")
                           .arg(widgets::countText(qsizetype(context_.project().tools.size()), "tool", "tools"), path));
  }
}

}  // namespace mx::gui
