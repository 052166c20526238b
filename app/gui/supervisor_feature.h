#pragma once
// The supervisor dock (Landers & Ulsoy): the project's "supervisor" section gives the scenario and the
// Grafcet chart of each controller; the chart is drawn and edited (each valid edit is an undoable
// project edit); a run streams F_Y, power, the active steps (tokens), module activity and events from
// the engine thread, paced so that the operator's feed hold and chatter buttons act on it; Compare
// runs none, SMC I and SMC II side by side. A shown run or comparison re-runs when its inputs change.
// Module L's settings (supervisor.model_controller) are edited in the view, one undoable edit each.
#include <QMainWindow>
#include <QThreadPool>
#include <functional>
#include <optional>
#include <vector>

#include "document/project_document.h"
#include "feature_context.h"
#include "services/supervisor_request.h"
#include "window_feature.h"

namespace mx::widgets {
class SupervisorView;
}

namespace mx::gui {

class SupervisionRunner;
struct SupervisionChunk;
struct SupervisionOutcome;

class SupervisorFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds the "supervisorDock" to `window`, tabbed with the part-program dock when there is one.
  SupervisorFeature(QMainWindow* window, const FeatureContext& context);

  void projectChanged(const app::Project& project, Features recompute) override;
  void projectReplaced() override { shown_ = Shown::None; }
  void stop() override;
  void start();    // live run of the view's controller (paced, operator buttons active)
  void compare();  // none, SMC I and SMC II side by side
  widgets::SupervisorView* view() const { return view_; }
  SupervisionRunner* runner() const { return runner_; }
  // The scenario and chart of the view's controller, as the next run takes them; none when invalid.
  const std::optional<app::SupervisorRequest>& request() const { return request_; }

 signals:
  void supervisionFinished();                        // a live run ended
  void comparisonResult(const QString& controller);  // one controller of a comparison arrived

 private:
  void connectView();
  void connectRunner();
  void refresh(const app::Project& project);  // the request and chart of the view's controller
  void onChunk(const SupervisionChunk& chunk);
  void onFinished(const SupervisionOutcome& outcome);
  void onCompared(const SupervisionOutcome& outcome);
  void requestChartEdit(const QString& controller, const GrafcetChart& chart);
  void showModelController(const app::SupervisorSection& section);
  void editModelController(const std::function<void(app::SupervisorModelControllerSpec&)>& change,
                           const QString& description);

  enum class Shown { None, Run, Comparison };
  const app::ProjectDocument& document_;
  const widgets::DisplayUnits* units_ = nullptr;
  SupervisionRunner* runner_;
  widgets::SupervisorView* view_;
  std::optional<app::SupervisorRequest> request_;
  std::vector<ModuleActivityRecord> live_modules_;
  Shown shown_ = Shown::None;
};

}  // namespace mx::gui
