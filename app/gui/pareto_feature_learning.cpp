// ParetoFeature: modules VI-VII beside the chart: the Rule 14 learning database (record the operating
// point, the history view and its filters), the Rule 17 monitoring signals and the Rule 18 operator
// rules of the project.
#include <QJsonArray>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "history_view.h"
#include "learning_client.h"
#include "monitoring_panel.h"
#include "operator_rules_editor.h"
#include "pareto_feature.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "services/learning_database.h"
#include "services/pareto_rules.h"
#include "simulation/frequency_peaks.h"

namespace mx::gui {

namespace {

std::optional<double> finiteOrNone(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

widgets::HistoryRow historyRow(const app::LearningRecord& r) {
  widgets::HistoryRow row;
  row.id = r.id;
  row.time = app::learningTimeText(r.time);
  row.tool = r.tool.id;
  row.material = r.material;
  row.machine = r.machine.name.value_or(QString());
  row.source = app::learningSourceName(r.source);
  for (double w : r.weights) row.weights.append(w);
  row.speed_rpm = r.q.speed_rpm;
  row.depth_mm = r.q.depth_mm;
  row.feed_mm_per_tooth = r.q.feed_mm_per_tooth;
  auto objective = [&](const char* key) -> std::optional<double> {
    const QJsonValue v = r.objectives.value(key);
    return v.isDouble() ? finiteOrNone(v.toDouble()) : std::nullopt;
  };
  row.mrr_cm3_s = objective("mrr_cm3_s").value_or(0.0);
  row.tol = objective("tol");
  row.surf = objective("surf");
  row.ros = objective("ros");
  return row;
}

// The file path, or the URL without its options: what the status line shows.
QString shownLocation(const QString& location) {
  try {
    return app::parseLearningLocation(location).display();
  } catch (const std::invalid_argument&) {
    return location;
  }
}

bool samePoint(const ParetoPoint& a, const ParetoPoint& b) {
  return std::abs(a.speed_rev_per_s - b.speed_rev_per_s) < 1e-9 && std::abs(a.depth_m - b.depth_m) < 1e-12 &&
         std::abs(a.feed_per_tooth_m - b.feed_per_tooth_m) < 1e-12;
}

QVector<widgets::MonitoringPeak> spectrumPeaks(const SimulationSummary& summary) {
  QVector<widgets::MonitoringPeak> peaks;
  try {
    for (const FrequencyPeak& p :
         identifyPeaks(summary.spectrum_hz, summary.spectrum_n, summary.spindle_rpm / 60.0, std::max(1, summary.teeth)))
      peaks.append({p.frequency_hz, p.amplitude, QString::fromStdString(describe(p.kind)), p.harmonic});
  } catch (const std::exception&) {
    // no spectrum (too short a run): no peaks
  }
  return peaks;
}

}  // namespace

QString ParetoFeature::learningDatabasePath() const {
  return learning_db_path_.isEmpty() ? app::LearningDatabase::configuredOrDefault() : learning_db_path_;
}

void ParetoFeature::setLearningDatabasePath(const QString& path) {
  learning_db_path_ = path;
  refreshHistory();
}

bool ParetoFeature::learningIdle() const {
  return learning_->idle();
}

// The current operating point in engine form, with the Pareto objectives when the active tool is the
// study's tool and the point cuts within the study's lobes: the robustness has no value at b = 0 (a drag
// below the speed axis stops there) nor off the lobes (the chart shows speeds beyond them).
std::optional<ParetoPoint> ParetoFeature::currentParetoPoint() const {
  const auto& study = runner_->study();
  const app::PickedPoint& pt = context_.point();
  if (!study || context_.activeTool() != study->request().tool) return std::nullopt;
  const double n = rpmToRevPerS(pt.speed_rpm);
  if (!(pt.depth_mm > 0.0 && pt.feed_mm_per_tooth > 0.0 && study->grid().boundary().covers(n))) return std::nullopt;
  return study->table().evaluate(n, pt.depth_mm * 1e-3, pt.feed_mm_per_tooth * 1e-3);
}

void ParetoFeature::recordOperatingPoint() {
  const auto& study = runner_->study();
  const auto q = currentParetoPoint();
  if (!study || !q) {
    emit errorRaised(
        tr("Learning database"),
        tr("Pick an operating point of the Pareto tool '%1' first").arg(study ? study->request().tool : QString()));
    return;
  }
  // Automatic when the point is the system's Pareto choice, operator otherwise.
  const bool automatic = choice_ && samePoint(choice_->point(), *q);
  const SimulationSummary* simulation = context_.currentSimulation();  // of this point, or none
  const double eta = simulation ? simulation->eta : std::numeric_limits<double>::quiet_NaN();
  const app::LearningRecord record =
      study->learningRecord(weights_panel_->weights(), *q, std::isfinite(eta) ? eta : 0.0,
                            automatic ? app::LearningSource::Automatic : app::LearningSource::Operator);
  emit statusMessage(tr("Recording the point in %1...").arg(shownLocation(learningDatabasePath())), 0);
  learning_->record(learningDatabasePath(), record);
  refreshHistory();  // queued after the record: it shows it
}

void ParetoFeature::recordFeedback(const ParetoPoint& q) {
  feedback_records_.insert(learning_->record(
      learningDatabasePath(),
      runner_->study()->learningRecord(weights_panel_->weights(), q, 0.0, app::LearningSource::Feedback)));
  refreshHistory();
}

void ParetoFeature::connectLearning() {
  connect(learning_, &LearningClient::recorded, this, [this](quint64 generation, qint64 id, const QString& location) {
    if (feedback_records_.erase(generation) == 0)  // Rule 16 has said what it did already
      emit statusMessage(tr("Recorded point %1 in %2").arg(id).arg(location), 8000);
  });
  connect(learning_, &LearningClient::recordFailed, this, [this](quint64 generation, const QString& message) {
    if (feedback_records_.erase(generation) > 0)
      emit statusMessage(tr("Learning database: %1").arg(message), 10000);
    else {
      emit statusMessage(tr("Not recorded: %1").arg(message), 10000);
      emit errorRaised(tr("Learning database"), message);
    }
  });
  connect(learning_, &LearningClient::historyLoaded, this,
          [this](quint64, const LearningHistoryResult& result) { showHistory(result); });
  connect(learning_, &LearningClient::historyFailed, this,
          [this](quint64, const QString& message) { showHistoryError(message); });
}

void ParetoFeature::refreshHistory() {
  const widgets::HistoryFilter f = history_->filter();
  LearningHistoryRequest request;
  request.tool = f.tool;
  request.material = f.material;
  request.machine = f.machine;
  request.source = f.source;
  request.mrr_lo = f.mrr_lo;
  request.mrr_hi = f.mrr_hi;
  history_->setStatus(tr("Loading history from %1...").arg(shownLocation(learningDatabasePath())));
  learning_->loadHistory(learningDatabasePath(), request);
}

void ParetoFeature::showHistory(const LearningHistoryResult& result) {
  QVector<widgets::HistoryRow> rows;
  rows.reserve(static_cast<int>(result.records.size()));
  for (const app::LearningRecord& r : result.records) rows.append(historyRow(r));
  history_->setToolChoices(result.tools);
  history_->setMaterialChoices(result.materials);
  history_->setMachineChoices(result.machines);
  history_->setRows(rows);
  history_->setStatus(tr("%1 of %2 entries - %3").arg(rows.size()).arg(result.total).arg(result.location));
  emit historyShown();
}

void ParetoFeature::showHistoryError(const QString& message) {
  history_->setRows({});
  history_->setStatus(tr("Learning database unavailable: %1").arg(message));
  emit historyShown();
}

void ParetoFeature::onRulesEdited(const QStringList& rules) {
  app::Project edited = context_.project();
  if (rules.isEmpty())
    edited.operator_rules.reset();
  else
    edited.operator_rules = rules;
  emit editRequested(edited, tr("Edit operator rules"), 0);
}

// Rule 18 at the current point: the rules that fire for the active tool (highlighted), the
// contradictions, the fired constraints the point breaks and the advice.
void ParetoFeature::updateFiredRules() {
  const app::Project& p = context_.project();
  const QStringList rules = p.operator_rules.value_or(QStringList{});
  if (rules_editor_->rules() != rules) rules_editor_->setRules(rules);
  const app::ToolSpec* tool = p.findTool(context_.activeTool());
  if (rules.isEmpty() || !tool) {
    rules_editor_->setFiredRules({});
    rules_editor_->setNotes({});
    return;
  }
  QStringList notes;
  try {
    const app::ParetoRules r = app::evaluateParetoRules(rules, p, *tool);
    QList<int> fired;
    for (const RuleRef& ref : r.outcome.fired) fired << ref.line;
    rules_editor_->setFiredRules(fired);
    const app::PickedPoint& pt = context_.point();
    ParetoPoint q;
    if (auto pq = currentParetoPoint()) {
      q = *pq;
    } else {
      q.speed_rev_per_s = rpmToRevPerS(pt.speed_rpm);
      q.depth_m = pt.depth_mm * 1e-3;
      q.feed_per_tooth_m = pt.feed_mm_per_tooth * 1e-3;
      q.objectives[index(Objective::Mrr)] = context_.readout().mrr_mm3_per_s * 1e-9;
      q.power_w = context_.readout().peak_power_w;
    }
    for (const BoundReason& v : r.outcome.violations(app::pointVariables(q, tool->teeth)))
      notes << tr("Line %1 violated at this point: %2").arg(v.rule.line).arg(QString::fromStdString(v.rule.text));
    for (const RuleAdvice& a : r.outcome.advice)
      notes << tr("Advice (line %1): %2").arg(a.rule.line).arg(QString::fromStdString(a.message));
  } catch (const app::ProjectError& e) {
    rules_editor_->setFiredRules({});
    notes << QString::fromStdString(e.what());
  }
  rules_editor_->setNotes(notes);
}

// Rule 17: the signals of the current point (Pareto objectives, readouts) and of its simulation.
void ParetoFeature::updateMonitoring() {
  const SimulationSummary* summary = context_.currentSimulation();
  widgets::MonitoringValues v;
  const widgets::PointReadout& r = context_.readout();
  const app::Project& project = context_.project();
  if (r.valid) {
    v.peak_power_w = r.peak_power_w;
    v.mrr_cm3_s = r.mrr_mm3_per_s * 1e-3;
    if (const app::ToolSpec* t = project.findTool(context_.activeTool()))
      v.feed_velocity_mm_s = r.feed_mm_per_tooth * t->teeth * r.speed_rpm / 60.0;
  }
  if (project.machine)  // P_av at the point's speed (torque-limited below the base speed)
    v.power_limit_w = r.valid ? app::availablePowerW(project.machine, r.speed_rpm) : project.machine->spindle_power_W;
  if (const auto q = currentParetoPoint()) {
    v.tol_min = finiteOrNone(q->tol());
    v.surf_um = finiteOrNone(q->surf());
    v.ros = finiteOrNone(q->ros());
  }
  if (summary) {
    v.peak_force_n = summary->peak_force_n;
    v.peak_power_w = summary->peak_power_w;
    v.eta = summary->eta;
    v.chip_ratio = summary->chip_ratio;
    v.tooth_passing_hz = summary->tooth_passing_hz;
    v.chatter = summary->chatter;
    v.chatter_frequency_hz = summary->chatter_frequency_hz;
    monitoring_->setPeaks(spectrumPeaks(*summary));
  } else {
    monitoring_->setPeaks({});  // the last run's peaks are of another point
  }
  monitoring_->setValues(v);
}

}  // namespace mx::gui
