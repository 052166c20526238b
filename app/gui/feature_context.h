#pragma once
// What the features of the main window share: the document (read-only), the display units, the
// engine thread's pool, the active tool, the readout of the operating point, and the events one
// feature raises for the others (a simulation request, a finished simulation, a rebuilt chart).
// The window owns it; features never reach each other directly.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <memory>
#include <optional>

#include "display_units.h"
#include "document/project_document.h"
#include "point_evaluator.h"
#include "point_readout.h"
#include "simulation_data.h"

namespace mx::gui {

class FeatureContext : public QObject {
  Q_OBJECT
 public:
  FeatureContext(const app::ProjectDocument& document, widgets::DisplayUnits& units, QThreadPool* engine_pool,
                 QObject* parent);

  const app::ProjectDocument& document() const { return document_; }
  const app::Project& project() const { return document_.project(); }
  const app::PickedPoint& point() const { return document_.point(); }
  widgets::DisplayUnits* units() const { return &units_; }
  QThreadPool* enginePool() const { return engine_pool_; }

  // The tool of the readouts, the shading, the markers and the simulation.
  const QString& activeTool() const { return active_tool_; }
  void setActiveTool(const QString& id);  // "" is ignored; emits activeToolChanged when it changes
  // The point a feature placed by default (the lobes' first guess, then q*); a better default may
  // replace the point while it is still there, i.e. until the user moves it. nullopt: none placed.
  void setDefaultPoint(const std::optional<app::PickedPoint>& point) { default_point_ = point; }
  bool pointIsDefault() const;  // no point yet, or the current one is the default placed
  // The readout of the operating point (power, MRR, stability) for the active tool.
  const widgets::PointReadout& readout() const { return readout_; }
  void setReadout(const widgets::PointReadout& readout);

  // The time-domain simulation: what runs or last ran, for which tool and point. A result counts only
  // for the active tool at the current point; a new run or a project edit replaces it.
  void setSimulationRunning(const QString& tool, const app::PickedPoint& point);
  void setSimulationResult(const SimulationSummary& summary);  // of the running tool and point
  void clearSimulation();                                      // none runs, none is current
  widgets::SimulationCheck simulationCheck() const;            // for the active tool and current point
  const SimulationSummary* currentSimulation() const;          // null unless Done for the current point

  // The lobes' evaluator of the chart (never null; not ready before the first lobes).
  const std::shared_ptr<const PointEvaluator>& evaluator() const { return evaluator_; }
  void setEvaluator(std::shared_ptr<const PointEvaluator> evaluator) { evaluator_ = std::move(evaluator); }

 signals:
  void activeToolChanged(const QString& id);
  void readoutChanged(const mx::widgets::PointReadout& readout);
  void lobesShown();           // the chart was rebuilt (its markers and overlays are gone)
  void simulationRequested();  // simulate the operating point of the active tool
  void simulationFinished(const mx::gui::SimulationSummary& summary);
  void simulationStateChanged();  // started, finished or cleared
  // Chatter reported at the operating point while the 2006 ranking is the active study (Rule 6).
  void rankingChatterReported(double chatter_hz);

 private:
  const app::ProjectDocument& document_;
  widgets::DisplayUnits& units_;
  QThreadPool* engine_pool_;
  bool simulatesCurrentPoint() const;

  QString active_tool_;
  std::optional<app::PickedPoint> default_point_;
  widgets::PointReadout readout_;
  QString simulated_tool_;
  app::PickedPoint simulated_point_;
  bool simulation_running_ = false;
  std::optional<SimulationSummary> simulation_;
  std::shared_ptr<const PointEvaluator> evaluator_ = std::make_shared<PointEvaluator>();
};

}  // namespace mx::gui
