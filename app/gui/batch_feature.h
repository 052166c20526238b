#pragma once
// File > Batch study (docs/shop-scale.md, "In the GUI"): writes a manifest from the open project, its
// tools, the material library and the machines of other project files (read on the engine pool; the
// project's snapshot beside the manifest), runs it here as a
// `millexpert-cli batch` child process (never the GUI thread; progress from the results file, Cancel
// kills it and a new run resumes by case hash), and shows a merged results file as a table (the merge
// runs on the engine pool).
#include <QElapsedTimer>
#include <QMainWindow>
#include <QPointer>
#include <QProcess>
#include <QTimer>

#include "engine_channel.h"
#include "feature_context.h"
#include "services/batch_study.h"
#include "window_feature.h"

namespace mx::widgets {
class BatchStudyDialog;
struct BatchStudySettings;
}  // namespace mx::widgets

namespace mx::gui {

class BatchFeature : public WindowFeature {
  Q_OBJECT
 public:
  BatchFeature(QMainWindow* window, FeatureContext& context);
  ~BatchFeature() override;

  void projectChanged(const app::Project& project, Features recompute) override;
  void stop() override;  // cancels a run
  void addFileActions(QMenu* file, QToolBar* toolbar) override;

  widgets::BatchStudyDialog* openDialog();  // filled from the current project
  // millexpert-cli; default: beside this program (installed) or one folder up (the build tree).
  void setCliProgram(const QString& path) { cli_program_ = path; }
  QString cliProgram() const;

  // Writes the study (manifest and project snapshot); false, with the error shown, when it cannot.
  bool saveStudy(const widgets::BatchStudySettings& settings, const QString& manifest_path);
  // Writes the study and runs it here into batchStudyResultsPath(manifest_path).
  bool runStudy(const widgets::BatchStudySettings& settings, const QString& manifest_path);
  void cancelRun();
  bool running() const { return process_ != nullptr; }
  // Merges the results files on the engine pool and shows the table.
  void showResults(const QStringList& files);
  // Reads the machine sections of project files on the engine pool and lists them in the dialog.
  void addMachinesFrom(const QStringList& files);

 signals:
  void runFinished(int exit_code, bool cancelled);
  void resultsShown(int rows);
  void machinesAdded(int count);  // how many new machines the files gave

 private:
  app::BatchStudyRequest requestOf(const widgets::BatchStudySettings& settings) const;
  void pollProgress();
  void onProcessFinished(int exit_code, QProcess::ExitStatus status);
  void askToSave(const widgets::BatchStudySettings& settings);
  void askToRun(const widgets::BatchStudySettings& settings);
  void askForResults();
  void askForMachines();
  QString machineLabel(const app::MachineSpec& machine, const QString& origin) const;
  std::vector<app::MachineSpec> checkedMachines(const QStringList& labels) const;
  struct ListedMachine;
  const ListedMachine* listedMachine(const QString& label) const;  // nullptr when not listed
  void listProjectMachine();

  FeatureContext& context_;
  QWidget* window_;
  EngineChannel channel_;
  QPointer<widgets::BatchStudyDialog> dialog_;
  QString cli_program_;
  QString manifest_path_;  // of the last study saved or run
  QProcess* process_ = nullptr;
  QTimer poll_;
  QString results_path_;
  qint64 results_offset_ = 0;  // bytes of the results file counted so far
  qint64 done_ = 0, total_ = 0;
  bool cancelled_ = false;
  quint64 merge_generation_ = 0;
  // What the dialog's machine list shows: the project's own first (no section: nullopt), then the
  // machines read from other project files.
  struct ListedMachine {
    QString label;
    std::optional<app::MachineSpec> machine;
  };
  std::vector<ListedMachine> machines_;
};

}  // namespace mx::gui
