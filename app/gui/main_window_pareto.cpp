// MainWindow: the Pareto expert system (issue 5; Rubio et al., Pareto paper, modules V-VII).
// - The ParetoStudy of the project's pareto.tool is built on the engine thread when its inputs change;
//   moving the Pareto weights re-selects on the GUI thread (one pass over the table).
// - Committing weights (sliders, Rule 11 requirement, Rule 12 automatic weights, a history entry, a
//   click on the front) is one undoable step: the pareto.weights edit and the move of the operating
//   point to the selected q.
// - Rule 14: the chosen point can be recorded in the learning database; the history view queries it.
// - Rule 17: the monitoring dock shows the signals of the current point and its last simulation.
// - Rule 18: the operator-rules editor edits the project's operator_rules; the rules that fire for
//   the active tool are highlighted, with the constraints the current point violates.
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStatusBar>
#include <QVBoxLayout>
#include <cmath>

#include "history_view.h"
#include "main_window.h"
#include "monitoring_panel.h"
#include "operator_rules_editor.h"
#include "pareto_front_view.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "requirements_panel.h"
#include "services/learning_database.h"
#include "services/pareto_rules.h"
#include "simulation/frequency_peaks.h"

namespace mx::gui {

namespace {

QDockWidget* makeDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content, bool scroll) {
  auto* dock = new QDockWidget(title, window);
  dock->setObjectName(name);
  if (scroll) {
    auto* area = new QScrollArea;
    area->setWidget(content);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    dock->setWidget(area);
  } else {
    dock->setWidget(content);
  }
  return dock;
}

std::optional<ObjectiveRequirement> engineRequirement(const std::optional<widgets::RequirementView>& r) {
  if (!r) return std::nullopt;
  const double scale = r->objective == 1 ? 1e-6 : 1.0;  // MRR: cm^3/s -> m^3/s
  return ObjectiveRequirement{static_cast<Objective>(r->objective), r->lo * scale, r->hi * scale};
}

widgets::ParetoPointView pointView(const ParetoPoint& p) {
  widgets::ParetoPointView v;
  v.speed_rpm = revPerSToRpm(p.speed_rev_per_s);
  v.depth_mm = p.depth_m * 1e3;
  v.feed_mm_per_tooth = p.feed_per_tooth_m * 1e3;
  v.tol = p.tol();
  v.mrr_cm3_s = p.mrr() * 1e6;
  v.surf = p.surf();
  v.ros = p.ros();
  return v;
}

}  // namespace

ParetoWeights projectParetoWeightsOf(const app::Project& p) {
  ParetoWeights w{0.25, 0.25, 0.25, 0.25};
  if (p.pareto && p.pareto->weights && p.pareto->weights->size() == 4)
    for (std::size_t i = 0; i < 4; ++i) w[i] = (*p.pareto->weights)[i];
  return w;
}

