#include "pareto_feature.h"

#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "document/frf_paths.h"
#include "feature_dock.h"
#include "history_view.h"
#include "learning_client.h"
#include "lobe_chart_view.h"
#include "monitoring_panel.h"
#include "notice_stack.h"
#include "operator_rules_editor.h"
#include "pareto_choice_summary.h"
#include "pareto_front_view.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "requirements_panel.h"

namespace mx::gui {

namespace {

const QString kMarkers = "pareto";  // the chart's marker group of the Pareto choice

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

widgets::ParetoChoiceSummary choiceSummary(const app::ParetoChoice& c) {
  const ParetoPoint& q = c.point();
  widgets::ParetoChoiceSummary s;
  s.speed_rpm = revPerSToRpm(q.speed_rev_per_s);
  s.depth_mm = q.depth_m * 1e3;
  s.feed_mm_per_tooth = q.feed_per_tooth_m * 1e3;
  s.mrr_cm3_s = q.mrr() * 1e6;
  s.tol_min = q.tol();
  s.surf_um = q.surf();
  s.ros = q.ros();
  if (c.economics) {
    s.cost_per_part = c.economics->cost_per_part;
    s.time_per_part_min = c.economics->time_per_part_s / 60.0;
  }
  for (const app::BindingLimit& b : c.binding) s.binding << b.text;
  return s;
}

app::PickedPoint pickedPoint(const ParetoPoint& q) {
  return {revPerSToRpm(q.speed_rev_per_s), q.depth_m * 1e3, q.feed_per_tooth_m * 1e3};
}

}  // namespace

ParetoWeights projectParetoWeightsOf(const app::Project& p) {
  ParetoWeights w{0.25, 0.25, 0.25, 0.25};
  if (p.pareto && p.pareto->weights && p.pareto->weights->size() == 4)
    for (std::size_t i = 0; i < 4; ++i) w[i] = (*p.pareto->weights)[i];
  return w;
}

ParetoFeature::ParetoFeature(QMainWindow* window, FeatureContext& context, widgets::LobeChartView* chart)
    : WindowFeature(window),
      context_(context),
      chart_(chart),
      runner_(new ParetoRunner(context.enginePool(), this)),
      weights_panel_(new widgets::ParetoWeightsPanel),
      requirements_(new widgets::RequirementsPanel),
      summary_(new widgets::ParetoChoiceSummaryPanel),
      front_view_(new widgets::ParetoFrontView),
      front_notice_(new widgets::NoticeStack(front_view_)),
      monitoring_(new widgets::MonitoringPanel),
      history_(new widgets::HistoryView),
      rules_editor_(new widgets::OperatorRulesEditor),
      record_button_(new QPushButton(tr("Record point in learning database"))),
      report_chatter_(new QPushButton(tr("Report chatter (Rule 16 / Rule 6)"))),
      chatter_hz_(new QDoubleSpinBox),
      learning_(new LearningClient(this)) {
  setObjectName("paretoFeature");
  front_notice_->setObjectName("paretoFrontNotice");
  requirements_->setUnits(context.units());
  summary_->setUnits(context.units());
  front_view_->setUnits(context.units());
  monitoring_->setUnits(context.units());
  history_->setUnits(context.units());
  buildDocks(window);
  rebuild_timer_.setSingleShot(true);
  rebuild_timer_.setInterval(120);
  connectSignals();
}

QWidget* ParetoFeature::buildWeightsPanel() {
  record_button_->setObjectName("record_point_button");
  record_button_->setToolTip(
      tr("Rule 14: store the operating point with the Pareto weights, tool, material, "
         "machine and objectives in the learning database"));
  chatter_hz_->setObjectName("reported_chatter_hz");
  chatter_hz_->setRange(1.0, 20000.0);
  chatter_hz_->setDecimals(1);
  chatter_hz_->setValue(600.0);
  chatter_hz_->setSuffix(tr(" Hz"));
  chatter_hz_->setToolTip(tr("Chatter frequency heard or measured at the machine [Hz]"));
  report_chatter_->setObjectName("report_chatter_button");
  report_chatter_->setToolTip(
      tr("Chatter at this frequency at the operating point. Pareto study (active tool = pareto.tool): "
         "Module VI, the Smith-Tlusty speed N = 60 f_c / (n_t k) nearest it, the point re-selected within "
         "+-2 % of N, moved there and recorded. Otherwise the 2006 ranking: Rule 6 moves the cost weights "
         "until q** leaves +-2 % of the speed at that depth and deeper (expert.reported_chatter)"));
  // The button under the frequency, not beside it: side by side they would make the dock wider than
  // a 1080p window gives it.
  auto* chatter_row = new QHBoxLayout;
  chatter_row->addWidget(new QLabel(tr("Chatter frequency [Hz]")));
  chatter_row->addWidget(chatter_hz_, 1);
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  layout->addWidget(weights_panel_);
  layout->addWidget(summary_);
  layout->addWidget(requirements_);
  layout->addWidget(record_button_);
  layout->addLayout(chatter_row);
  layout->addWidget(report_chatter_);
  layout->addStretch(1);
  return panel;
}

void ParetoFeature::buildDocks(QMainWindow* window) {
  QDockWidget* weights =
      makeFeatureDock(window, tr("Pareto weights"), "paretoWeightsDock", buildWeightsPanel(), DockContent::Scrolling);
  QDockWidget* rules = makeFeatureDock(window, tr("Operator rules"), "operatorRulesDock", rules_editor_);
  QDockWidget* front = makeFeatureDock(window, tr("Pareto front"), "paretoFrontDock", front_notice_);
  QDockWidget* monitoring =
      makeFeatureDock(window, tr("Monitoring"), "monitoringDock", monitoring_, DockContent::Scrolling);
  QDockWidget* history = makeFeatureDock(window, tr("History"), "historyDock", history_);
  for (QDockWidget* d : {weights, rules}) window->addDockWidget(Qt::RightDockWidgetArea, d);
  for (QDockWidget* d : {front, monitoring, history}) window->addDockWidget(Qt::BottomDockWidgetArea, d);
  if (auto* right = window->findChild<QDockWidget*>("weightsDock")) {
    window->tabifyDockWidget(right, weights);
    window->tabifyDockWidget(weights, rules);
  }
  if (auto* bottom = window->findChild<QDockWidget*>("rankingDock")) {
    window->tabifyDockWidget(bottom, front);
    window->tabifyDockWidget(front, monitoring);
    window->tabifyDockWidget(monitoring, history);
  }
  // The database is opened when the history is first shown (not at start-up).
  connect(history, &QDockWidget::visibilityChanged, this, [this](bool visible) {
    if (visible) refreshHistory();
  });
  if (auto* point = window->findChild<QDockWidget*>("pointDock")) point->raise();
  if (auto* simulation = window->findChild<QDockWidget*>("simulationDock")) simulation->raise();
}

void ParetoFeature::connectSignals() {
  connect(&rebuild_timer_, &QTimer::timeout, this, &ParetoFeature::rebuild);
  connect(runner_, &ParetoRunner::studyReady, this, &ParetoFeature::onStudyReady);
  connect(weights_panel_, &widgets::ParetoWeightsPanel::weightsChanged, this,
          [this](const ParetoWeights& w) { showChoice(w); });
  connect(weights_panel_, &widgets::ParetoWeightsPanel::weightsCommitted, this,
          [this](const ParetoWeights& w) { commitWeights(w, tr("Change Pareto weights")); });
  connect(requirements_, &widgets::RequirementsPanel::requirementChanged, this, &ParetoFeature::onRequirementChanged);
  connect(summary_, &widgets::ParetoChoiceSummaryPanel::objectiveChosen, this,
          [this](const QString& key) { editParetoSetting("objective", key); });
  connect(summary_, &widgets::ParetoChoiceSummaryPanel::normalisationChosen, this,
          [this](const QString& key) { editParetoSetting("normalisation", key); });
  connect(requirements_, &widgets::RequirementsPanel::autoWeightsRequested, this, &ParetoFeature::onAutoWeights);
  connect(front_view_, &widgets::ParetoFrontView::pointActivated, this, &ParetoFeature::onFrontPointActivated);
  connect(front_notice_, &widgets::NoticeStack::actionTriggered, this, &ParetoFeature::addParetoSection);
  connect(record_button_, &QPushButton::clicked, this, [this] { recordOperatingPoint(); });
  connect(report_chatter_, &QPushButton::clicked, this, [this] { routeChatterReport(chatter_hz_->value()); });
  connect(rules_editor_, &widgets::OperatorRulesEditor::rulesChanged, this, &ParetoFeature::onRulesEdited);
  connect(history_, &widgets::HistoryView::filterChanged, this, [this] { refreshHistory(); });
  connect(history_, &widgets::HistoryView::refreshRequested, this, [this] { refreshHistory(); });
  connect(history_, &widgets::HistoryView::applyWeightsRequested, this, [this](const QVector<double>& w) {
    if (w.size() == 4) commitWeights({w[0], w[1], w[2], w[3]}, tr("Apply weights from the history"));
  });
  connect(&context_, &FeatureContext::activeToolChanged, this, &ParetoFeature::showChoiceMarker);
  connect(&context_, &FeatureContext::readoutChanged, this, [this] {
    updateFiredRules();
    updateMonitoring();
  });
  connect(&context_, &FeatureContext::simulationStateChanged, this, &ParetoFeature::updateMonitoring);
  connectLearning();
}

// A new study waits for the edits to pause; new weights alone re-select from the current one.
void ParetoFeature::projectChanged(const app::Project& project, Features recompute) {
  if (recompute & Feature::ParetoStudy) {
    runner_->dropPending();  // a study of the project before this change would show as its front
    rebuild_timer_.start();
  } else if ((recompute & Feature::ParetoChoice) && runner_->study()) {
    weights_panel_->setWeights(projectParetoWeightsOf(project));
    showChoice(weights_panel_->weights());
  }
  if (recompute & Feature::FiredRules) updateFiredRules();
}

void ParetoFeature::rebuild() {
  const app::Project& p = context_.project();
  choice_.reset();
  if (const QString missing = missingSections(); !missing.isEmpty()) {
    disable();
    if (!p.pareto)
      front_notice_->showNotice(tr("This project has no Pareto study: the front of tool life, removal rate, "
                                   "roughness and robustness needs a \"pareto\" section with the material's "
                                   "tool-life and roughness laws."),
                                tr("Add a Pareto section (Rubio et al.'s aluminium laws, to edit for your material)"));
    else
      front_notice_->showNotice(tr("The Pareto study needs %1.").arg(missing));
    return;
  }
  front_notice_->showContent();
  runner_->build(app::withAbsoluteFrfPaths(p));  // the FRF files are read on the engine thread
}

// What the study lacks, in words: "a tool and the machine section", or "".
QString ParetoFeature::missingSections() const {
  const app::Project& p = context_.project();
  QStringList missing;
  if (!p.pareto) missing << tr("a \"pareto\" section");
  if (p.tools.empty()) missing << tr("a tool");
  if (!p.machine) missing << tr("the machine section");
  if (!p.operation) missing << tr("the operation section");
  if (!p.expert) missing << tr("the expert section (its grid and cost weights)");
  if (missing.size() > 1) missing.last().prepend(tr("and "));
  return missing.join(missing.size() > 2 ? ", " : " ");
}

// A Pareto section with the tool-life (Taylor) and roughness laws of Rubio et al.'s aluminium case
// (Table 3, projects/rubio-pareto-case.mxproj) and its weights: a start that computes, to be replaced
// by the shop's own laws.
void ParetoFeature::addParetoSection() {
  app::Project edited = context_.project();
  if (edited.pareto) return;
  app::ParetoSection section;
  section.taylor = app::PowerLawSpec{15300000.0, -3.02, -1.14, -0.54};
  section.roughness = app::PowerLawSpec{0.98, 0.4638, 1.129, 0.4461};
  section.weights = std::vector<double>{0.4, 0.1, 0.3, 0.2};
  edited.pareto = section;
  emit editRequested(edited, tr("Add a Pareto section"), 0);
}

void ParetoFeature::disable() {
  runner_->clear();
  front_view_->setPoints({});
  setControlsEnabled(false);
  weights_panel_->setToolTip(tr("This project has no \"pareto\" section (docs/project-file.md)"));
  showChoiceMarker();
}

// The controls that need a study: the front, the weights, the requirement and record. Reporting
// chatter needs none: without the Pareto study it feeds the 2006 ranking (routeChatterReport).
void ParetoFeature::setControlsEnabled(bool enabled) {
  for (QWidget* w :
       std::initializer_list<QWidget*>{front_view_, weights_panel_, summary_, requirements_, record_button_})
    w->setEnabled(enabled);
}

void ParetoFeature::onStudyReady(const QString& error) {
  const auto& study = runner_->study();
  const bool ok = error.isEmpty() && study;
  setControlsEnabled(ok);
  if (!ok) {
    front_view_->setPoints({});
    front_notice_->showNotice(tr("The Pareto study could not run: %1").arg(error));
    choice_.reset();
    showChoiceMarker();
    emit statusMessage(tr("Pareto expert system unavailable: %1").arg(error), 15000);
    updateFiredRules();
    return;
  }
  QVector<widgets::ParetoPointView> points;
  points.reserve(static_cast<qsizetype>(study->front().size()));
  for (std::size_t k = 0; k < study->front().size(); ++k) {
    widgets::ParetoPointView v = pointView(study->table().points()[study->front()[k]]);
    v.weights = runner_->frontWeights()[k];
    points.append(v);
  }
  front_view_->setPoints(points);
  weights_panel_->setWeights(projectParetoWeightsOf(context_.project()));
  summary_->setEconomicsAvailable(study->request().economics.has_value());
  summary_->setObjective(app::paretoObjectiveName(study->request().objective));
  summary_->setNormalisation(app::paretoNormalisationName(study->request().normalisation));
  showChoice(weights_panel_->weights());
  updateFiredRules();
  updateMonitoring();
}

std::optional<app::ParetoChoice> ParetoFeature::chooseWith(const ParetoWeights& w, bool auto_weights) {
  const auto& study = runner_->study();
  if (!study) return std::nullopt;
  try {
    app::ParetoChoiceOptions options;
    options.weights = w;
    options.requirement = engineRequirement(requirements_->requirement());
    options.auto_weights = auto_weights;
    return study->choose(options);
  } catch (const std::exception& e) {
    emit statusMessage(tr("Pareto selection: %1").arg(e.what()), 10000);
    return std::nullopt;
  }
}

// Rule 10.1 for these weights: the front view and the chart show the selected point (the operating
// point does not move: that is a commit).
void ParetoFeature::showChoice(const ParetoWeights& w) {
  choice_ = chooseWith(w, false);
  if (choice_) {
    const auto& front = runner_->study()->front();
    int selected = -1;
    if (choice_->selection.table_index) {
      const auto it = std::lower_bound(front.begin(), front.end(), *choice_->selection.table_index);
      if (it != front.end() && *it == *choice_->selection.table_index) selected = static_cast<int>(it - front.begin());
    }
    front_view_->setSelectedIndex(selected);
    summary_->setSummary(choiceSummary(*choice_));
    if (requirements_->requirement())
      requirements_->setStatus(choice_->requirement_satisfied, choice_->requirement_changed);
    else
      requirements_->clearStatus();
  }
  if (!choice_) summary_->setSummary(std::nullopt);
  showChoiceMarker();
  emit paretoShown();
}

// One undoable edit of pareto.objective or pareto.normalisation; the study is rebuilt from it.
void ParetoFeature::editParetoSetting(const QString& field, const QString& value) {
  app::Project edited = context_.project();
  if (!edited.pareto) return;
  if (field == "objective") {
    if (value != "weighted" && !edited.pareto->economics) {
      emit statusMessage(tr("pareto.objective = '%1' needs pareto.economics in the project").arg(value), 10000);
      summary_->setObjective(edited.pareto->objective.value_or("weighted"));
      return;
    }
    edited.pareto->objective = value;
  } else {
    edited.pareto->normalisation = value;
  }
  emit editRequested(edited, tr("Set pareto.%1 to %2").arg(field, value), 0);
}

// The choice on the chart when the active tool is the study's tool.
void ParetoFeature::showChoiceMarker() {
  chart_->clearMarkers(kMarkers);
  const auto& study = runner_->study();
  if (!choice_ || !study || study->request().tool != context_.activeTool()) return;
  const ParetoPoint& q = choice_->point();
  chart_->setMarker(tr("Pareto q (%1)").arg(context_.activeTool()), revPerSToRpm(q.speed_rev_per_s), q.depth_m * 1e3,
                    QColor(0, 130, 90), kMarkers);
}

// One undoable step: pareto.weights := w, then the operating point moves to the point they select
// (or to `target` when given: a clicked front point).
void ParetoFeature::commitWeights(const ParetoWeights& w, const QString& description,
                                  const std::optional<ParetoPoint>& target) {
  app::Project edited = context_.project();
  if (!edited.pareto) return;
  edited.pareto->weights = std::vector<double>{w[0], w[1], w[2], w[3]};
  weights_panel_->setWeights(w);
  showChoice(w);
  const auto& study = runner_->study();
  if (!study || !(target || choice_)) {
    emit editRequested(edited, description, 0);
    return;
  }
  const app::PickedPoint point = pickedPoint(target ? *target : choice_->point());
  context_.setActiveTool(study->request().tool);
  emit editWithPointRequested(edited, point, description);
}

void ParetoFeature::moveToChoice() {
  if (runner_->study()) commitWeights(weights_panel_->weights(), tr("Move to the Pareto choice"));
}

void ParetoFeature::onFrontPointActivated(const widgets::ParetoPointView& view) {
  const auto& study = runner_->study();
  if (!study) return;
  int index = -1;  // the front point shown as `view`
  for (std::size_t k = 0; k < study->front().size() && index < 0; ++k) {
    const widgets::ParetoPointView v = pointView(study->table().points()[study->front()[k]]);
    if (v.speed_rpm == view.speed_rpm && v.depth_mm == view.depth_mm && v.feed_mm_per_tooth == view.feed_mm_per_tooth)
      index = static_cast<int>(k);
  }
  if (index < 0) return;
  const ParetoPoint& q = study->table().points()[study->front()[static_cast<std::size_t>(index)]];
  ParetoWeights w = weights_panel_->weights();
  if (view.weights) {
    w = *view.weights;
  } else {
    // An unsupported point (non-convex part of the front): the weights of the nearest supported one.
    double best = std::numeric_limits<double>::infinity();
    const auto& scores = study->table().scores();
    const ObjectiveVector& s = scores[study->front()[static_cast<std::size_t>(index)]];
    for (std::size_t k = 0; k < study->front().size(); ++k) {
      if (!runner_->frontWeights()[k]) continue;
      double d = 0.0;
      for (std::size_t i = 0; i < kObjectiveCount; ++i) d += std::pow(scores[study->front()[k]][i] - s[i], 2);
      if (d < best) {
        best = d;
        w = *runner_->frontWeights()[k];
      }
    }
    emit statusMessage(tr("No weights select this point exactly (non-convex part of the front): the "
                          "weights of the nearest supported point are applied"),
                       10000);
  }
  commitWeights(w, tr("Move to a Pareto point"), q);
  front_view_->setSelectedIndex(index);
}

// Module VI, chatter reported by the operator (or found by the simulation): Rule 16 and a re-selection
// near the Smith-Tlusty speed; the point moves there (undoable), is recorded (source feedback) and
// simulated.
void ParetoFeature::reportChatter(double chatter_hz) {
  const auto& study = runner_->study();
  const auto q = currentParetoPoint();
  if (!study || !q) {
    emit errorRaised(tr("Chatter feedback"), tr("Pick an operating point of the Pareto tool first"));
    return;
  }
  const auto r = study->reselectAfterChatter(weights_panel_->weights(), engineRequirement(requirements_->requirement()),
                                             chatter_hz, *q);
  if (!r || !r->selection) {
    emit errorRaised(
        tr("Chatter feedback"),
        tr("No admissible point near a Smith-Tlusty speed for %1 Hz in the grid's speed range").arg(chatter_hz));
    return;
  }
  const ParetoPoint& p = r->selection->point;
  emit pointRequested(pickedPoint(p), 0);
  emit statusMessage(tr("Rule 16: chatter at %1 Hz -> N = %2 rpm (k = %3); re-selected %4 rpm, %5 mm")
                         .arg(chatter_hz, 0, 'f', 1)
                         .arg(revPerSToRpm(r->suggested_rev_per_s), 0, 'f', 0)
                         .arg(r->k)
                         .arg(revPerSToRpm(p.speed_rev_per_s), 0, 'f', 0)
                         .arg(p.depth_m * 1e3, 0, 'f', 3),
                     15000);
  recordFeedback(p);
  emit context_.simulationRequested();
}

// The active study is the Pareto one when it is built and the active tool is its pareto.tool;
// otherwise the report is Rule 6 evidence for the 2006 ranking (Module VI and Rule 6 of 2006 answer
// the same observation, each in its own study).
void ParetoFeature::routeChatterReport(double chatter_hz) {
  const auto& study = runner_->study();
  if (study && context_.activeTool() == study->request().tool) {
    reportChatter(chatter_hz);
  } else {
    emit context_.rankingChatterReported(chatter_hz);
  }
}

void ParetoFeature::onRequirementChanged() {
  if (!runner_->study()) return;
  const ParetoWeights before = weights_panel_->weights();
  const auto choice = chooseWith(before, false);
  if (!choice) return;
  if (choice->requirement_changed)
    commitWeights(choice->weights, tr("Rule 11: weights for the requirement"));
  else
    showChoice(before);
}

void ParetoFeature::onAutoWeights() {
  const auto choice = chooseWith(weights_panel_->weights(), true);
  if (!choice || !choice->ascent) return;
  requirements_->setAutoWeightsResult(choice->ascent->iterations, choice->ascent->converged);
  commitWeights(choice->weights, tr("Rule 12: automatic weights"));
}

}  // namespace mx::gui
