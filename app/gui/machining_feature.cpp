#include "machining_feature.h"

#include <QDateTime>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <cmath>
#include <optional>

#include "document/output_file.h"
#include "engine_task.h"
#include "feature_dock.h"
#include "gcode/gcode_reader.h"
#include "notice_stack.h"
#include "part_program_panel.h"
#include "services/sdnrp_request.h"
#include "surface_finish_panel.h"

namespace mx::gui {

namespace {

std::optional<double> finiteOr(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// A proposed F or S that stays in effect on the following blocks until one has its own word (modal).
struct ModalProposal {
  std::optional<double> value;
  int line = 0;
  // The value in effect at a block: its own proposal, none when it carries its own word, else the modal.
  std::optional<double> at(std::optional<double> proposed, bool own_word, int block_line) {
    if (proposed) {
      value = proposed;
      line = block_line;
      return proposed;
    }
    if (own_word) value.reset();
    return value;
  }
  int inheritedAt(std::optional<double> proposed) const { return proposed || !value ? 0 : line; }
};

// One display row per block: F in the program's units per minute, S in rpm. The new F and S are those in
// effect at the block: where a block has no word of its own, the one proposed on an earlier line.
QVector<widgets::PartProgramRow> partProgramRows(const PartProgramOverrideResult& r) {
  QVector<widgets::PartProgramRow> rows;
  rows.reserve(static_cast<qsizetype>(r.program.blocks.size()));
  std::vector<const FeedOverrideRow*> by_block(r.program.blocks.size(), nullptr);
  for (const FeedOverrideRow& f : r.rows)
    if (f.block >= 1 && f.block <= by_block.size()) by_block[f.block - 1] = &f;
  ModalProposal feed, speed;
  for (std::size_t i = 0; i < r.program.blocks.size(); ++i) {
    const GcodeBlock& b = r.program.blocks[i];
    const GcodeMotion& m = r.run.motions[i];
    const GcodeBlockEdit& e = r.edits[i];
    const double unit = m.inch ? 0.0254 : 1e-3;
    widgets::PartProgramRow row;
    row.line = b.line;
    row.text = QString::fromStdString(b.text);
    if (m.isFeedMove() || m.feed_word) row.original_feed = finiteOr(m.feed_m_per_s * 60.0 / unit);
    const std::optional<double> new_feed = finiteOr(e.feed), new_speed = finiteOr(e.speed_rpm);
    const std::optional<double> feed_in_effect = feed.at(new_feed, m.feed_word, b.line);
    const std::optional<double> speed_in_effect = speed.at(new_speed, m.speed_word, b.line);
    if (row.original_feed) {
      row.new_feed = feed_in_effect;
      row.new_feed_from_line = feed.inheritedAt(new_feed);
    }
    if (m.isFeedMove() || m.speed_word) row.speed_rpm = finiteOr(m.speed_rev_per_s * 60.0);
    if (row.speed_rpm) {
      row.new_speed_rpm = speed_in_effect;
      row.new_speed_from_line = speed.inheritedAt(new_speed);
    }
    if (m.isFeedMove()) row.depth_mm = r.depths_m[i] * 1e3;
    if (const FeedOverrideRow* f = by_block[i]) {
      row.predicted_force_n = finiteOr(f->predicted_force_N);
      row.reason = QString::fromStdString(f->reason);
    }
    if (row.reason.isEmpty() && !e.comment.empty()) row.reason = QString::fromStdString(e.comment).remove("MX: ");
    row.changed = !e.empty();
    rows.append(row);
  }
  return rows;
}

// The SDNRP run and, when compared, the same run without SDNRP.
struct SurfaceFinishRuns {
  SdnrpResult controlled;
  std::optional<SdnrpResult> baseline;
};

// Shop units on the panel: Ra in um, feed in mm/min, speed in rpm.
QVector<widgets::SurfaceFinishSample> panelSamples(const SdnrpResult& v) {
  QVector<widgets::SurfaceFinishSample> samples;
  samples.reserve(static_cast<qsizetype>(v.samples.size()));
  for (const SdnrpSample& x : v.samples)
    samples.append({x.t_s, x.ra_m * 1e6, x.ra_dynamic_m * 1e6, x.force_N, x.force_dynamic_N, x.feed_m_per_s * 60e3,
                    x.speed_rev_per_s * 60.0});
  return samples;
}

widgets::SurfaceFinishSummary panelSummary(const SdnrpResult& v) {
  return {
      v.ra_desired_m * 1e6,  v.fd_N,          v.f_final_N, v.feed_final_m_per_s * 60e3, v.speed_final_rev_per_s * 60.0,
      v.ra_produced_m * 1e6, v.feed_saturated};
}

// A device, FIFO or directory chosen in the dialog is refused, not replaced (document/output_file.h).
bool writeAtomically(const QString& path, const QByteArray& bytes, QString* error) {
  *error = app::writeFileAtomically(path, bytes);
  return error->isEmpty();
}

}  // namespace

MachiningFeature::MachiningFeature(QMainWindow* window, const FeatureContext& context)
    : WindowFeature(window),
      window_(window),
      document_(context.document()),
      pool_(context.enginePool()),
      channel_(this),
      surface_panel_(new widgets::SurfaceFinishPanel),
      surface_notice_(new widgets::NoticeStack(surface_panel_)),
      program_panel_(new widgets::PartProgramPanel) {
  setObjectName("machiningFeature");
  surface_notice_->setObjectName("surfaceFinishNotice");
  surface_panel_->setUnits(context.units());
  program_panel_->setUnits(context.units());
  units_ = context.units();
  addDocks();
  connectPanels();
}

void MachiningFeature::addDocks() {
  QDockWidget* surface = makeFeatureDock(window_, tr("Surface finish (SDNRP)"), "surfaceFinishDock", surface_notice_,
                                         DockContent::Scrolling);
  QDockWidget* program =
      makeFeatureDock(window_, tr("Part program"), "partProgramDock", program_panel_, DockContent::Scrolling);
  window_->addDockWidget(Qt::BottomDockWidgetArea, surface);
  window_->addDockWidget(Qt::BottomDockWidgetArea, program);
  if (auto* control = window_->findChild<QDockWidget*>("controlDock")) {
    window_->tabifyDockWidget(control, surface);
    window_->tabifyDockWidget(surface, program);
  }
  if (auto* simulation = window_->findChild<QDockWidget*>("simulationDock")) simulation->raise();
}

void MachiningFeature::connectPanels() {
  connect(surface_panel_, &widgets::SurfaceFinishPanel::runRequested, this, &MachiningFeature::runSurfaceFinish);
  connect(surface_notice_, &widgets::NoticeStack::actionTriggered, this, &MachiningFeature::addSdnrpSection);
  connect(program_panel_, &widgets::PartProgramPanel::openRequested, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        window_, tr("Open part program"), QString(),
        tr("Part programs (*.nc *.ngc *.tap *.gcode *.h *.H *.mpf *.MPF *.spf *.SPF);;All files (*)"));
    if (!path.isEmpty()) openPartProgram(path);
  });
  connect(program_panel_, &widgets::PartProgramPanel::exportProgramRequested, this, [this] {
    const QString path = QFileDialog::getSaveFileName(window_, tr("Export optimised program"), QString(),
                                                      tr("Part programs (*.nc *.ngc *.h *.mpf);;All files (*)"));
    if (!path.isEmpty()) exportPartProgram(path);
  });
  connect(program_panel_, &widgets::PartProgramPanel::exportAfcRequested, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(window_, tr("Export AFC table"), "AFC.TAB", tr("Heidenhain table (*.TAB *.tab)"));
    if (!path.isEmpty()) exportAfcTable(path);
  });
  connect(program_panel_, &widgets::PartProgramPanel::dialectChanged, this, [this] {
    if (!override_path_.isEmpty()) openPartProgram(override_path_);
  });
  connect(program_panel_, &widgets::PartProgramPanel::exportCsvRequested, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(window_, tr("Export feed overrides"), QString(), tr("CSV (*.csv)"));
    if (!path.isEmpty()) exportPartProgramCsv(path);
  });
}

