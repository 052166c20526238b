#include "expert_feature.h"

#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryFile>
#include <cmath>

#include "document/frf_paths.h"
#include "expert_overlays.h"
#include "expert_runner.h"
#include "feature_dock.h"
#include "lobe_chart_view.h"
#include "ranking_table.h"
#include "services/expert_request.h"
#include "services/reported_chatter.h"
#include "weights_panel.h"

namespace mx::gui {

namespace {
const QString kMarkers = "expert";  // the chart's marker group of q* and q**
}

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

ExpertFeature::ExpertFeature(QMainWindow* window, FeatureContext& context, widgets::LobeChartView* chart)
    : WindowFeature(window),
      context_(context),
      chart_(chart),
      runner_(new ExpertRunner(context.enginePool(), this)),
      weights_panel_(new widgets::WeightsPanel(window)),
      ranking_table_(new widgets::RankingTable(window)) {
  setObjectName("expertFeature");
  ranking_table_->setUnits(context.units());
  buildDocks(window);
  rebuild_timer_.setSingleShot(true);
  rebuild_timer_.setInterval(120);
  connect(&rebuild_timer_, &QTimer::timeout, this, &ExpertFeature::rebuild);
  connect(weights_panel_, &widgets::WeightsPanel::weightsChanged, this, &ExpertFeature::rerank);
  connect(weights_panel_, &widgets::WeightsPanel::weightsCommitted, this, &ExpertFeature::commitWeights);
  connect(weights_panel_, &widgets::WeightsPanel::resetRequested, this, [this] {
    weights_panel_->setWeights(projectWeightsOf(context_.project()));
    rerank(weights_panel_->weights());
  });
  connect(ranking_table_, &widgets::RankingTable::toolActivated, this, [this](const QString& id) {
    context_.setActiveTool(id);
    updateOverlays();
  });
  connect(runner_, &ExpertRunner::sessionReady, this, &ExpertFeature::onSessionReady);
  connect(runner_, &ExpertRunner::refined, this, &ExpertFeature::onRefined);
  connect(&context_, &FeatureContext::activeToolChanged, this, &ExpertFeature::updateOverlays);
  connect(&context_, &FeatureContext::lobesShown, this, &ExpertFeature::updateOverlays);
  connect(&context_, &FeatureContext::rankingChatterReported, this, &ExpertFeature::reportChatter);
}

// Weights share the right area with the operating point; the ranking shares the bottom with the
// live simulation (tabs), so that the window fits 1920x1080.
void ExpertFeature::buildDocks(QMainWindow* window) {
  QDockWidget* weights =
      makeFeatureDock(window, tr("Cost weights"), "weightsDock", weights_panel_, DockContent::Scrolling);
  QDockWidget* ranking = makeFeatureDock(window, tr("Tool ranking"), "rankingDock", ranking_table_);
  window->addDockWidget(Qt::RightDockWidgetArea, weights);
  window->addDockWidget(Qt::BottomDockWidgetArea, ranking);
  if (auto* point = window->findChild<QDockWidget*>("pointDock")) window->tabifyDockWidget(point, weights);
  if (auto* simulation = window->findChild<QDockWidget*>("simulationDock")) {
    window->tabifyDockWidget(simulation, ranking);
    simulation->raise();
  }
  if (auto* point = window->findChild<QDockWidget*>("pointDock")) point->raise();
}

void ExpertFeature::addFileActions(QMenu* file, QToolBar* /*toolbar*/) {
  QAction* a = file->addAction(tr("Export &report..."));
  a->setShortcut(QKeySequence(tr("Ctrl+R")));
  a->setToolTip(tr("Write the expert report (project, ranking, q* and q**, cost terms, figures) as PDF or HTML"));
  a->setStatusTip(a->toolTip());
  connect(a, &QAction::triggered, this, &ExpertFeature::exportReport);
}

void ExpertFeature::addViewActions(QMenu* view, QToolBar* /*toolbar*/) {
  QAction* heat = view->addAction(tr("Show tool-cost &heat map"));
  heat->setCheckable(true);
  heat->setToolTip(tr("Colour the (N, b) plane by the tool cost C (eq. 13) of the active tool"));
  connect(heat, &QAction::toggled, this, [this](bool on) {
    show_cost_map_ = on;
    updateOverlays();
  });
  QAction* grid = view->addAction(tr("Show admissible &grid"));
  grid->setCheckable(true);
  grid->setToolTip(tr("Show the admissible (N, b) grid points of the active tool"));
  connect(grid, &QAction::toggled, this, [this](bool on) {
    show_grid_ = on;
    updateOverlays();
  });
}

// A new session waits for the edits to pause; a weight change alone re-ranks from the cached one
// (Rule 4) and re-runs Rules 5-6 for q**: no lobes or grids.
void ExpertFeature::projectChanged(const app::Project& project, Features recompute) {
  if (recompute & Feature::ExpertSession) {
    runner_->dropPending();  // a session of the project before this change would un-stale the table
    ranking_table_->setStale(tr("the project changed; the expert session is being rebuilt"));
    rebuild_timer_.start();
  } else if ((recompute & Feature::ExpertRerank) && !rebuild_timer_.isActive()) {
    const CostWeights w = projectWeightsOf(project);
    weights_panel_->setWeights(w);
    if (runner_->session()) {
      rerank(w);
      runner_->refine(w, reportedChatter());
    }
  }
}

void ExpertFeature::rebuild() {
  const app::Project& p = context_.project();
  weights_ = projectWeightsOf(p);
  weights_panel_->setWeights(weights_);
  ranking_.reset();
  refinement_.reset();
  if (p.tools.empty() || !p.expert || !p.machine || !p.operation) {
    ranking_table_->setRanking({}, {});
    return;
  }
  try {
    // The cheap checks here, for a status message; the request itself, with the tools' FRF files, is
    // made on the engine thread.
    app::expertRequestFromProject(p);
    for (const app::ToolSpec& t : p.tools) app::requireFittedModes(t, tr("the Rule 5 refinement (simulation)"));
    runner_->build(app::withAbsoluteFrfPaths(p));
  } catch (const std::exception& e) {
    ranking_table_->setRanking({}, {});
    emit statusMessage(tr("Expert system unavailable: %1").arg(e.what()), 10000);
  }
}

void ExpertFeature::onSessionReady(const QString& error) {
  if (!error.isEmpty()) {
    ranking_table_->setRanking({}, {});
    emit errorRaised(tr("Expert system"), error);
    return;
  }
  rerank(weights_panel_->weights());
  runner_->refine(weights_panel_->weights(), reportedChatter());
}

// Rule 4 from the cached session: no lobes, grids or simulations are recomputed.
void ExpertFeature::rerank(const CostWeights& weights) {
  weights_ = weights;
  ranking_ = runner_->rank(weights.c);
  if (!ranking_) return;
  const std::array<double, 3> effective = runner_->effectiveWeights(weights.c);
  if (effective != weights.c)
    emit statusMessage(tr("Operator rules (Rule 18) bound the tool-cost weights to c = (%1, %2, %3)")
                           .arg(effective[0], 0, 'f', 3)
                           .arg(effective[1], 0, 'f', 3)
                           .arg(effective[2], 0, 'f', 3),
                       8000);
  const QStringList& ids = runner_->toolIds();
  const QString selected = ids.value(static_cast<qsizetype>(ranking_->selected().tool));
  QVector<widgets::RankingRow> rows = widgets::RankingTable::rowsFromRanking(*ranking_, ids);
  if (refinement_ && refinement_->refinement && refinement_->weights.c == effective) {
    const Refinement& r = *refinement_->refinement;
    widgets::RankingTable::applyRefinement(rows, ids.value(static_cast<qsizetype>(r.tool)), r.chosen());
  }
  ranking_table_->setRanking(rows, selected);
  updateOverlays();
  placeDefaultPoint();
  emit rankingShown();
}

void ExpertFeature::commitWeights(const CostWeights& weights) {
  app::Project edited = context_.project();
  if (!edited.expert) return;
  edited.expert->c.assign(weights.c.begin(), weights.c.end());
  edited.expert->cr.assign(weights.cr.begin(), weights.cr.end());
  edited.expert->ct.assign(weights.ct.begin(), weights.ct.end());
  edited.expert->cf.assign(weights.cf.begin(), weights.cf.end());
  emit editRequested(edited, tr("Change cost weights"), 0);
}

// The project's expert.reported_chatter for the session's tools (none for a stale tool list).
std::vector<ChatterReport> ExpertFeature::reportedChatter() const {
  const app::Project& p = context_.project();
  if (!p.expert) return {};
  try {
    return app::engineChatterReports(p.expert->reported_chatter, runner_->toolIds());
  } catch (const std::exception&) {
    return {};  // the session predates the tool edit; the next session takes the reports
  }
}

// Rule 6 on evidence: the chatter heard at the operating point of the active tool joins
// expert.reported_chatter (one undoable edit); the re-run moves the weights until q** leaves it.
void ExpertFeature::reportChatter(double chatter_hz) {
  app::Project edited = context_.project();
  const QString tool = context_.activeTool();
  const app::PickedPoint& q = context_.point();
  if (!edited.expert || tool.isEmpty() || !(q.speed_rpm > 0.0) || !(q.depth_mm > 0.0)) {
    emit errorRaised(tr("Chatter feedback"), tr("Pick an operating point of a tool of the expert system first"));
    return;
  }
  app::ChatterReportSpec report;
  report.tool = tool;
  report.speed_rpm = q.speed_rpm;
  report.depth_mm = q.depth_mm;
  report.freq_Hz = chatter_hz;
  edited.expert->reported_chatter.push_back(report);
  emit editRequested(edited,
                     tr("Report chatter at %1 rpm, %2 mm").arg(q.speed_rpm, 0, 'f', 0).arg(q.depth_mm, 0, 'f', 3), 0);
  emit statusMessage(tr("Rule 6: chatter at %1 rpm, %2 mm (%3 Hz) reported for %4; re-running Rules 4-6")
                         .arg(q.speed_rpm, 0, 'f', 0)
                         .arg(q.depth_mm, 0, 'f', 3)
                         .arg(chatter_hz, 0, 'f', 1)
                         .arg(tool),
                     10000);
}

void ExpertFeature::onRefined(const RefinementOutcome& outcome) {
  if (!outcome.error.isEmpty()) {
    emit statusMessage(tr("Rules 5-6 failed: %1").arg(outcome.error), 10000);
    opening_ = false;
    return;
  }
  refinement_ = outcome.result;
  if (refinement_ && refinement_->unresolved_report && runner_->session()) {
    const app::Project& p = context_.project();
    emit errorRaised(tr("Rule 6"),
                     app::unresolvedChatterMessage(
                         *refinement_, p.expert ? p.expert->reported_chatter : std::vector<app::ChatterReportSpec>{},
                         runner_->toolIds(), runner_->session()->settings().refinement.max_malfunction_iterations));
  }
  if (refinement_ && refinement_->malfunction_iterations > 0) {
    emit statusMessage(tr("Rule 6: %1 malfunction iteration(s), weights c = (%2, %3, %4)")
                           .arg(refinement_->malfunction_iterations)
                           .arg(refinement_->weights.c[0], 0, 'f', 4)
                           .arg(refinement_->weights.c[1], 0, 'f', 4)
                           .arg(refinement_->weights.c[2], 0, 'f', 4),
                       10000);
  }
  rerank(refinement_ ? refinement_->weights : weights_);
  opening_ = false;
  emit refinementShown();
}

// q* of the active tool, q** when Rules 5-6 chose that tool, and the heat map and grid on request.
void ExpertFeature::updateOverlays() {
  chart_->clearMarkers(kMarkers);
  const QString& tool = context_.activeTool();
  if (!ranking_ || !runner_->session()) {
    chart_->setCostMap({}, {}, {});
    chart_->setGridPoints({}, {});
    return;
  }
  const int index = static_cast<int>(runner_->toolIds().indexOf(tool));
  const ExpertPoint* q_star = nullptr;
  for (const ToolChoice& t : ranking_->tools)
    if (static_cast<int>(t.tool) == index) q_star = &t.q;
  const ExpertPoint* q_star_star = nullptr;
  if (refinement_ && refinement_->refinement && static_cast<int>(refinement_->refinement->tool) == index)
    q_star_star = &refinement_->refinement->chosen().q;
  // q** within 1 % of q* in speed and depth: one marker, so that the labels do not overprint.
  const bool together = q_star && q_star_star &&
                        std::abs(q_star_star->speed_rev_per_s / q_star->speed_rev_per_s - 1.0) < 0.01 &&
                        std::abs(q_star_star->depth_m / q_star->depth_m - 1.0) < 0.01;
  if (q_star)
    chart_->setMarker(together ? QString("q*, q** (%1)").arg(tool) : QString("q* (%1)").arg(tool),
                      revPerSToRpm(q_star->speed_rev_per_s), q_star->depth_m * 1e3, QColor(20, 20, 160), kMarkers);
  if (q_star_star && !together)
    chart_->setMarker("q**", revPerSToRpm(q_star_star->speed_rev_per_s), q_star_star->depth_m * 1e3,
                      QColor(140, 0, 140), kMarkers);
  if (index >= 0) drawSessionOverlays(index);
}

namespace {
// A value of q* in shop units without the noise of the conversion from SI (0.3 mm/tooth, not
// 0.30000000000000004), as the point is shown and saved.
double withoutConversionNoise(double value) {
  return QString::number(value, 'g', 12).toDouble();
}
}  // namespace

// A project without a stored operating point opens at q* of the active tool: of the first ranking and
// of its Rules 5-6 re-rank, unless the user has moved the point by then. Later rankings (other weights,
// edits) leave the point where it is.
void ExpertFeature::placeDefaultPoint() {
  if (!opening_ || !ranking_ || context_.project().operating_point || !context_.pointIsDefault()) return;
  const qsizetype index = runner_->toolIds().indexOf(context_.activeTool());
  for (const ToolChoice& t : ranking_->tools) {
    if (index < 0 || t.tool != static_cast<std::size_t>(index)) continue;
    const app::PickedPoint q{withoutConversionNoise(revPerSToRpm(t.q.speed_rev_per_s)),
                             withoutConversionNoise(t.q.depth_m * 1e3),
                             withoutConversionNoise(t.q.feed_per_tooth_m * 1e3)};
    context_.setDefaultPoint(q);
    if (!(q == context_.point())) emit initialPointRequested(q);
  }
}

void ExpertFeature::drawSessionOverlays(int tool) {
  const auto& session = *runner_->session();
  if (show_cost_map_) {
    const CostMapData map = costMap(session, static_cast<std::size_t>(tool), weights_.c);
    chart_->setCostMap(map.speeds_rpm, map.depths_mm, map.cost);
  }
  if (show_grid_) {
    QVector<double> n, b;
    gridPoints(session, static_cast<std::size_t>(tool), n, b);
    chart_->setGridPoints(n, b);
  }
  chart_->setCostMapVisible(show_cost_map_);
  chart_->setGridVisible(show_grid_);
}

QString reportProjectName(const app::ProjectDocument& document) {
  const QString path = document.filePath();
  if (path.isEmpty()) return QObject::tr("unsaved");
  return document.isDirty() ? QObject::tr("%1 (with unsaved changes)").arg(path) : path;
}

// millexpert-report runs in a separate process (never blocks the GUI) on a snapshot of the current,
// possibly unsaved, project.
void ExpertFeature::exportReport() {
  const QString path = QFileDialog::getSaveFileName(chart_, tr("Export report"), "millexpert-report.pdf",
                                                    tr("PDF (*.pdf);;HTML (*.html)"));
  if (!path.isEmpty()) exportReportTo(path);
}

void ExpertFeature::exportReportTo(const QString& path) {
  QTemporaryFile file(QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation))
                          .filePath("millexpert-report-XXXXXX.mxproj"));  // one per export: several may run
  file.setAutoRemove(false);
  if (!file.open()) {
    emit errorRaised(tr("Export report"), tr("Cannot create a temporary project file: %1").arg(file.errorString()));
    return;
  }
  const QString snapshot = file.fileName();
  file.close();
  try {
    app::saveProject(app::withAbsoluteFrfPaths(context_.project()), snapshot);  // the snapshot lives elsewhere
  } catch (const app::ProjectError& e) {
    emit errorRaised(tr("Export report"), QString::fromStdString(e.what()));
    return;
  }
  const auto& c = weights_.c;
  QStringList args{snapshot,
                   path.endsWith(".html", Qt::CaseInsensitive) ? "--html" : "--pdf",
                   path,
                   "--c",
                   QString("%1,%2,%3").arg(c[0], 0, 'g', 17).arg(c[1], 0, 'g', 17).arg(c[2], 0, 'g', 17),
                   "--project-name",
                   reportProjectName(context_.document()),
                   "--units",
                   context_.units()->shop().toText()};  // the report in the window's shop units
  auto* process = new QProcess(this);
  connect(process, &QProcess::finished, this, [this, process, path, snapshot](int code, QProcess::ExitStatus status) {
    QFile::remove(snapshot);
    const QString err = QString::fromUtf8(process->readAllStandardError()).trimmed();
    process->deleteLater();
    if (status == QProcess::NormalExit && code == 0) {
      emit statusMessage(tr("Report written to %1").arg(path), 8000);
      emit reportWritten(path);
    } else {
      emit errorRaised(tr("Export report"), err.isEmpty() ? tr("millexpert-report failed (exit %1)").arg(code) : err);
    }
  });
  emit statusMessage(tr("Writing the report (expert system, simulations, figures)..."), 0);
  process->start(
      report_program_.isEmpty() ? QCoreApplication::applicationDirPath() + "/millexpert-report" : report_program_,
      args);
}

}  // namespace mx::gui
