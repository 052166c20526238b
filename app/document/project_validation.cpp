#include "document/project_validation.h"

#include <QHash>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "document/project_reported_chatter.h"
#include "document/project_rules.h"
#include "document/project_sections_io.h"
#include "document/shortened_text.h"
#include "document/tool_geometry.h"

namespace mx::app {

namespace {

void checkOptional(const QString& path, const std::optional<double>& value, const NumberRule& rule) {
  if (value) checkNumber(path, *value, rule);
}

// At least two rows, speeds >= 0 and strictly increasing, powers >= 0.
void validateSpindleCurve(const std::vector<SpindleCurveRowSpec>& rows) {
  const QString path = "machine.spindle_curve";
  if (rows.size() < 2)
    throw ProjectError(
        QString("%1 has %2 row(s): must have at least 2 rows of speed_rpm and power_W").arg(path).arg(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const QString row = indexPath(path, static_cast<qsizetype>(i));
    checkNumber(row + ".speed_rpm", rows[i].speed_rpm, rules::kCurveSpeedRpm);
    if (i > 0 && !(rows[i].speed_rpm > rows[i - 1].speed_rpm))
      throwBadField(row + ".speed_rpm", formatNumber(rows[i].speed_rpm),
                    QString("> %1 (%2.speed_rpm: speeds strictly increasing)")
                        .arg(formatNumber(rows[i - 1].speed_rpm), indexPath(path, static_cast<qsizetype>(i - 1))));
    checkNumber(row + ".power_W", rows[i].power_W, rules::kCurvePowerW);
  }
}

void validateMachine(const MachineSpec& m) {
  checkNumber("machine.spindle_power_W", m.spindle_power_W, rules::kSpindlePowerW);
  checkOptional("machine.max_spindle_rpm", m.max_spindle_rpm, rules::kSpindleRpm);
  checkOptional("machine.max_feed_mm_s", m.max_feed_mm_s, rules::kFeedMmS);
  checkOptional("machine.max_torque_Nm", m.max_torque_Nm, rules::kTorqueNm);
  if (m.spindle_curve) validateSpindleCurve(*m.spindle_curve);
}

void validateMaterial(const MaterialSpec& m) {
  checkNumber("material.Kt_N_mm2", m.Kt_N_mm2, rules::kCuttingPressureNmm2);
  checkNumber("material.Kr", m.Kr, rules::kForceRatio);
  checkOptional("material.Kte_N_mm", m.Kte_N_mm, rules::kEdgeForceNmm);
  checkOptional("material.Kre_N_mm", m.Kre_N_mm, rules::kEdgeForceNmm);
  checkOptional("material.Ka_N_mm2", m.Ka_N_mm2, rules::kAxialPressureNmm2);
  checkOptional("material.Kae_N_mm", m.Kae_N_mm, rules::kEdgeForceNmm);
  checkOptional("material.process_damping_N_per_m", m.process_damping_N_per_m, rules::kProcessDampingNm);
}

void validateOperation(const OperationSpec& op) {
  if (op.radial_immersion && op.radial_depth_mm) {
    throw ProjectError(QString("operation: radial_immersion = %1 and radial_depth_mm = %2 are both given: "
                               "must give exactly one of them")
                           .arg(formatNumber(*op.radial_immersion), formatNumber(*op.radial_depth_mm)));
  }
  if (!op.radial_immersion && !op.radial_depth_mm) {
    throwMissing("operation.radial_immersion", "number in (0, 1], or operation.radial_depth_mm in (0, D] instead");
  }
  checkOptional("operation.radial_immersion", op.radial_immersion, rules::kFraction);
  checkOptional("operation.radial_depth_mm", op.radial_depth_mm, rules::kPositive);
  checkNumber("operation.max_feed_per_tooth_mm", op.max_feed_per_tooth_mm, rules::kFeedPerToothMm);
}

void checkCount(const QString& path, std::size_t count, qsizetype max, const QString& what) {
  if (count > static_cast<std::size_t>(max))
    throw ProjectError(QString("%1 has %2 %3: at most %4 are allowed").arg(path).arg(count).arg(what).arg(max));
}

void validateModes(const QString& path, const std::vector<ModeSpec>& modes) {
  checkCount(path, modes.size(), rules::kMaxModesPerAxis, "modes");
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const QString mode = indexPath(path, static_cast<qsizetype>(i));
    checkNumber(mode + ".freq_Hz", modes[i].freq_Hz, rules::kModeFrequencyHz);
    checkNumber(mode + ".damping_pct", modes[i].damping_pct, rules::kDampingPct);
    checkNumber(mode + ".stiffness_N_per_um", modes[i].stiffness_N_per_um, rules::kStiffnessNPerUm);
  }
}

void validateFrfRef(const QString& path, const std::optional<FrfRefSpec>& ref) {
  if (!ref) return;
  if (ref->file.trimmed().isEmpty())
    throw ProjectError(QString("%1.file = %2: must name a UFF 58/58b or CSV file").arg(path, formatValue(ref->file)));
  if (ref->dataset) checkNumber(path + ".dataset", *ref->dataset, rules::kCountAtLeastZero);
  static const QStringList kQuantities{"receptance", "mobility", "accelerance"};
  if (ref->quantity && !kQuantities.contains(*ref->quantity))
    throw ProjectError(QString("%1.quantity = %2: must be \"receptance\", \"mobility\" or \"accelerance\"")
                           .arg(path, formatValue(*ref->quantity)));
}

void validateCuttingPreset(const QString& path, const CuttingPresetSpec& p) {
  if (p.name.trimmed().isEmpty())
    throw ProjectError(QString("%1.name = %2: must be a non-empty string").arg(path, formatValue(p.name)));
  checkOptional(path + ".speed_rpm", p.speed_rpm, rules::kPresetSpeedRpm);
  checkOptional(path + ".surface_speed_m_min", p.surface_speed_m_min, rules::kSurfaceSpeedMMin);
  checkOptional(path + ".feed_per_tooth_mm", p.feed_per_tooth_mm, rules::kFeedPerToothMm);
  checkOptional(path + ".feed_mm_min", p.feed_mm_min, rules::kPresetFeedMmMin);
  checkOptional(path + ".axial_depth_mm", p.axial_depth_mm, rules::kPresetDepthMm);
  checkOptional(path + ".radial_depth_mm", p.radial_depth_mm, rules::kPresetDepthMm);
}

// A length of the tool that cannot exceed its overall length.
void checkWithinOverallLength(const QString& path, const QString& key, const std::optional<double>& length,
                              const ToolSpec& t) {
  if (!length || !t.overall_length_mm) return;
  checkNumber(QString("%1.%2").arg(path, key), *length,
              {rules::B::Open, 0.0, rules::B::Closed, *t.overall_length_mm, false},
              QString("%1.overall_length_mm = %2").arg(path, formatNumber(*t.overall_length_mm)));
}

void validateCamGeometry(const QString& path, const ToolSpec& t) {
  if (t.type && (t.type->trimmed().isEmpty() || t.type->size() > rules::kMaxToolTypeChars))
    throw ProjectError(QString("%1.type = %2: must be a non-empty string of at most %3 characters")
                           .arg(path, formatValue(*t.type))
                           .arg(rules::kMaxToolTypeChars));
  checkOptional(path + ".flute_length_mm", t.flute_length_mm, rules::kToolLengthMm);
  checkOptional(path + ".overall_length_mm", t.overall_length_mm, rules::kToolLengthMm);
  checkOptional(path + ".stickout_mm", t.stickout_mm, rules::kToolLengthMm);
  checkWithinOverallLength(path, "flute_length_mm", t.flute_length_mm, t);
  checkWithinOverallLength(path, "stickout_mm", t.stickout_mm, t);
  if (t.corner_radius_mm)
    checkNumber(path + ".corner_radius_mm", *t.corner_radius_mm, rules::cornerRadius(t.diameter_mm),
                QString("%1.diameter_mm = %2").arg(path, formatNumber(t.diameter_mm)));
  checkCount(path + ".cutting_data", t.cutting_data.size(), rules::kMaxCuttingPresets, "cutting presets");
  for (std::size_t i = 0; i < t.cutting_data.size(); ++i)
    validateCuttingPreset(indexPath(path + ".cutting_data", static_cast<qsizetype>(i)), t.cutting_data[i]);
  static const QStringList kFormats{"fusion", "freecad", "linuxcnc"};
  if (t.origin && !kFormats.contains(t.origin->format))
    throw ProjectError(QString("%1.origin.format = %2: must be \"fusion\", \"freecad\" or \"linuxcnc\"")
                           .arg(path, formatValue(t.origin->format)));
}

void validateTool(const QString& path, const ToolSpec& t) {
  if (t.id.trimmed().isEmpty())
    throw ProjectError(QString("%1.id = %2: must be a non-empty string").arg(path, formatValue(t.id)));
  checkNumber(path + ".teeth", t.teeth, rules::kTeeth);
  checkNumber(path + ".diameter_mm", t.diameter_mm, rules::kDiameterMm);
  checkNumber(path + ".helix_deg", t.helix_deg, rules::kHelixDeg);
  validateToolGeometry(path, t);
  checkOptional(path + ".Kt_N_mm2", t.Kt_N_mm2, rules::kCuttingPressureNmm2);
  checkOptional(path + ".Kr", t.Kr, rules::kForceRatio);
  checkOptional(path + ".Kte_N_mm", t.Kte_N_mm, rules::kEdgeForceNmm);
  checkOptional(path + ".Kre_N_mm", t.Kre_N_mm, rules::kEdgeForceNmm);
  checkOptional(path + ".Ka_N_mm2", t.Ka_N_mm2, rules::kAxialPressureNmm2);
  checkOptional(path + ".Kae_N_mm", t.Kae_N_mm, rules::kEdgeForceNmm);
  checkOptional(path + ".max_force_N", t.max_force_N, rules::kToolForceN);
  validateModes(path + ".modes_x", t.modes_x);
  validateModes(path + ".modes_y", t.modes_y);
  validateFrfRef(path + ".frf_x", t.frf_x);
  validateFrfRef(path + ".frf_y", t.frf_y);
  validateCamGeometry(path, t);
}

void validateUniqueIds(const std::vector<ToolSpec>& tools) {
  QHash<QString, qsizetype> first;
  for (qsizetype i = 0; i < static_cast<qsizetype>(tools.size()); ++i) {
    const QString& id = tools[static_cast<std::size_t>(i)].id;
    if (first.contains(id)) {
      throw ProjectError(QString("tools[%1].id = %2: duplicate of tools[%3].id (tool ids must be unique)")
                             .arg(i)
                             .arg(formatValue(id))
                             .arg(first.value(id)));
    }
    first.insert(id, i);
  }
}

// Every tool's radial depth must lie in (0, D]; the message names the field that gives it.
void validateRadialDepths(const std::vector<ToolSpec>& tools, const std::optional<OperationSpec>& operation) {
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const ToolSpec& t = tools[i];
    const QString tool = indexPath("tools", static_cast<qsizetype>(i));
    const QString diameter = QString("%1.diameter_mm = %2").arg(tool, formatNumber(t.diameter_mm));
    if (t.radial_depth_mm) {
      checkNumber(tool + ".radial_depth_mm", *t.radial_depth_mm, rules::radialDepth(t.diameter_mm), diameter);
    } else if (operation && operation->radial_depth_mm) {
      checkNumber("operation.radial_depth_mm", *operation->radial_depth_mm, rules::radialDepth(t.diameter_mm),
                  QString("%1, tool %2").arg(diameter, quoted(t.id)));
    }
  }
}

void validateWeights(const QString& path, const std::vector<double>& weights, std::size_t length) {
  if (weights.size() != length) {
    QStringList items;
    for (double w : weights) items << formatNumber(w);
    throw ProjectError(QString("%1 = [%2]: must be an array of %3 numbers >= 0, got %4")
                           .arg(path, items.join(", "))
                           .arg(length)
                           .arg(weights.size()));
  }
  for (std::size_t i = 0; i < weights.size(); ++i)
    checkNumber(indexPath(path, static_cast<qsizetype>(i)), weights[i], rules::kNonNegative);
}

// The grid's cells (speeds x depth divisions) and points (x feeds up to the feed per tooth limit)
// bound the expert's and the Pareto study's time and memory.
void validateGridSize(const ExpertGridSpec& g, const std::optional<OperationSpec>& operation) {
  const double speeds = std::floor((g.speed_to_rpm - g.speed_from_rpm) / g.speed_step_rpm) + 1.0;
  const double cells = speeds * g.depth_divisions;
  const QString grid = QString(
                           "%1 speeds (speed_from_rpm = %2 to speed_to_rpm = %3 by speed_step_rpm = %4) x "
                           "depth_divisions = %5")
                           .arg(formatNumber(speeds), formatNumber(g.speed_from_rpm), formatNumber(g.speed_to_rpm),
                                formatNumber(g.speed_step_rpm))
                           .arg(g.depth_divisions);
  if (cells > rules::kMaxGridCells)
    throw ProjectError(QString("expert.grid: %1 = %2 cells: at most %3; raise expert.grid.speed_step_rpm or lower "
                               "expert.grid.depth_divisions")
                           .arg(grid, formatNumber(cells), formatNumber(rules::kMaxGridCells)));
  if (!operation) return;
  const double feeds = std::max(1.0, std::floor(operation->max_feed_per_tooth_mm / g.feed_step_mm));
  const double points = cells * feeds;
  if (points > rules::kMaxGridPoints)
    throw ProjectError(QString("expert.grid: %1 x %2 feeds (operation.max_feed_per_tooth_mm = %3 by feed_step_mm = "
                               "%4) = %5 points: at most %6; raise expert.grid.feed_step_mm or "
                               "expert.grid.speed_step_rpm, or lower expert.grid.depth_divisions")
                           .arg(grid, formatNumber(feeds), formatNumber(operation->max_feed_per_tooth_mm),
                                formatNumber(g.feed_step_mm), formatNumber(points),
                                formatNumber(rules::kMaxGridPoints)));
}

void validateGrid(const ExpertGridSpec& g) {
  checkNumber("expert.grid.speed_from_rpm", g.speed_from_rpm, rules::kGridSpeedRpm);
  checkNumber("expert.grid.speed_to_rpm", g.speed_to_rpm, rules::kGridSpeedRpm);
  if (!(g.speed_from_rpm < g.speed_to_rpm)) {
    throw ProjectError(QString("expert.grid.speed_to_rpm = %1: must be > expert.grid.speed_from_rpm = %2")
                           .arg(formatNumber(g.speed_to_rpm), formatNumber(g.speed_from_rpm)));
  }
  checkNumber("expert.grid.speed_step_rpm", g.speed_step_rpm, rules::kGridSpeedRpm);
  checkNumber("expert.grid.depth_divisions", g.depth_divisions, rules::kGridDivisions);
  checkNumber("expert.grid.feed_step_mm", g.feed_step_mm, rules::kGridFeedStepMm);
}

void validateExpert(const ExpertSpec& e) {
  checkNumber("expert.delta_per_s", e.delta_per_s, rules::kDeltaPerS);
  checkNumber("expert.alpha", e.alpha, rules::kFraction);
  validateWeights("expert.c", e.c, 3);
  validateWeights("expert.cr", e.cr, 3);
  validateWeights("expert.ct", e.ct, 2);
  validateWeights("expert.cf", e.cf, 2);
  if (e.grid) validateGrid(*e.grid);
  validateExpertExtras(e);
}

// Rule 1.1's margin shifts the lobes' poles by -delta: it must stay below every mode's decay rate
// zeta omega_n, else the margined system has no stable depth at all.
void validateDeltaAgainstModes(double delta_per_s, const std::vector<ToolSpec>& tools) {
  for (std::size_t i = 0; i < tools.size(); ++i) {
    for (const auto& [axis, modes] :
         {std::pair{"modes_x", &tools[i].modes_x}, std::pair{"modes_y", &tools[i].modes_y}}) {
      for (std::size_t j = 0; j < modes->size(); ++j) {
        const ModeSpec& m = (*modes)[j];
        const double decay = m.damping_pct / 100.0 * 2.0 * std::numbers::pi * m.freq_Hz;
        if (delta_per_s >= decay)
          throw ProjectError(
              QString("expert.delta_per_s = %1: must be in [0, %2) 1/s, below the decay rate zeta "
                      "omega_n of %3.%4[%5]")
                  .arg(formatNumber(delta_per_s), formatNumber(decay), indexPath("tools", qsizetype(i)), axis)
                  .arg(j));
      }
    }
  }
}

// The point the project opens at: a tool of the project and a cut inside the ranges of the CLI's flags.
void validateOperatingPoint(const OperatingPointSpec& point, const std::vector<ToolSpec>& tools) {
  const bool known = std::any_of(tools.begin(), tools.end(), [&](const ToolSpec& t) { return t.id == point.tool; });
  if (!known) throwBadField("operating_point.tool", formatValue(point.tool), "the id of a tool of the project");
  checkNumber("operating_point.speed_rpm", point.speed_rpm, rules::kPointSpeedRpm);
  checkNumber("operating_point.depth_mm", point.depth_mm, rules::kPointDepthMm);
  checkNumber("operating_point.feed_mm_per_tooth", point.feed_mm_per_tooth, rules::kPointFeedMmPerTooth);
}

}  // namespace

