// MainWindow: the expert system (issue 4). The session (lobes and admissible grids of every tool) is
// built on the engine thread once per project change; a weight change re-ranks on the GUI thread
// from the session's caches (milliseconds); a committed weight change is an undoable project edit
// and re-runs Rules 5-6 (cached simulations) on the engine thread for q**.
#include <QDockWidget>
#include <QScrollArea>
#include <QStatusBar>

#include "expert_overlays.h"
#include "expert_runner.h"
#include "main_window.h"
#include "pareto_runner.h"
#include "ranking_table.h"
#include "services/expert_request.h"
#include "weights_panel.h"

namespace mx::gui {

CostWeights projectWeightsOf(const app::Project& p) {
  CostWeights w;
  if (!p.expert) return w;
  auto copy = [](const std::vector<double>& from, auto& to) {
    if (from.size() == to.size()) std::copy(from.begin(), from.end(), to.begin());
  };
  copy(p.expert->c, w.c);
  copy(p.expert->cr, w.cr);
  copy(p.expert->ct, w.ct);
  copy(p.expert->cf, w.cf);
  return w;
}

void MainWindow::buildExpertDocks() {
  expert_ = new ExpertRunner(engine_->pool(), this);
  weights_panel_ = new widgets::WeightsPanel(this);
  ranking_table_ = new widgets::RankingTable(this);
  ranking_table_->setUnits(&units_);
  // Weights share the right area with the operating point; the ranking shares the bottom with the
  // live simulation (tabs), so that the window fits 1920x1080.
  auto* weights = new QDockWidget(tr("Cost weights"), this);
  weights->setObjectName("weightsDock");
  auto* scroll = new QScrollArea;
  scroll->setWidget(weights_panel_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  weights->setWidget(scroll);
  auto* ranking = new QDockWidget(tr("Tool ranking"), this);
  ranking->setObjectName("rankingDock");
  ranking->setWidget(ranking_table_);
  addDockWidget(Qt::RightDockWidgetArea, weights);
  addDockWidget(Qt::BottomDockWidgetArea, ranking);
  if (auto* point = findChild<QDockWidget*>("pointDock")) tabifyDockWidget(point, weights);
  if (auto* simulation = findChild<QDockWidget*>("simulationDock")) {
    tabifyDockWidget(simulation, ranking);
    simulation->raise();
  }
  if (auto* point = findChild<QDockWidget*>("pointDock")) point->raise();
  connect(weights_panel_, &widgets::WeightsPanel::weightsChanged, this, &MainWindow::rerank);
  connect(weights_panel_, &widgets::WeightsPanel::weightsCommitted, this, &MainWindow::commitWeights);
  connect(weights_panel_, &widgets::WeightsPanel::resetRequested, this, [this] {
    weights_panel_->setWeights(projectWeightsOf(doc_.project()));
    rerank(weights_panel_->weights());
  });
  connect(ranking_table_, &widgets::RankingTable::toolActivated, this, [this](const QString& id) {
    setActiveTool(id);
    updateExpertOverlays();
  });
  connect(expert_, &ExpertRunner::sessionReady, this, &MainWindow::onExpertSessionReady);
  connect(expert_, &ExpertRunner::refined, this, &MainWindow::onRefined);
}

void MainWindow::rebuildExpert() {
  const app::Project& p = doc_.project();
  weights_ = projectWeightsOf(p);
  weights_panel_->setWeights(weights_);
  ranking_.reset();
  refinement_.reset();
  if (p.tools.empty() || !p.expert || !p.machine || !p.operation) {
    ranking_table_->setRanking({}, {});
    return;
  }
  try {
    app::ExpertRequest request = app::expertRequestFromProject(p);
    expert_->build(std::move(request.tools), request.settings, request.tool_ids);
  } catch (const std::exception& e) {
    ranking_table_->setRanking({}, {});
    statusBar()->showMessage(tr("Expert system unavailable: %1").arg(e.what()), 10000);
  }
}

void MainWindow::onExpertSessionReady(const QString& error) {
  if (!error.isEmpty()) {
    ranking_table_->setRanking({}, {});
    showError(tr("Expert system"), error);
    return;
  }
  rerank(weights_panel_->weights());
  expert_->refine(weights_panel_->weights());
}

// Rule 4 from the cached session: no lobes, grids or simulations are recomputed.
void MainWindow::rerank(const CostWeights& weights) {
  weights_ = weights;
  ranking_ = expert_->rank(weights.c);
  if (!ranking_) return;
  const QString selected = expert_->toolIds().value(static_cast<qsizetype>(ranking_->selected().tool));
  QVector<widgets::RankingRow> rows = widgets::RankingTable::rowsFromRanking(*ranking_, expert_->toolIds());
  if (refinement_ && refinement_->refinement && refinement_->weights.c == weights.c) {
    const Refinement& r = *refinement_->refinement;
    widgets::RankingTable::applyRefinement(rows, expert_->toolIds().value(static_cast<qsizetype>(r.tool)), r.chosen());
  }
  ranking_table_->setRanking(rows, selected);
  updateExpertOverlays();
  emit rankingShown();
}

void MainWindow::commitWeights(const CostWeights& weights) {
  app::Project edited = doc_.project();
  if (!edited.expert) return;
  edited.expert->c.assign(weights.c.begin(), weights.c.end());
  edited.expert->cr.assign(weights.cr.begin(), weights.cr.end());
  edited.expert->ct.assign(weights.ct.begin(), weights.ct.end());
  edited.expert->cf.assign(weights.cf.begin(), weights.cf.end());
  const QString error = doc_.applyEdit(edited, tr("Change cost weights"));
  if (!error.isEmpty()) showError(tr("Weights refused"), error);
}

void MainWindow::onRefined(const RefinementOutcome& outcome) {
  if (!outcome.error.isEmpty()) {
    statusBar()->showMessage(tr("Rules 5-6 failed: %1").arg(outcome.error), 10000);
    return;
  }
  refinement_ = outcome.result;
  if (refinement_ && refinement_->malfunction_iterations > 0) {
    statusBar()->showMessage(tr("Rule 6: %1 malfunction iteration(s), weights c = (%2, %3, %4)")
                                 .arg(refinement_->malfunction_iterations)
                                 .arg(refinement_->weights.c[0], 0, 'f', 4)
                                 .arg(refinement_->weights.c[1], 0, 'f', 4)
                                 .arg(refinement_->weights.c[2], 0, 'f', 4),
                             10000);
  }
  rerank(refinement_ ? refinement_->weights : weights_);
  emit refinementShown();
}

void MainWindow::updateExpertOverlays() {
  chart_->clearMarkers();
  if (pareto_choice_ && pareto_->study() && pareto_->study()->request().tool == active_tool_) {
    const ParetoPoint& q = pareto_choice_->point();
    chart_->setMarker(tr("Pareto q (%1)").arg(active_tool_), revPerSToRpm(q.speed_rev_per_s), q.depth_m * 1e3,
                      QColor(0, 130, 90));
  }
  const auto& session = expert_->session();
  if (!ranking_ || !session) {
    chart_->setCostMap({}, {}, {});
    chart_->setGridPoints({}, {});
    return;
  }
  const int index = static_cast<int>(expert_->toolIds().indexOf(active_tool_));
  for (const ToolChoice& t : ranking_->tools) {
    if (static_cast<int>(t.tool) != index) continue;
    chart_->setMarker(QString("q* (%1)").arg(active_tool_), revPerSToRpm(t.q.speed_rev_per_s), t.q.depth_m * 1e3,
                      QColor(20, 20, 160));
  }
  if (refinement_ && refinement_->refinement && static_cast<int>(refinement_->refinement->tool) == index) {
    const ExpertPoint& q = refinement_->refinement->chosen().q;
    chart_->setMarker("q**", revPerSToRpm(q.speed_rev_per_s), q.depth_m * 1e3, QColor(140, 0, 140));
  }
  if (index < 0) return;
  if (show_cost_map_) {
    const CostMapData map = costMap(*session, static_cast<std::size_t>(index), weights_.c);
    chart_->setCostMap(map.speeds_rpm, map.depths_mm, map.cost);
  }
  if (show_grid_) {
    QVector<double> n, b;
    gridPoints(*session, static_cast<std::size_t>(index), n, b);
    chart_->setGridPoints(n, b);
  }
  chart_->setCostMapVisible(show_cost_map_);
  chart_->setGridVisible(show_grid_);
}

}  // namespace mx::gui
