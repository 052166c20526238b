#include "services/measured_dynamics.h"

#include <QFileInfo>
#include <tuple>

#include "core/invalid_input.h"
#include "document/frf_paths.h"
#include "document/shortened_text.h"
#include "services/frf_import.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

bool axisNeedsFit(const std::vector<ModeSpec>& modes, const std::optional<FrfRefSpec>& frf) {
  return modes.empty() && frf.has_value();
}

QString directionText(FrfDirection d) {
  return QString::fromStdString(std::string(frfDirectionName(d)));
}

void checkDirection(const QString& where, const Receptance& r, FrfDirection axis) {
  if (r.direction == axis && r.reference_direction == axis) return;
  throw InputError(
      QString("%1: the dataset is a %2/%3 FRF (response/reference): must be %4/%4")
          .arg(where, directionText(r.direction), directionText(r.reference_direction), directionText(axis)));
}

}  // namespace

DynamicsSource dynamicsSourceFromName(const QString& field, const QString& name) {
  if (name == "modal") return DynamicsSource::Modal;
  if (name == "measured") return DynamicsSource::Measured;
  throw InputError(QString("%1 = %2: must be modal or measured").arg(field, quoted(name)));
}

QString dynamicsName(DynamicsSource source) {
  return source == DynamicsSource::Measured ? "measured" : "modal";
}

DynamicsSource defaultDynamics(const ToolSpec& tool) {
  const bool needs_frf = axisNeedsFit(tool.modes_x, tool.frf_x) || axisNeedsFit(tool.modes_y, tool.frf_y);
  return needs_frf ? DynamicsSource::Measured : DynamicsSource::Modal;
}

void requireFittedModes(const ToolSpec& tool, const QString& purpose) {
  for (const auto& [modes, frf, axis] :
       {std::tuple{&tool.modes_x, &tool.frf_x, "x"}, {&tool.modes_y, &tool.frf_y, "y"}}) {
    if (!axisNeedsFit(*modes, *frf)) continue;
    throw InputError(QString("tool %1: modes_%2 is empty and only frf_%2 (%3) is given: %4 needs fitted modes; "
                             "fit the FRF (millexpert-cli frf-fit, or Tap test > Fit in the GUI) and accept them "
                             "as modes_%2")
                         .arg(quoted(tool.id), axis, shortened((*frf)->file), purpose));
  }
}

DynamicsChoice chooseDynamics(const ToolSpec& tool, std::optional<DynamicsSource> requested, double delta_per_s,
                              StabilityMethod method) {
  const DynamicsSource wanted = requested.value_or(defaultDynamics(tool));
  if (wanted == DynamicsSource::Modal) {
    requireFittedModes(tool, "--dynamics modal");
    return {};
  }
  if (!tool.hasFrf())
    throw InputError(QString("tool %1: dynamics = measured needs a tap-test FRF (frf_x or frf_y); the tool has "
                             "modes only")
                         .arg(quoted(tool.id)));
  DynamicsChoice choice{DynamicsSource::Measured, {}};
  if (method == StabilityMethod::SemiDiscretization) {
    choice.note = "semi-discretization needs a state-space model: the lobes use the fitted modes";
  } else if (delta_per_s > 0.0) {
    choice.note = QString(
                      "delta = %1 1/s > 0: a measured FRF gives G(i omega) only, not G(-delta + i omega), so the "
                      "lobes use the fitted modes")
                      .arg(delta_per_s);
  }
  if (choice.note.isEmpty()) return choice;
  requireFittedModes(tool, method == StabilityMethod::SemiDiscretization ? QString("semi-discretization")
                                                                         : QString("a margin delta > 0"));
  choice.used = DynamicsSource::Modal;
  return choice;
}

MeasuredAxis loadMeasuredAxis(const Project& project, const ToolSpec& tool, const QString& field,
                              const FrfRefSpec& ref) {
  const QString path = resolvedFrfPath(project, ref);
  const QString where = QString("tool %1: %2.file = %3 (%4)").arg(quoted(tool.id), field, quoted(ref.file, u'"'), path);
  if (!QFileInfo::exists(path)) throw InputError(where + ": file not found");
  FrfFile file;
  Receptance r;
  try {
    const std::optional<FrfQuantity> quantity =
        ref.quantity ? std::optional(frfQuantityFromName(field + ".quantity", *ref.quantity)) : std::nullopt;
    file = loadFrfFile(path, quantity);
    r = frfReceptance(file, path, ref.datasetIndex());
  } catch (const InputError& e) {
    throw InputError(QString("tool %1: %2: %3").arg(quoted(tool.id), field, QString::fromStdString(e.what())));
  }
  if (file.format != FrfFormat::Csv) checkDirection(where, r, field.endsWith('y') ? FrfDirection::Y : FrfDirection::X);
  MeasuredAxis axis{std::move(r.frequency_hz), std::move(r.h_m_per_n)};
  try {
    axis.validate(field.toStdString());
  } catch (const InvalidInput& e) {
    throw InputError(where + ": " + QString::fromStdString(e.what()));
  }
  return axis;
}

MillingSetup dynamicsSetupFor(const Project& project, const QString& tool_id, DynamicsSource source) {
  MillingSetup setup = project.setupFor(tool_id);
  if (source != DynamicsSource::Measured) return setup;
  const ToolSpec& tool = *project.findTool(tool_id);
  if (tool.frf_x) setup.measured_x = loadMeasuredAxis(project, tool, "frf_x", *tool.frf_x);
  if (tool.frf_y) setup.measured_y = loadMeasuredAxis(project, tool, "frf_y", *tool.frf_y);
  return setup;
}

}  // namespace mx::app