void MainWindow::buildParetoDocks() {
  pareto_ = new ParetoRunner(engine_->pool(), this);
  pareto_weights_ = new widgets::ParetoWeightsPanel;
  requirements_ = new widgets::RequirementsPanel;
  record_button_ = new QPushButton(tr("Record point in learning database"));
  record_button_->setObjectName("record_point_button");
  record_button_->setToolTip(
      tr("Rule 14: store the operating point with the Pareto weights, tool, material, "
         "machine and objectives in the learning database"));
  chatter_hz_ = new QDoubleSpinBox;
  chatter_hz_->setObjectName("reported_chatter_hz");
  chatter_hz_->setRange(1.0, 20000.0);
  chatter_hz_->setDecimals(1);
  chatter_hz_->setValue(600.0);
  chatter_hz_->setSuffix(tr(" Hz"));
  chatter_hz_->setToolTip(tr("Chatter frequency heard or measured at the machine [Hz]"));
  report_chatter_ = new QPushButton(tr("Report chatter (Rule 16)"));
  report_chatter_->setObjectName("report_chatter_button");
  report_chatter_->setToolTip(
      tr("Module VI: chatter at this frequency at the operating point. The Smith-Tlusty "
         "speed N = 60 f_c / (n_t k) nearest it is computed, the point is re-selected "
         "within +-2 % of N, moved there and recorded (source feedback)"));
  auto* chatter_row = new QHBoxLayout;
  chatter_row->addWidget(new QLabel(tr("Chatter frequency [Hz]")));
  chatter_row->addWidget(chatter_hz_);
  chatter_row->addWidget(report_chatter_);
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  layout->addWidget(pareto_weights_);
  layout->addWidget(requirements_);
  layout->addWidget(record_button_);
  layout->addLayout(chatter_row);
  layout->addStretch(1);
  front_view_ = new widgets::ParetoFrontView;
  monitoring_ = new widgets::MonitoringPanel;
  history_ = new widgets::HistoryView;
  rules_editor_ = new widgets::OperatorRulesEditor;

  QDockWidget* weights = makeDock(this, tr("Pareto weights"), "paretoWeightsDock", panel, true);
  QDockWidget* rules = makeDock(this, tr("Operator rules"), "operatorRulesDock", rules_editor_, false);
  QDockWidget* front = makeDock(this, tr("Pareto front"), "paretoFrontDock", front_view_, false);
  QDockWidget* monitoring = makeDock(this, tr("Monitoring"), "monitoringDock", monitoring_, true);
  QDockWidget* history = makeDock(this, tr("History"), "historyDock", history_, false);
  for (QDockWidget* d : {weights, rules}) addDockWidget(Qt::RightDockWidgetArea, d);
  for (QDockWidget* d : {front, monitoring, history}) addDockWidget(Qt::BottomDockWidgetArea, d);
  if (auto* right = findChild<QDockWidget*>("weightsDock")) {
    tabifyDockWidget(right, weights);
    tabifyDockWidget(weights, rules);
  }
  if (auto* bottom = findChild<QDockWidget*>("rankingDock")) {
    tabifyDockWidget(bottom, front);
    tabifyDockWidget(front, monitoring);
    tabifyDockWidget(monitoring, history);
  }
  // The database is opened when the history is first shown (not at start-up).
  connect(history, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (visible) refreshHistory();
  });
  if (auto* point = findChild<QDockWidget*>("pointDock")) point->raise();
  if (auto* simulation = findChild<QDockWidget*>("simulationDock")) simulation->raise();

  pareto_timer_.setSingleShot(true);
  pareto_timer_.setInterval(120);
  connect(&pareto_timer_, &QTimer::timeout, this, &MainWindow::rebuildPareto);
  connect(pareto_, &ParetoRunner::studyReady, this, &MainWindow::onParetoReady);
  connect(pareto_weights_, &widgets::ParetoWeightsPanel::weightsChanged, this,
          [this](const ParetoWeights& w) { showParetoChoice(w); });
  connect(pareto_weights_, &widgets::ParetoWeightsPanel::weightsCommitted, this,
          [this](const ParetoWeights& w) { commitParetoWeights(w, tr("Change Pareto weights")); });
  connect(requirements_, &widgets::RequirementsPanel::requirementChanged, this, &MainWindow::onRequirementChanged);
  connect(requirements_, &widgets::RequirementsPanel::autoWeightsRequested, this, &MainWindow::onAutoWeights);
  connect(front_view_, &widgets::ParetoFrontView::pointActivated, this, &MainWindow::onFrontPointActivated);
  connect(record_button_, &QPushButton::clicked, this, [this] { recordOperatingPoint(); });
  connect(report_chatter_, &QPushButton::clicked, this, [this] { reportChatter(chatter_hz_->value()); });
  connect(rules_editor_, &widgets::OperatorRulesEditor::rulesChanged, this, &MainWindow::onRulesEdited);
  connect(history_, &widgets::HistoryView::filterChanged, this, [this] { refreshHistory(); });
  connect(history_, &widgets::HistoryView::refreshRequested, this, [this] { refreshHistory(); });
  connect(history_, &widgets::HistoryView::applyWeightsRequested, this, [this](const QVector<double>& w) {
    if (w.size() == 4) commitParetoWeights({w[0], w[1], w[2], w[3]}, tr("Apply weights from the history"));
  });
}

QString MainWindow::learningDatabasePath() const {
  return learning_db_path_.isEmpty() ? app::LearningDatabase::defaultPath() : learning_db_path_;
}

void MainWindow::setLearningDatabasePath(const QString& path) {
  learning_db_path_ = path;
  refreshHistory();
}