void MachiningFeature::projectChanged(const app::Project& project, Features recompute) {
  if ((recompute & Feature::PartProgram) && !override_path_.isEmpty()) openPartProgram(override_path_);
  if (!(recompute & Feature::SurfaceFinish)) return;
  if (!project.sdnrp) {
    surface_notice_->showNotice(
        tr("This project has no surface-finish section (\"sdnrp\"). The SDNRP loop of Cus and Zuperl would run "
           "on their defaults: R_a 0.81 \u00b5m for 15 s, from the speed and feed their model picks."),
        tr("Add an SDNRP section with these defaults"));
    return;
  }
  surface_notice_->showContent();
  try {
    const SdnrpSettings s = app::sdnrpSettingsFromProject(project);
    surface_panel_->setDesiredRaUm(s.ra_desired_m * 1e6);
    surface_panel_->setDisturbanceOn(s.disturbance.enabled);
    surface_panel_->setDurationS(s.duration_s);
  } catch (const std::exception&) {
    // an invalid sdnrp section is reported when the loop is run
  }
}

// The defaults made explicit (SdnrpSettings), so that the panel and the file show what runs.
void MachiningFeature::addSdnrpSection() {
  app::Project edited = document_.project();
  if (edited.sdnrp) return;
  const SdnrpSettings defaults;
  app::SdnrpSection section;
  section.ra_um = defaults.ra_desired_m * 1e6;
  section.seconds = defaults.duration_s;
  edited.sdnrp = section;
  emit editRequested(edited, tr("Add a surface-finish section"), 0);
}

