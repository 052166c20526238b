#pragma once
// The force-control dock (2006 paper, section 4): the project's "control" section drives the adaptive
// beta-FROH closed loop on the engine thread; the view's beta slider, controller settings and workpiece
// editors are undoable edits of that section (one per slider drag). A change of its inputs re-runs the
// closed loop; a change other than beta also re-runs the J_c(beta) sweep.
#include <QMainWindow>
#include <QThreadPool>
#include <functional>
#include <optional>

#include "document/project_document.h"
#include "feature_context.h"
#include "services/control_request.h"
#include "window_feature.h"

namespace mx::widgets {
class ControlView;
}

namespace mx::gui {

class ControlRunner;

class ControlFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds the "controlDock" to `window`, tabbed with the history dock when there is one.
  ControlFeature(QMainWindow* window, const FeatureContext& context);

  void projectChanged(const app::Project& project, Features recompute) override;
  void stop() override;
  widgets::ControlView* view() const { return view_; }
  ControlRunner* runner() const { return runner_; }

 signals:
  void controlShown();       // a closed-loop run arrived
  void controlSweepShown();  // the J_c(beta) sweep arrived

 private:
  void connectView();
  void connectRunner();
  void disable(const QString& status);
  void startSweep();
  void editSection(const std::function<void(app::ControlRequest&)>& change, const QString& what, int gesture = 0);

  const app::ProjectDocument& document_;
  ControlRunner* runner_;
  widgets::ControlView* view_;
  std::optional<app::ControlRequest> request_;
};

}  // namespace mx::gui
