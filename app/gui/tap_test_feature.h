#pragma once
// The tap-test view (the "tapTestDock"): File > Import tap test reads a UFF 58/58b or CSV file on the
// engine thread and shows its x and y receptance; the fit (LSCF stabilisation diagram, or peak picking,
// or the poles clicked on the diagram) runs on the engine thread with progress and cancel; Accept
// writes the fitted modes and the FRF reference into the active tool as one undoable edit.
// File > Export FRF writes the active tool's measured or fitted FRF. The active tool's own FRFs are
// shown when the project is loaded.
#include <QMainWindow>
#include <map>
#include <optional>

#include "engine_channel.h"
#include "feature_context.h"
#include "frf/receptance_conversion.h"
#include "tap_test_runner.h"
#include "window_feature.h"

namespace mx::widgets {
class TapTestPanel;
struct TapTestFitRequest;
}  // namespace mx::widgets

namespace mx::gui {

class TapTestFeature : public WindowFeature {
  Q_OBJECT
 public:
  TapTestFeature(QMainWindow* window, FeatureContext& context);

  void projectChanged(const app::Project& project, Features recompute) override;
  void projectReplaced() override;
  void stop() override;
  void addFileActions(QMenu* file, QToolBar* toolbar) override;

  // Reads `path` for `direction` ("x" or "y"); the dataset is the first whose response is that
  // direction (or `dataset` when given). For tests and the import dialog.
  void importFile(const QString& path, const QString& direction, std::optional<int> dataset,
                  std::optional<FrfQuantity> quantity);
  // The accepted tool edit for `direction` (what Accept applies), or the reason it cannot be made.
  std::optional<app::Project> acceptedProject(const QString& direction, QString* why) const;
  // File > Import tap test: the file, the direction (and a CSV's quantity) asked, then importFile.
  void chooseImport();
  widgets::TapTestPanel* panel() const { return panel_; }
  TapTestRunner* runner() const { return runner_; }

 signals:
  void measurementShown(const QString& direction);
  void fitShown(const QString& direction);

 private:
  struct Measurement {
    QString path;  // absolute
    int dataset = 0;
    std::optional<FrfQuantity> quantity;  // as given by the user (CSV) or the file's (UFF)
    Receptance receptance;
    std::optional<ModalFitResult> fit;
  };
  struct PendingImport {
    QString direction;
    QString path;  // absolute
    std::optional<int> dataset;
  };

  void exportFrf();
  void onLoaded(quint64 generation, const TapTestFile& file);
  void onFitted(quint64 generation, const TapTestFit& fit);
  void onFitRequested(const widgets::TapTestFitRequest& request);
  void accept(const QString& direction);
  void showToolFrfs();
  QString relativeToProject(const QString& absolute) const;

  QMainWindow* window_;
  FeatureContext& context_;
  TapTestRunner* runner_;
  widgets::TapTestPanel* panel_;
  std::map<QString, Measurement> measurements_;
  std::map<quint64, PendingImport> pending_;
  EngineChannel export_channel_{this};
  quint64 fit_generation_ = 0;
};

}  // namespace mx::gui