void MainWindow::rebuildPareto() {
  const app::Project& p = doc_.project();
  pareto_choice_.reset();
  if (!p.pareto || p.tools.empty() || !p.machine || !p.operation || !p.expert) {
    pareto_->clear();
    front_view_->setPoints({});
    front_view_->setEnabled(false);
    pareto_weights_->setEnabled(false);
    requirements_->setEnabled(false);
    record_button_->setEnabled(false);
    report_chatter_->setEnabled(false);
    pareto_weights_->setToolTip(tr("This project has no \"pareto\" section (docs/project-file.md)"));
    return;
  }
  pareto_->build(p);
}

void MainWindow::onParetoReady(const QString& error) {
  const auto& study = pareto_->study();
  const bool ok = error.isEmpty() && study;
  for (QWidget* w :
       std::initializer_list<QWidget*>{front_view_, pareto_weights_, requirements_, record_button_, report_chatter_})
    w->setEnabled(ok);
  if (!ok) {
    front_view_->setPoints({});
    pareto_choice_.reset();
    statusBar()->showMessage(tr("Pareto expert system unavailable: %1").arg(error), 15000);
    updateFiredRules();
    return;
  }
  QVector<widgets::ParetoPointView> points;
  points.reserve(static_cast<qsizetype>(study->front().size()));
  for (std::size_t k = 0; k < study->front().size(); ++k) {
    widgets::ParetoPointView v = pointView(study->table().points()[study->front()[k]]);
    v.weights = pareto_->frontWeights()[k];
    points.append(v);
  }
  front_view_->setPoints(points);
  pareto_weights_->setWeights(projectParetoWeightsOf(doc_.project()));
  showParetoChoice(pareto_weights_->weights());
  updateFiredRules();
  updateMonitoring();
}

std::optional<app::ParetoChoice> MainWindow::chooseWith(const ParetoWeights& w, bool auto_weights) {
  const auto& study = pareto_->study();
  if (!study) return std::nullopt;
  try {
    return study->choose({w, engineRequirement(requirements_->requirement()), false, auto_weights});
  } catch (const std::exception& e) {
    statusBar()->showMessage(tr("Pareto selection: %1").arg(e.what()), 10000);
    return std::nullopt;
  }
}

// Rule 10.1 for these weights: the front view and the chart show the selected point (the operating
// point does not move: that is a commit).
void MainWindow::showParetoChoice(const ParetoWeights& w) {
  pareto_choice_ = chooseWith(w, false);
  if (pareto_choice_) {
    const auto& study = pareto_->study();
    const auto& front = study->front();
    int selected = -1;
    if (pareto_choice_->selection.table_index) {
      const auto it = std::lower_bound(front.begin(), front.end(), *pareto_choice_->selection.table_index);
      if (it != front.end() && *it == *pareto_choice_->selection.table_index)
        selected = static_cast<int>(it - front.begin());
    }
    front_view_->setSelectedIndex(selected);
    if (requirements_->requirement())
      requirements_->setStatus(pareto_choice_->requirement_satisfied, pareto_choice_->requirement_changed);
    else
      requirements_->clearStatus();
  }
  updateExpertOverlays();
  emit paretoShown();
}

// One undoable step: pareto.weights := w, then the operating point moves to the point they select
// (or to `target` when given: a clicked front point).
void MainWindow::commitParetoWeights(const ParetoWeights& w, const QString& description,
                                     const std::optional<ParetoPoint>& target) {
  app::Project edited = doc_.project();
  if (!edited.pareto) return;
  edited.pareto->weights = std::vector<double>{w[0], w[1], w[2], w[3]};
  doc_.undoStack()->beginMacro(description);
  const QString error = doc_.applyEdit(edited, description);
  pareto_weights_->setWeights(w);
  showParetoChoice(w);
  if (error.isEmpty() && pareto_->study() && (target || pareto_choice_)) {
    const ParetoPoint& q = target ? *target : pareto_choice_->point();
    setActiveTool(pareto_->study()->request().tool);
    doc_.setPoint({revPerSToRpm(q.speed_rev_per_s), q.depth_m * 1e3, q.feed_per_tooth_m * 1e3});
  }
  doc_.undoStack()->endMacro();
  if (!error.isEmpty()) showError(tr("Pareto weights refused"), error);
}

void MainWindow::moveToParetoChoice() {
  if (pareto_->study()) commitParetoWeights(pareto_weights_->weights(), tr("Move to the Pareto choice"));
}

