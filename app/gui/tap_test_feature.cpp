#include "tap_test_feature.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <algorithm>

#include "document/frf_paths.h"
#include "engine_task.h"
#include "feature_dock.h"
#include "frf_plot_view.h"
#include "services/frf_export.h"
#include "services/frf_import.h"
#include "services/measured_dynamics.h"
#include "tap_test_panel.h"

namespace mx::gui {

namespace {

FrfDirection directionOf(const QString& name) {
  return name == "y" ? FrfDirection::Y : FrfDirection::X;
}

QString directionName(FrfDirection d) {
  return QString::fromLatin1(frfDirectionName(d).data());
}

// The first FRF whose response and reference are `direction`, else the first.
int datasetFor(const FrfFile& file, FrfDirection direction) {
  for (std::size_t i = 0; i < file.datasets.size(); ++i) {
    const FrfDataset& d = file.datasets[i];
    if (d.response_direction == direction && d.reference_direction == direction) return static_cast<int>(i);
  }
  return 0;
}

std::vector<app::ModeSpec> modeSpecs(const ModalAxis& modes) {
  std::vector<app::ModeSpec> out;
  for (const Mode& m : modes)
    out.push_back({m.natural_frequency_hz, 100.0 * m.damping_ratio, 1e-6 * m.stiffness_n_per_m, {}});
  return out;
}

}  // namespace

TapTestFeature::TapTestFeature(QMainWindow* window, FeatureContext& context)
    : WindowFeature(window),
      window_(window),
      context_(context),
      runner_(new TapTestRunner(context.enginePool(), this)),
      panel_(new widgets::TapTestPanel(window)) {
  setObjectName("tapTestFeature");
  QDockWidget* dock = makeFeatureDock(window, tr("Tap test"), "tapTestDock", panel_, DockContent::Scrolling);
  window->addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* simulation = window->findChild<QDockWidget*>("simulationDock")) window->tabifyDockWidget(simulation, dock);
  connect(runner_, &TapTestRunner::loaded, this, &TapTestFeature::onLoaded);
  connect(runner_, &TapTestRunner::fitted, this, &TapTestFeature::onFitted);
  connect(runner_, &TapTestRunner::failed, this, [this](quint64 generation, const QString& message) {
    pending_.erase(generation);
    panel_->setBusy(runner_->busy());
    panel_->setMessage(message);
    emit statusMessage(tr("Tap test: %1").arg(message), 10000);
  });
  connect(runner_, &TapTestRunner::cancelled, this, [this](quint64) { panel_->setMessage(tr("Fit cancelled")); });
  connect(runner_, &TapTestRunner::progress, panel_, &widgets::TapTestPanel::setProgress);
  connect(runner_, &TapTestRunner::busyChanged, panel_, &widgets::TapTestPanel::setBusy);
  connect(panel_, &widgets::TapTestPanel::fitRequested, this, &TapTestFeature::onFitRequested);
  connect(panel_, &widgets::TapTestPanel::cancelRequested, runner_, &TapTestRunner::cancel);
  connect(panel_, &widgets::TapTestPanel::acceptRequested, this, &TapTestFeature::accept);
  connect(&context_, &FeatureContext::activeToolChanged, this, &TapTestFeature::showToolFrfs);
}

void TapTestFeature::projectChanged(const app::Project& /*project*/, Features recompute) {
  if (recompute & Feature::TapTest) showToolFrfs();
}

void TapTestFeature::projectReplaced() {
  ++fit_generation_;
  runner_->forgetLoads();
  pending_.clear();
  for (const auto& [direction, m] : measurements_) panel_->clearMeasurement(direction);
  measurements_.clear();
}

void TapTestFeature::stop() {
  runner_->cancel();
}

void TapTestFeature::addFileActions(QMenu* file, QToolBar* /*toolbar*/) {
  QAction* import = file->addAction(tr("Import &tap test..."));
  import->setShortcut(QKeySequence(tr("Ctrl+T")));
  import->setStatusTip(tr("Read a tap-test FRF (UFF 58/58b or CSV) for x or y and fit its modes"));
  connect(import, &QAction::triggered, this, &TapTestFeature::chooseImport);
  QAction* exporter = file->addAction(tr("Export &FRF..."));
  exporter->setStatusTip(tr("Write the measured receptance of the shown direction as UFF 58/58b or CSV"));
  connect(exporter, &QAction::triggered, this, &TapTestFeature::exportFrf);
}

