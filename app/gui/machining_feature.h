#pragma once
// The machining docks: surface-finish control (the SDNRP loop of Cus & Zuperl) and part-program
// overrides (a G-code program re-fed by the project's force controller). Both run on the engine
// thread; the panels only show their results. Exports are atomic (QSaveFile).
#include <QMainWindow>
#include <QThreadPool>
#include <memory>

#include "document/project_document.h"
#include "engine_channel.h"
#include "feature_context.h"
#include "sdnrp/sdnrp_simulator.h"
#include "services/afc_request.h"
#include "services/part_program_request.h"
#include "window_feature.h"

namespace mx::widgets {
class NoticeStack;
class PartProgramPanel;
class SurfaceFinishPanel;
}  // namespace mx::widgets

namespace mx::gui {

class MachiningFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds "surfaceFinishDock" and "partProgramDock" to `window`, tabbed with the control dock.
  MachiningFeature(QMainWindow* window, const FeatureContext& context);

  // The panel takes sdnrp.ra_um, disturbance and duration; an open program is overridden again when
  // the inputs of its controllers changed.
  void projectChanged(const app::Project& project, Features recompute) override;
  // SDNRP with the panel's Ra, disturbance, duration; with "Compare" also the same run without SDNRP
  // (SdnrpSettings::control = false), both in one engine task.
  void runSurfaceFinish();
  // Reads the program (in the panel's dialect, or the detected one) and overrides it with the project's
  // controller, both on the engine thread; a Heidenhain program also gets its AFC setting there.
  void openPartProgram(const QString& path);
  bool exportPartProgram(const QString& path);     // the optimised program
  bool exportPartProgramCsv(const QString& path);  // the per-block feed-override table
  bool exportAfcTable(const QString& path);        // Heidenhain: the AFC.TAB row of the tool
  widgets::SurfaceFinishPanel* surfacePanel() const { return surface_panel_; }
  widgets::NoticeStack* surfaceNotice() const { return surface_notice_; }
  widgets::PartProgramPanel* programPanel() const { return program_panel_; }

 signals:
  void surfaceFinishShown();  // an SDNRP run (and its baseline without SDNRP, when compared) arrived
  void partProgramShown();    // an override of the opened program arrived

 private:
  void addDocks();
  void connectPanels();
  void showSurfaceFinish(const SdnrpResult& result, const SdnrpResult* baseline);
  void addSdnrpSection();
  struct ProgramOverride;
  void showOverride(const QString& path, ProgramOverride outcome);

  QMainWindow* window_;
  const app::ProjectDocument& document_;
  QThreadPool* pool_;
  const widgets::DisplayUnits* units_ = nullptr;
  EngineChannel channel_;
  widgets::SurfaceFinishPanel* surface_panel_;
  widgets::NoticeStack* surface_notice_;  // the panel, or that the project has no sdnrp section
  widgets::PartProgramPanel* program_panel_;
  quint64 sdnrp_generation_ = 0, override_generation_ = 0;
  std::shared_ptr<const app::OverrideOutcome> override_;
  std::optional<app::AfcOutcome> afc_;
  QString afc_error_;  // why a Heidenhain program has no AFC setting (no operating_point, ...)
  QString override_path_;
};

}  // namespace mx::gui