void validateProject(const Project& project) {
  if (project.machine) validateMachine(*project.machine);
  if (project.material) validateMaterial(*project.material);
  if (project.operation) validateOperation(*project.operation);
  validateTools(project.tools, project.operation);
  if (project.expert) validateExpert(*project.expert);
  if (project.expert && project.expert->grid) validateGridSize(*project.expert->grid, project.operation);
  if (project.expert) validateDeltaAgainstModes(project.expert->delta_per_s, project.tools);
  if (project.expert) validateReportedChatter(*project.expert, project.tools);
  validateProcessSections(project);
  if (project.operating_point) validateOperatingPoint(*project.operating_point, project.tools);
}

void validateTools(const std::vector<ToolSpec>& tools, const std::optional<OperationSpec>& operation) {
  checkCount("tools", tools.size(), rules::kMaxTools, "tools");
  for (std::size_t i = 0; i < tools.size(); ++i) validateTool(indexPath("tools", static_cast<qsizetype>(i)), tools[i]);
  validateUniqueIds(tools);
  validateRadialDepths(tools, operation);
}

std::optional<double> radialDepthMm(const Project& project, const ToolSpec& tool) {
  if (tool.radial_depth_mm) return tool.radial_depth_mm;
  if (!project.operation) return std::nullopt;
  if (project.operation->radial_depth_mm) return project.operation->radial_depth_mm;
  if (project.operation->radial_immersion) return *project.operation->radial_immersion * tool.diameter_mm;
  return std::nullopt;
}

QString projectValidationError(const Project& project) {
  try {
    validateProject(project);
  } catch (const ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace mx::app