void TapTestFeature::chooseImport() {
  const QString path = QFileDialog::getOpenFileName(window_, tr("Import tap test"),
                                                    context_.document().filePath().isEmpty()
                                                        ? QDir::homePath()
                                                        : QFileInfo(context_.document().filePath()).absolutePath(),
                                                    tr("Tap tests (*.uff *.unv *.uf *.csv);;All files (*)"));
  if (path.isEmpty()) return;
  bool ok = false;
  const QString direction = QInputDialog::getItem(window_, tr("Import tap test"), tr("Direction of the tool tip:"),
                                                  {"x", "y"}, 0, false, &ok);
  if (!ok) return;
  std::optional<FrfQuantity> quantity;
  if (path.endsWith(".csv", Qt::CaseInsensitive)) {
    const QString q =
        QInputDialog::getItem(window_, tr("Import tap test"), tr("The CSV's values are (SI units per newton):"),
                              {"receptance", "mobility", "accelerance"}, 2, false, &ok);
    if (!ok) return;
    quantity = app::frfQuantityFromName(tr("quantity"), q);
  }
  importFile(path, direction, std::nullopt, quantity);
}

void TapTestFeature::importFile(const QString& path, const QString& direction, std::optional<int> dataset,
                                std::optional<FrfQuantity> quantity) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const quint64 generation = runner_->load(absolute, quantity);
  pending_[generation] = {direction, absolute, dataset};
}

void TapTestFeature::onLoaded(quint64 generation, const TapTestFile& file) {
  const auto it = pending_.find(generation);
  if (it == pending_.end()) return;
  const PendingImport pending = it->second;
  pending_.erase(it);
  const FrfDirection axis = directionOf(pending.direction);
  const int index = pending.dataset.value_or(datasetFor(file.file, axis));
  try {
    Measurement m{file.path, index, file.quantity, app::frfReceptance(file.file, file.path, index), std::nullopt};
    if (file.file.format != FrfFormat::Csv &&
        (m.receptance.direction != axis || m.receptance.reference_direction != axis)) {
      panel_->setMessage(
          tr("%1: dataset %2 is a %3/%4 FRF: import it as %3")
              .arg(file.path)
              .arg(index)
              .arg(directionName(m.receptance.direction), directionName(m.receptance.reference_direction)));
      return;
    }
    if (file.file.format == FrfFormat::Csv) m.receptance.direction = m.receptance.reference_direction = axis;
    panel_->setMeasurement(pending.direction, m.receptance.frequency_hz, m.receptance.h_m_per_n);
    measurements_[pending.direction] = std::move(m);
  } catch (const std::exception& e) {
    panel_->setMessage(QString::fromStdString(e.what()));
    return;
  }
  panel_->setMessage(tr("%1 (%2): dataset %3 of %4")
                         .arg(QFileInfo(file.path).fileName(), pending.direction)
                         .arg(index)
                         .arg(file.file.datasets.size()));
  if (auto* dock = window_->findChild<QDockWidget*>("tapTestDock")) dock->raise();
  emit measurementShown(pending.direction);
}

void TapTestFeature::onFitRequested(const widgets::TapTestFitRequest& request) {
  const auto it = measurements_.find(request.direction);
  if (it == measurements_.end()) {
    panel_->setMessage(tr("No tap test for %1: File > Import tap test").arg(request.direction));
    return;
  }
  fit_generation_ = runner_->fit(it->second.receptance, request);
}

void TapTestFeature::onFitted(quint64 generation, const TapTestFit& fit) {
  if (generation != fit_generation_) return;
  const auto it = measurements_.find(fit.direction);
  if (it == measurements_.end()) return;
  it->second.fit = fit.result;
  panel_->setFitResult(fit.direction, fit.result, fit.at_poles);
  panel_->setMessage(tr("%1: %2 mode(s), fit error %3 % (%4)")
                         .arg(fit.direction)
                         .arg(fit.result.modes.size())
                         .arg(fit.result.fit_error_pct, 0, 'f', 2)
                         .arg(QString::fromStdString(fit.result.method)));
  emit fitShown(fit.direction);
}

QString TapTestFeature::relativeToProject(const QString& absolute) const {
  const QString project = context_.document().filePath();
  if (project.isEmpty()) return absolute;  // saving the project names it relative to the new folder
  return QDir(QFileInfo(project).absolutePath()).relativeFilePath(absolute);
}