void MachiningFeature::runSurfaceFinish() {
  SdnrpSettings s;
  try {
    s = app::sdnrpSettingsFromProject(document_.project());
  } catch (const std::exception& e) {
    emit errorRaised(tr("Surface finish"), e.what());
    return;
  }
  s.ra_desired_m = surface_panel_->desiredRaUm() * 1e-6;
  s.disturbance.enabled = surface_panel_->disturbanceOn();
  s.duration_s = surface_panel_->durationS();
  const bool compare = surface_panel_->compareOn();
  const quint64 generation = ++sdnrp_generation_;
  surface_panel_->setBusy(true);
  runEngineTask<SurfaceFinishRuns>(
      channel_, pool_,
      [s, compare] {
        SurfaceFinishRuns runs{SdnrpSimulator(s).run(), std::nullopt};
        if (compare) {
          SdnrpSettings held = s;  // same plant, drives, disturbance and seed
          held.control = false;
          runs.baseline = SdnrpSimulator(held).run();
        }
        return runs;
      },
      [this, generation](TaskResult<SurfaceFinishRuns> r) {
        if (generation != sdnrp_generation_) return;
        surface_panel_->setBusy(false);
        if (r.value)
          showSurfaceFinish(r.value->controlled, r.value->baseline ? &*r.value->baseline : nullptr);
        else
          emit errorRaised(tr("Surface finish"), r.error);
      });
}

void MachiningFeature::showSurfaceFinish(const SdnrpResult& v, const SdnrpResult* baseline) {
  surface_panel_->clear();
  surface_panel_->appendSamples(panelSamples(v));
  surface_panel_->setSummary(panelSummary(v));
  if (baseline) surface_panel_->setBaseline(panelSamples(*baseline), panelSummary(*baseline));
  emit surfaceFinishShown();
}

struct MachiningFeature::ProgramOverride {
  app::OverrideOutcome outcome;
  std::optional<app::AfcOutcome> afc;
  QString afc_error;
};

namespace {

std::optional<GcodeDialect> dialectOf(const QString& name) {
  return name.isEmpty() ? std::nullopt : dialectFromName(name.toStdString());
}

QString dialectDescription(const DialectDetection& d, bool named) {
  const QString title = QString::fromStdString(std::string(dialectTitle(d.dialect)));
  if (named) return QObject::tr("%1 (chosen)").arg(title);
  if (d.line == 0) return QObject::tr("%1 (no other dialect's syntax found)").arg(title);
  return QObject::tr("%1, detected at line %2: %3").arg(title).arg(d.line).arg(QString::fromStdString(d.evidence));
}

}  // namespace

void MachiningFeature::openPartProgram(const QString& path) {
  app::OverrideRequest request;
  try {
    request = app::overrideRequestFromProject(document_.project());
  } catch (const std::exception& e) {
    emit errorRaised(tr("Part program"), e.what());
    return;
  }
  const quint64 generation = ++override_generation_;
  const std::optional<GcodeDialect> dialect = dialectOf(program_panel_->dialectChoice());
  const app::Project project = document_.project();
  program_panel_->setStatus(tr("Running the %1 controller along %2...").arg(request.controllerName(), path));
  runEngineTask<ProgramOverride>(
      channel_, pool_,
      [request, project, path, dialect] {
        const GcodeProgram program = GcodeReader::readFile(path.toStdString(), dialect);
        ProgramOverride out{app::runOverride(request, program), std::nullopt, {}};
        if (program.dialect.dialect == GcodeDialect::Heidenhain) {
          try {
            out.afc = app::afcFromProject(project, program, std::nullopt);
          } catch (const std::exception& e) {
            out.afc_error = e.what();
          }
        }
        return out;
      },
      [this, generation, path](TaskResult<ProgramOverride> r) {
        if (generation != override_generation_) return;
        if (!r.value) {
          program_panel_->setStatus(tr("Override failed: %1").arg(r.error));
          emit errorRaised(tr("Part program"), r.error);
          return;
        }
        showOverride(path, std::move(*r.value));
      });
}