void MainWindow::onFrontPointActivated(const widgets::ParetoPointView& view) {
  const auto& study = pareto_->study();
  if (!study) return;
  int index = -1;  // the front point shown as `view`
  for (std::size_t k = 0; k < study->front().size() && index < 0; ++k) {
    const widgets::ParetoPointView v = pointView(study->table().points()[study->front()[k]]);
    if (v.speed_rpm == view.speed_rpm && v.depth_mm == view.depth_mm && v.feed_mm_per_tooth == view.feed_mm_per_tooth)
      index = static_cast<int>(k);
  }
  if (index < 0) return;
  const ParetoPoint& q = study->table().points()[study->front()[static_cast<std::size_t>(index)]];
  ParetoWeights w = pareto_weights_->weights();
  if (view.weights) {
    w = *view.weights;
  } else {
    // An unsupported point (non-convex part of the front): the weights of the nearest supported one.
    double best = std::numeric_limits<double>::infinity();
    const auto& scores = study->table().scores();
    const ObjectiveVector& s = scores[study->front()[static_cast<std::size_t>(index)]];
    for (std::size_t k = 0; k < study->front().size(); ++k) {
      if (!pareto_->frontWeights()[k]) continue;
      double d = 0.0;
      for (std::size_t i = 0; i < kObjectiveCount; ++i) d += std::pow(scores[study->front()[k]][i] - s[i], 2);
      if (d < best) {
        best = d;
        w = *pareto_->frontWeights()[k];
      }
    }
    statusBar()->showMessage(tr("No weights select this point exactly (non-convex part of the front): the "
                                "weights of the nearest supported point are applied"),
                             10000);
  }
  commitParetoWeights(w, tr("Move to a Pareto point"), q);
  front_view_->setSelectedIndex(index);
}

// Module VI, chatter reported by the operator (or found by the simulation): Rule 16 and a re-selection
// near the Smith-Tlusty speed; the point moves there (undoable), is recorded (source feedback) and
// simulated.
void MainWindow::reportChatter(double chatter_hz) {
  const auto& study = pareto_->study();
  const auto q = currentParetoPoint();
  if (!study || !q) {
    showError(tr("Chatter feedback"), tr("Pick an operating point of the Pareto tool first"));
    return;
  }
  const auto r = study->reselectAfterChatter(pareto_weights_->weights(),
                                             engineRequirement(requirements_->requirement()), chatter_hz, *q);
  if (!r || !r->selection) {
    showError(tr("Chatter feedback"),
              tr("No admissible point near a Smith-Tlusty speed for %1 Hz in the grid's speed range").arg(chatter_hz));
    return;
  }
  const ParetoPoint& p = r->selection->point;
  doc_.setPoint({revPerSToRpm(p.speed_rev_per_s), p.depth_m * 1e3, p.feed_per_tooth_m * 1e3});
  statusBar()->showMessage(tr("Rule 16: chatter at %1 Hz -> N = %2 rpm (k = %3); re-selected %4 rpm, %5 mm")
                               .arg(chatter_hz, 0, 'f', 1)
                               .arg(revPerSToRpm(r->suggested_rev_per_s), 0, 'f', 0)
                               .arg(r->k)
                               .arg(revPerSToRpm(p.speed_rev_per_s), 0, 'f', 0)
                               .arg(p.depth_m * 1e3, 0, 'f', 3),
                           15000);
  try {
    app::LearningDatabase db(learningDatabasePath());
    db.insert(study->learningRecord(pareto_weights_->weights(), p, 0.0, app::LearningSource::Feedback));
  } catch (const std::exception& e) {
    statusBar()->showMessage(tr("Learning database: %1").arg(e.what()), 10000);
  }
  refreshHistory();
  startSimulation();
}

void MainWindow::onRequirementChanged() {
  if (!pareto_->study()) return;
  const ParetoWeights before = pareto_weights_->weights();
  const auto choice = chooseWith(before, false);
  if (!choice) return;
  if (choice->requirement_changed)
    commitParetoWeights(choice->weights, tr("Rule 11: weights for the requirement"));
  else
    showParetoChoice(before);
}

void MainWindow::onAutoWeights() {
  const auto choice = chooseWith(pareto_weights_->weights(), true);
  if (!choice || !choice->ascent) return;
  requirements_->setAutoWeightsResult(choice->ascent->iterations, choice->ascent->converged);
  commitParetoWeights(choice->weights, tr("Rule 12: automatic weights"));
}

}  // namespace mx::gui