std::optional<app::Project> TapTestFeature::acceptedProject(const QString& direction, QString* why) const {
  const auto it = measurements_.find(direction);
  app::Project edited = context_.project();
  auto tool = std::find_if(edited.tools.begin(), edited.tools.end(),
                           [this](const app::ToolSpec& t) { return t.id == context_.activeTool(); });
  if (tool == edited.tools.end()) {
    *why = tr("no active tool");
    return std::nullopt;
  }
  if (it == measurements_.end() || !it->second.fit) {
    *why = tr("no fit for %1: import a tap test and fit it first").arg(direction);
    return std::nullopt;
  }
  const Measurement& m = it->second;
  app::FrfRefSpec ref{relativeToProject(m.path), m.dataset, std::nullopt, {}};
  if (m.quantity) ref.quantity = QString::fromLatin1(frfQuantityName(*m.quantity).data());
  (direction == "y" ? tool->modes_y : tool->modes_x) = modeSpecs(m.fit->modes);
  (direction == "y" ? tool->frf_y : tool->frf_x) = ref;
  return edited;
}

void TapTestFeature::accept(const QString& direction) {
  QString why;
  const std::optional<app::Project> edited = acceptedProject(direction, &why);
  if (!edited) {
    panel_->setMessage(why);
    return;
  }
  emit editRequested(*edited, tr("Accept the tap-test fit of %1 (tool %2)").arg(direction, context_.activeTool()), 0);
}

// The active tool's own FRFs, when the view does not show them yet.
void TapTestFeature::showToolFrfs() {
  const app::ToolSpec* tool = context_.project().findTool(context_.activeTool());
  if (!tool) return;
  for (const auto& [direction, ref] : {std::pair{QString("x"), tool->frf_x}, {QString("y"), tool->frf_y}}) {
    if (!ref) continue;
    const QString path = app::resolvedFrfPath(context_.project(), *ref);
    const auto shown = measurements_.find(direction);
    if (shown != measurements_.end() && shown->second.path == path && shown->second.dataset == ref->datasetIndex())
      continue;
    const PendingImport wanted{direction, path, ref->datasetIndex()};
    const bool loading = std::any_of(pending_.begin(), pending_.end(), [&wanted](const auto& p) {
      return p.second.direction == wanted.direction && p.second.path == wanted.path &&
             p.second.dataset == wanted.dataset;
    });
    if (loading) continue;
    std::optional<FrfQuantity> quantity;
    try {
      if (ref->quantity) quantity = app::frfQuantityFromName("quantity", *ref->quantity);
    } catch (const std::exception&) {
      continue;  // the document validates the name; nothing to show otherwise
    }
    importFile(path, direction, ref->datasetIndex(), quantity);
  }
}

void TapTestFeature::exportFrf() {
  const QString direction = panel_->currentDirection();
  const auto it = measurements_.find(direction);
  if (it == measurements_.end()) {
    emit errorRaised(tr("Export FRF"), tr("No tap test for %1: File > Import tap test").arg(direction));
    return;
  }
  QString selected;
  const QString path =
      QFileDialog::getSaveFileName(window_, tr("Export FRF (%1)").arg(direction), QString(),
                                   tr("UFF 58 ASCII (*.uff);;UFF 58b binary (*.uff);;CSV (*.csv)"), &selected);
  if (path.isEmpty()) return;
  const FrfFormat format = selected.startsWith("CSV")       ? FrfFormat::Csv
                           : selected.startsWith("UFF 58b") ? FrfFormat::Uff58b
                                                            : FrfFormat::Uff58;
  FrfDataset dataset = fromReceptance(it->second.receptance, FrfQuantity::Receptance,
                                      QString("%1 %2").arg(context_.activeTool(), direction).toStdString());
  runEngineTask<bool>(
      export_channel_, context_.enginePool(),
      [path, format, dataset = std::move(dataset)] {
        app::saveFrfFile(path, format, {dataset});
        return true;
      },
      [this, path, direction](const TaskResult<bool>& r) {
        if (r.error.isEmpty()) {
          emit statusMessage(tr("FRF of %1 written to %2").arg(direction, path), 5000);
        } else {
          emit errorRaised(tr("Export FRF"), r.error);
        }
      });
}

}  // namespace mx::gui
