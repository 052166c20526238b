// Project queries: tool lookup, the required sections, and the SI engine setup of one tool.
#include "document/project.h"

#include <QStringList>
#include <limits>
#include <numbers>

#include "document/project_validation.h"
#include "document/shortened_text.h"
#include "document/tool_geometry.h"

namespace mx::app {

namespace {

constexpr double kPaPerNPerMm2 = 1e6;    // 1 N/mm^2 = 1e6 N/m^2
constexpr double kNPerMPerNPerMm = 1e3;  // 1 N/mm = 1e3 N/m
constexpr double kNPerMPerNPerUm = 1e6;  // 1 N/um = 1e6 N/m
constexpr double kMPerMm = 1e-3;

ModalAxis toModalAxis(const std::vector<ModeSpec>& modes) {
  ModalAxis axis;
  axis.reserve(modes.size());
  for (const ModeSpec& m : modes)
    axis.push_back({m.freq_Hz, m.damping_pct / 100.0, m.stiffness_N_per_um * kNPerMPerNPerUm});
  return axis;
}

QString toolIds(const std::vector<ToolSpec>& tools) {
  QStringList ids;
  for (const ToolSpec& t : tools) ids << shortened(t.id);
  return ids.isEmpty() ? QString("(none)") : ids.join(", ");
}

}  // namespace

const ToolSpec* Project::findTool(const QString& id) const {
  for (const ToolSpec& t : tools)
    if (t.id == id) return &t;
  return nullptr;
}

double Project::toolForceLimitN(const ToolSpec& tool) const {
  if (tool.max_force_N) return *tool.max_force_N;
  if (control && control->breakage_force_N.value_or(0.0) > 0.0)
    return control->safety_factor.value_or(1.0) * *control->breakage_force_N;
  return std::numeric_limits<double>::infinity();
}

MillingSetup Project::setupFor(const QString& toolId) const {
  const ToolSpec* tool = findTool(toolId);
  if (tool == nullptr)
    throw ProjectError(QString("tool %1 not found; available: %2").arg(quoted(toolId), toolIds(tools)));
  if (!operation) {
    throw ProjectError(QString("section 'operation' is missing (needed by tool %1 for the milling direction and "
                               "radial engagement)")
                           .arg(quoted(toolId)));
  }
  if (!material && (!tool->Kt_N_mm2 || !tool->Kr)) {
    QStringList needed;
    if (!tool->Kt_N_mm2) needed << "Kt_N_mm2";
    if (!tool->Kr) needed << "Kr";
    throw ProjectError(QString("section 'material' is missing (needed by tool %1 for %2; or give them on the tool)")
                           .arg(quoted(toolId), needed.join(" and ")));
  }
  const std::optional<double> radial_depth_mm = radialDepthMm(*this, *tool);
  if (!radial_depth_mm) {
    throw ProjectError(QString("operation: no radial engagement for tool %1 (give operation.radial_immersion or "
                               "operation.radial_depth_mm)")
                           .arg(quoted(toolId)));
  }

  MillingSetup s = cutterGeometryOf(*tool);
  s.tangential_coefficient_pa = tool->Kt_N_mm2.value_or(material ? material->Kt_N_mm2 : 0.0) * kPaPerNPerMm2;
  s.radial_ratio = tool->Kr.value_or(material ? material->Kr : 0.0);
  // The tool's value, else the material's, else 0 (a material given by K_t and K_r alone).
  auto coefficient = [&](const std::optional<double>& on_tool, std::optional<double> MaterialSpec::*field) {
    return on_tool.value_or(material ? (*material.*field).value_or(0.0) : 0.0);
  };
  s.tangential_edge_n_per_m = coefficient(tool->Kte_N_mm, &MaterialSpec::Kte_N_mm) * kNPerMPerNPerMm;
  s.radial_edge_n_per_m = coefficient(tool->Kre_N_mm, &MaterialSpec::Kre_N_mm) * kNPerMPerNPerMm;
  s.axial_coefficient_pa = coefficient(tool->Ka_N_mm2, &MaterialSpec::Ka_N_mm2) * kPaPerNPerMm2;
  s.axial_edge_n_per_m = coefficient(tool->Kae_N_mm, &MaterialSpec::Kae_N_mm) * kNPerMPerNPerMm;
  s.process_damping_n_per_m = material ? material->process_damping_N_per_m.value_or(0.0) : 0.0;
  s.modes_x = toModalAxis(tool->modes_x);
  s.modes_y = toModalAxis(tool->modes_y);
  s.direction = operation->milling;
  s.radial_depth_m = *radial_depth_mm * kMPerMm;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
  return s;
}

const MachineSpec& Project::requireMachine() const {
  if (!machine) throw ProjectError("section 'machine' is missing (needed for the spindle power and speed limits)");
  return *machine;
}

const ExpertSpec& Project::requireExpert() const {
  if (!expert) throw ProjectError("section 'expert' is missing (needed by the expert system: delta_per_s, alpha)");
  return *expert;
}

SpindlePowerCurve spindlePowerOf(const MachineSpec& machine) {
  SpindlePowerCurve p;
  p.max_power_w = machine.spindle_power_W;
  if (machine.max_torque_Nm) p.max_torque_nm = *machine.max_torque_Nm;
  if (machine.spindle_curve)
    for (const SpindleCurveRowSpec& row : *machine.spindle_curve)
      p.curve.push_back({row.speed_rpm / 60.0, row.power_W});
  return p;
}

double availablePowerW(const std::optional<MachineSpec>& machine, double speed_rpm) {
  return machine ? spindlePowerOf(*machine).available(speed_rpm / 60.0) : std::numeric_limits<double>::infinity();
}

}  // namespace mx::app
