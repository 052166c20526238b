#include "batch_feature.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QThread>
#include <algorithm>

#include "batch_study_dialog.h"
#include "display_units.h"
#include "services/batch_merge.h"
#include "services/material_library.h"
#include "services/service_errors.h"

namespace mx::gui {

namespace {

constexpr int kPollMs = 250;

// The project's material first, then the library's other names.
QStringList materialNames(const app::Project& project, const std::vector<app::MaterialEntry>& library) {
  QStringList names;
  if (project.material) names << project.material->name;
  for (const app::MaterialEntry& e : library)
    if (!names.contains(e.name)) names << e.name;
  return names;
}

std::optional<app::MaterialSpec> materialNamed(const app::Project& project,
                                               const std::vector<app::MaterialEntry>& library, const QString& name) {
  if (project.material && project.material->name == name) return *project.material;
  for (const app::MaterialEntry& e : library)
    if (e.name == name) return app::materialSpecOf(e);
  return std::nullopt;
}

}  // namespace

BatchFeature::BatchFeature(QMainWindow* window, FeatureContext& context)
    : WindowFeature(window), context_(context), window_(window), channel_(this) {
  setObjectName("batchFeature");
  poll_.setInterval(kPollMs);
  connect(&poll_, &QTimer::timeout, this, &BatchFeature::pollProgress);
}

BatchFeature::~BatchFeature() {
  stop();
}

void BatchFeature::projectChanged(const app::Project& /*project*/, Features /*recompute*/) {
  // The dialog's lists are filled from the project each time it opens; a running study has its own
  // snapshot.
}

void BatchFeature::stop() {
  if (!process_) return;
  cancelRun();
  process_->waitForFinished(5000);
}

void BatchFeature::addFileActions(QMenu* file, QToolBar* /*toolbar*/) {
  QAction* a = file->addAction(tr("&Batch study..."));
  a->setToolTip(
      tr("Write a batch manifest from this project, its tools and the material library; run it here "
         "or on a cluster, and open merged results"));
  a->setStatusTip(a->toolTip());
  connect(a, &QAction::triggered, this, [this] { openDialog(); });
}

QString BatchFeature::cliProgram() const {
  if (!cli_program_.isEmpty()) return cli_program_;
  const QDir here(QCoreApplication::applicationDirPath());
  const QString beside = here.filePath("millexpert-cli");
  return QFileInfo::exists(beside) ? beside : QDir::cleanPath(here.filePath("../millexpert-cli"));
}

widgets::BatchStudyDialog* BatchFeature::openDialog() {
  if (!dialog_) {
    dialog_ = new widgets::BatchStudyDialog(window_);
    connect(dialog_, &widgets::BatchStudyDialog::saveRequested, this, &BatchFeature::askToSave);
    connect(dialog_, &widgets::BatchStudyDialog::runRequested, this, &BatchFeature::askToRun);
    connect(dialog_, &widgets::BatchStudyDialog::cancelRequested, this, &BatchFeature::cancelRun);
    connect(dialog_, &widgets::BatchStudyDialog::openResultsRequested, this, &BatchFeature::askForResults);
    connect(dialog_, &widgets::BatchStudyDialog::addMachinesRequested, this, &BatchFeature::askForMachines);
  }
  if (!running()) {
    const app::Project& p = context_.project();
    widgets::BatchStudyChoices choices;
    for (const app::ToolSpec& t : p.tools) choices.tools << t.id;
    choices.materials = materialNames(p, app::bundledMaterialLibrary());
    listProjectMachine();
    for (const ListedMachine& m : machines_) choices.machines << m.label;
    choices.max_jobs = std::max(1, QThread::idealThreadCount());
    choices.project_name = context_.document().filePath().isEmpty()
                               ? tr("unsaved project")
                               : QFileInfo(context_.document().filePath()).fileName();
    dialog_->setChoices(choices);
  }
  dialog_->show();
  dialog_->raise();
  return dialog_;
}

app::BatchStudyRequest BatchFeature::requestOf(const widgets::BatchStudySettings& s) const {
  app::BatchStudyRequest r;
  r.computation = s.computation;
  r.tools = s.tools;
  const std::vector<app::MaterialEntry> library = app::bundledMaterialLibrary();  // parsed once
  for (const QString& name : s.materials)
    if (auto m = materialNamed(context_.project(), library, name)) r.materials.push_back(*m);
  r.machines = checkedMachines(s.machines);
  if (s.computation == "lobes")
    r.options = QJsonObject{{"from", s.from_rpm}, {"to", s.to_rpm}, {"step", s.step_rpm}, {"method", s.method}};
  return r;
}

bool BatchFeature::saveStudy(const widgets::BatchStudySettings& settings, const QString& manifest_path) {
  try {
    const app::BatchStudyFiles files = app::writeBatchStudy(context_.project(), requestOf(settings), manifest_path);
    manifest_path_ = manifest_path;
    total_ = files.cases;
    const QString text = tr("Wrote %1 (%2 cases) and the project snapshot %3")
                             .arg(QDir::toNativeSeparators(files.manifest))
                             .arg(files.cases)
                             .arg(QFileInfo(files.project).fileName());
    if (dialog_) dialog_->setStatus(text);
    emit statusMessage(text, 8000);
    return true;
  } catch (const std::exception& e) {
    if (dialog_) dialog_->setStatus(QString::fromStdString(e.what()));
    emit errorRaised(tr("Batch study"), QString::fromStdString(e.what()));
    return false;
  }
}

bool BatchFeature::runStudy(const widgets::BatchStudySettings& settings, const QString& manifest_path) {
  if (running() || !saveStudy(settings, manifest_path)) return false;
  results_path_ = app::batchStudyResultsPath(manifest_path);
  results_offset_ = 0;
  done_ = 0;
  cancelled_ = false;
  process_ = new QProcess(this);
  process_->setProcessChannelMode(QProcess::SeparateChannels);
  connect(process_, &QProcess::finished, this, &BatchFeature::onProcessFinished);
  process_->start(cliProgram(), {"batch", manifest_path, "--out", results_path_, "--jobs",
                                 QString::number(std::max(1, settings.jobs))});
  if (!process_->waitForStarted(10000)) {
    const QString why = tr("Cannot start %1: %2").arg(cliProgram(), process_->errorString());
    process_->deleteLater();
    process_ = nullptr;
    emit errorRaised(tr("Batch study"), why);
    return false;
  }
  if (dialog_) {
    dialog_->setRunning(true);
    dialog_->setProgress(0, total_);
    dialog_->setStatus(tr("Running %1 cases with %2 jobs into %3...")
                           .arg(total_)
                           .arg(settings.jobs)
                           .arg(QDir::toNativeSeparators(results_path_)));
  }
  pollProgress();
  poll_.start();
  return true;
}

void BatchFeature::cancelRun() {
  if (!process_) return;
  cancelled_ = true;
  process_->kill();  // each finished case is a whole line: a new run resumes after it
}

// Counts the result lines written since the last poll: only the new bytes are read.
void BatchFeature::pollProgress() {
  QFile f(results_path_);
  if (!f.open(QIODevice::ReadOnly)) return;
  if (f.size() < results_offset_) results_offset_ = 0;  // rewritten (a torn line redone)
  if (!f.seek(results_offset_)) return;
  const QByteArray added = f.read(f.size() - results_offset_);
  const qsizetype complete = added.lastIndexOf('\n') + 1;
  done_ += added.left(complete).count('\n');
  results_offset_ += complete;
  if (dialog_) dialog_->setProgress(done_, total_);
}

void BatchFeature::onProcessFinished(int exit_code, QProcess::ExitStatus status) {
  poll_.stop();
  pollProgress();
  const QString errors = QString::fromUtf8(process_->readAllStandardError()).trimmed();
  process_->deleteLater();
  process_ = nullptr;
  const bool crashed = status != QProcess::NormalExit;
  QString text;
  if (cancelled_)
    text = tr("Cancelled after %1 of %2 cases; Run here again resumes with the next case.").arg(done_).arg(total_);
  else if (crashed)
    text = tr("millexpert-cli batch stopped after %1 of %2 cases: %3").arg(done_).arg(total_).arg(errors);
  else if (exit_code == 0)
    text = tr("Done: %1 cases in %2.").arg(total_).arg(QDir::toNativeSeparators(results_path_));
  else if (exit_code == 1)
    text = tr("Done: %1 cases; some failed (their rows carry the error).").arg(total_);
  else
    text = tr("The batch refused its input: %1").arg(errors);
  if (dialog_) {
    dialog_->setRunning(false);
    dialog_->setStatus(text);
  }
  emit statusMessage(text, 10000);
  emit runFinished(crashed ? -1 : exit_code, cancelled_);
  if (!cancelled_ && !crashed && exit_code <= 1) showResults({results_path_});
}

void BatchFeature::showResults(const QStringList& files) {
  const quint64 generation = ++merge_generation_;
  if (dialog_) dialog_->setStatus(tr("Merging %1 results file(s)...").arg(files.size()));
  channel_.start(context_.enginePool(), [this, files, generation](const EngineReply& reply) {
    QJsonObject summary;
    QString error;
    try {
      summary = app::mergeBatchResults(files);
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    const std::vector<QStringList> lines = error.isEmpty() ? app::batchTableLines(summary) : std::vector<QStringList>{};
    reply([this, summary, lines, error, generation] {
      if (generation != merge_generation_) return;  // a newer merge was asked for
      if (!error.isEmpty()) {
        if (dialog_) dialog_->setStatus(error);
        emit errorRaised(tr("Batch results"), error);
        return;
      }
      if (dialog_) {
        dialog_->setResults(app::batchTableHeader(), lines);
        dialog_->setStatus(tr("%1: %2 cases in %3 rows (%4 failed, %5 duplicates)")
                               .arg(summary.value("computation").toString())
                               .arg(summary.value("cases").toInteger())
                               .arg(summary.value("rows").toArray().size())
                               .arg(summary.value("failed").toInteger())
                               .arg(summary.value("duplicates").toInteger()));
      }
      emit resultsShown(static_cast<int>(lines.size()));
    });
  });
}

void BatchFeature::askToSave(const widgets::BatchStudySettings& settings) {
  const QString path = QFileDialog::getSaveFileName(dialog_, tr("Save batch manifest"),
                                                    manifest_path_.isEmpty() ? "batch-study.json" : manifest_path_,
                                                    tr("Batch manifest (*.json)"));
  if (!path.isEmpty()) saveStudy(settings, path);
}

void BatchFeature::askToRun(const widgets::BatchStudySettings& settings) {
  const QString path = QFileDialog::getSaveFileName(dialog_, tr("Batch manifest to run (results beside it, .jsonl)"),
                                                    manifest_path_.isEmpty() ? "batch-study.json" : manifest_path_,
                                                    tr("Batch manifest (*.json)"));
  if (!path.isEmpty()) runStudy(settings, path);
}

// The machine sections of the checked labels; none when only the project's own is checked, so that
// each case keeps the project's machine.
std::vector<app::MachineSpec> BatchFeature::checkedMachines(const QStringList& labels) const {
  std::vector<app::MachineSpec> machines;
  if (labels.size() == 1 && !machines_.empty() && labels.front() == machines_.front().label) return machines;
  for (const QString& label : labels) {
    const ListedMachine* listed = listedMachine(label);
    if (!listed) throw app::InputError(QString("batch study: machine '%1' is not listed").arg(label));
    if (!listed->machine)
      throw app::InputError(
          "batch study: the project has no machine section, so its own machine cannot be a case beside other "
          "machines; uncheck it or give the project a machine");
    machines.push_back(*listed->machine);
  }
  return machines;
}

const BatchFeature::ListedMachine* BatchFeature::listedMachine(const QString& label) const {
  const auto it =
      std::find_if(machines_.begin(), machines_.end(), [&label](const ListedMachine& m) { return m.label == label; });
  return it == machines_.end() ? nullptr : &*it;
}

// The project's own machine as the first entry of the list; the machines added from files stay.
void BatchFeature::listProjectMachine() {
  const app::Project& p = context_.project();
  ListedMachine own{p.machine ? machineLabel(*p.machine, tr("this project"))
                              : tr("this project's (no machine section: no power limit)"),
                    p.machine};
  if (machines_.empty())
    machines_.push_back(std::move(own));
  else
    machines_.front() = std::move(own);
}

// "DMU-50: 15.0 kW, max 18000 rpm, 120 N·m (cell-3.mxproj)": what a machinist tells machines apart by.
QString BatchFeature::machineLabel(const app::MachineSpec& m, const QString& origin) const {
  const widgets::ShopUnits& units = widgets::DisplayUnits::of(context_.units());
  QStringList limits{units.format(widgets::Quantity::Power, m.spindle_power_W)};
  if (m.max_spindle_rpm) limits << tr("max %1 rpm").arg(*m.max_spindle_rpm, 0, 'f', 0);
  if (m.max_torque_Nm) limits << tr("%1 N\u00b7m").arg(*m.max_torque_Nm, 0, 'g', 4);
  return tr("%1: %2 (%3)").arg(m.name.value_or(tr("unnamed machine")), limits.join(", "), origin);
}

void BatchFeature::addMachinesFrom(const QStringList& files) {
  if (dialog_) dialog_->setStatus(tr("Reading the machines of %1 project file(s)...").arg(files.size()));
  channel_.start(context_.enginePool(), [this, files](const EngineReply& reply) {
    QStringList problems;
    const std::vector<app::MachineOfProject> read = app::machinesOfProjects(files, &problems);
    reply([this, read, problems] {
      QStringList added;
      for (const app::MachineOfProject& m : read) {
        const QString label = machineLabel(m.machine, QFileInfo(m.file).fileName());
        if (listedMachine(label)) continue;
        machines_.push_back({label, m.machine});
        added << label;
      }
      QString text = tr("%n machine(s) added.", nullptr, static_cast<int>(added.size()));
      if (!problems.isEmpty()) text += ' ' + tr("Not added: %1").arg(problems.join("; "));
      if (dialog_) {
        dialog_->addMachines(added);
        dialog_->setStatus(text);
      }
      if (!problems.isEmpty()) emit statusMessage(text, 10000);
      emit machinesAdded(static_cast<int>(added.size()));
    });
  });
}

void BatchFeature::askForMachines() {
  const QStringList files = QFileDialog::getOpenFileNames(dialog_, tr("Machines of other project files"),
                                                          QFileInfo(context_.document().filePath()).absolutePath(),
                                                          tr("MillExpert projects (*.mxproj)"));
  if (!files.isEmpty()) addMachinesFrom(files);
}

void BatchFeature::askForResults() {
  const QStringList files = QFileDialog::getOpenFileNames(
      dialog_, tr("Open batch results"), QFileInfo(manifest_path_).absolutePath(), tr("Batch results (*.jsonl)"));
  if (!files.isEmpty()) showResults(files);
}

}  // namespace mx::gui