void MachiningFeature::showOverride(const QString& path, ProgramOverride result) {
  override_ = std::make_shared<app::OverrideOutcome>(std::move(result.outcome));
  afc_ = std::move(result.afc);
  afc_error_ = result.afc_error;
  override_path_ = path;
  QVector<widgets::PartProgramWarningView> warnings;
  for (const GcodeWarning& w : override_->result.warnings)
    warnings.append(
        {w.line, static_cast<int>(w.column), QString::fromStdString(w.text), QString::fromStdString(w.message)});
  const bool inch = !override_->result.run.motions.empty() && override_->result.run.motions.front().inch;
  program_panel_->setProgram(path, partProgramRows(override_->result), warnings, inch ? "in/min" : "mm/min",
                             override_->controller);
  const DialectDetection& dialect = override_->result.program.dialect;
  QString description = dialectDescription(dialect, !program_panel_->dialectChoice().isEmpty());
  if (afc_)
    description +=
        tr(" \u2014 AFC-LOAD %1 kW for T%2").arg(afc_->teach_in.afc_load_W * 1e-3, 0, 'f', 3).arg(afc_->tool_number);
  program_panel_->setDialect(description, dialect.dialect == GcodeDialect::Heidenhain);
  double peak = 0.0;
  for (const FeedOverrideRow& f : override_->result.rows)
    if (std::isfinite(f.predicted_force_N)) peak = std::max(peak, f.predicted_force_N);
  QString status = tr("%1 blocks, %2 changed, %3 warning(s); largest predicted force %4")
                       .arg(override_->result.program.blocks.size())
                       .arg(override_->result.changed_blocks)
                       .arg(override_->result.warnings.size())
                       .arg(units_->shop().format(widgets::Quantity::Force, peak));
  if (afc_)
    status += tr("; AFC: reference power AFC-LOAD %1 kW for tool %2 (T%3), FMAX %4 %")
                  .arg(afc_->teach_in.afc_load_W * 1e-3, 0, 'f', 3)
                  .arg(afc_->tool)
                  .arg(afc_->tool_number)
                  .arg(afc_->teach_in.setting.fmax_percent);
  else if (!afc_error_.isEmpty())
    status += tr("; no AFC setting: %1").arg(afc_error_);
  program_panel_->setStatus(status);
  emit partProgramShown();
}

bool MachiningFeature::exportPartProgram(const QString& path) {
  if (!override_) return false;
  const GcodeHeader header{QFileInfo(document_.filePath()).fileName().toStdString(),
                           override_->controller.toStdString(),
                           QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString()};
  const std::string text = override_->result.writeProgram(header);
  QString error;
  if (!writeAtomically(path, QByteArray::fromStdString(text), &error)) {
    emit errorRaised(tr("Export program"), tr("%1: %2").arg(path, error));
    return false;
  }
  emit statusMessage(tr("Optimised program written to %1").arg(path), 8000);
  return true;
}

bool MachiningFeature::exportAfcTable(const QString& path) {
  if (!afc_) {
    emit errorRaised(tr("Export AFC table"),
                     afc_error_.isEmpty() ? tr("Open a Heidenhain program first.") : afc_error_);
    return false;
  }
  QString error;
  if (!writeAtomically(path, QByteArray::fromStdString(afcTableText(afc_->teach_in.setting)), &error)) {
    emit errorRaised(tr("Export AFC table"), tr("%1: %2").arg(path, error));
    return false;
  }
  emit statusMessage(tr("AFC table written to %1; enter AFC %2 and AFC-LOAD %3 kW in the tool table for T%4")
                         .arg(path, QString::fromStdString(afc_->teach_in.setting.name))
                         .arg(afc_->teach_in.afc_load_W * 1e-3, 0, 'f', 3)
                         .arg(afc_->tool_number),
                     8000);
  return true;
}

bool MachiningFeature::exportPartProgramCsv(const QString& path) {
  if (!override_) return false;
  QString error;
  if (!writeAtomically(path, QByteArray::fromStdString(override_->result.csv()), &error)) {
    emit errorRaised(tr("Export CSV"), tr("%1: %2").arg(path, error));
    return false;
  }
  emit statusMessage(tr("Feed-override table written to %1").arg(path), 8000);
  return true;
}

}  // namespace mx::gui
