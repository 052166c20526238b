#include "services/expert_request.h"

#include <cmath>

#include "core/invalid_input.h"
#include "document/shortened_text.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

template <std::size_t N>
std::array<double, N> checkedWeights(const QString& name, const std::vector<double>& values) {
  try {
    validateSimplexWeights(name.toStdString(), values, N);
  } catch (const InvalidInput& e) {
    throw ProjectError(QString("expert.%1").arg(QString::fromStdString(e.what())));
  }
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = values[i];
  return out;
}

}  // namespace

StabilityMethod stabilityMethodFromText(const QString& text, const QString& where) {
  if (text == "zoa") return StabilityMethod::ZeroOrder;
  if (text == "sdm") return StabilityMethod::SemiDiscretization;
  throw InputError(QString("%1 = %2: must be zoa or sdm").arg(where, quoted(text)));
}

ExpertRequest expertRequestFromProject(const Project& project) {
  ExpertRequest r;
  if (project.tools.empty()) throw ProjectError("section 'tools' is empty: the expert system needs candidate tools");
  const MachineSpec& machine = project.requireMachine();
  const ExpertSpec& expert = project.requireExpert();
  for (const ToolSpec& t : project.tools) {
    r.tool_ids << t.id;
    r.tools.push_back(project.setupFor(t.id));
    r.tool_force_limits_n.push_back(project.toolForceLimitN(t));
  }
  ExpertSettings& s = r.settings;
  const SpindlePowerCurve spindle = spindlePowerOf(machine);
  s.limits.spindle_power_w = spindle.max_power_w;
  s.limits.max_spindle_torque_nm = spindle.max_torque_nm;
  s.limits.spindle_curve = spindle.curve;
  if (machine.max_spindle_rpm) s.limits.max_spindle_rev_per_s = rpmToRevPerS(*machine.max_spindle_rpm);
  if (machine.max_feed_mm_s) s.limits.max_feed_velocity_m_per_s = *machine.max_feed_mm_s * 1e-3;
  if (project.operation && project.operation->max_feed_per_tooth_mm > 0.0)
    s.limits.max_feed_per_tooth_m = project.operation->max_feed_per_tooth_mm * 1e-3;
  s.stability.delta_per_s = expert.delta_per_s;
  s.stability.alpha = expert.alpha;
  const ExpertGridSpec grid = expert.grid.value_or(ExpertGridSpec{});
  s.grid.speed_from_rev_per_s = rpmToRevPerS(grid.speed_from_rpm);
  s.grid.speed_to_rev_per_s = rpmToRevPerS(grid.speed_to_rpm);
  s.grid.speed_step_rev_per_s = rpmToRevPerS(grid.speed_step_rpm);
  s.grid.depth_divisions = grid.depth_divisions;
  s.grid.feed_step_m = grid.feed_step_mm * 1e-3;

  if (expert.method) s.stability.method = stabilityMethodFromText(*expert.method, "expert.method");
  if (expert.simulated_points) s.refinement.simulated_points = *expert.simulated_points;
  if (const auto& search = expert.rule5_search) {
    Rule5SearchSettings& t = s.refinement.search;
    if (search->speed_step_rpm) t.speed_step_rev_per_s = rpmToRevPerS(*search->speed_step_rpm);
    if (search->depth_step_mm) t.depth_step_m = *search->depth_step_mm * 1e-3;
    if (search->feed_step_mm) t.feed_step_m = *search->feed_step_mm * 1e-3;
    if (search->max_iterations) t.max_iterations = *search->max_iterations;
  }
  if (expert.max_malfunction_iterations) s.refinement.max_malfunction_iterations = *expert.max_malfunction_iterations;
  if (expert.grid && expert.grid->modal_candidate_speeds)
    s.grid.modal_candidate_speeds = *expert.grid->modal_candidate_speeds;

  r.weights.c = checkedWeights<3>("c", expert.c);
  r.weights.cr = checkedWeights<3>("cr", expert.cr);
  r.weights.ct = checkedWeights<2>("ct", expert.ct);
  r.weights.cf = checkedWeights<2>("cf", expert.cf);
  return r;
}

std::vector<DynamicsChoice> applyExpertDynamics(const Project& project, ExpertRequest& request,
                                                std::optional<DynamicsSource> requested, bool simulate) {
  std::vector<DynamicsChoice> choices;
  const StabilitySettings& stability = request.settings.stability;
  for (qsizetype i = 0; i < request.tool_ids.size(); ++i) {
    const ToolSpec& tool = *project.findTool(request.tool_ids[i]);
    // A tool without a tap test keeps its modes when the others are asked to use theirs.
    const std::optional<DynamicsSource> wanted = tool.hasFrf() ? requested : std::nullopt;
    choices.push_back(chooseDynamics(tool, wanted, stability.delta_per_s, stability.method));
    if (simulate) requireFittedModes(tool, "the time-domain refinement (Rule 5; --no-simulation leaves it out)");
    if (choices.back().used != DynamicsSource::Measured) continue;
    request.tools[static_cast<std::size_t>(i)] = dynamicsSetupFor(project, tool.id, DynamicsSource::Measured);
    request.settings.stability.dynamics = DynamicsSource::Measured;
  }
  return choices;
}

std::vector<double> parseWeightList(const QString& flag, const QString& text, std::size_t count) {
  const QStringList items = text.split(',');
  std::vector<double> values;
  for (const QString& item : items) {
    bool ok = false;
    const double v = item.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
      throw InputError(QString("--%1 = %2: %3 is not a finite number").arg(flag, quoted(text), quoted(item)));
    values.push_back(v);
  }
  if (values.size() != count)
    throw InputError(QString("--%1 = %2: expected %3 comma-separated weights").arg(flag, quoted(text)).arg(count));
  try {
    validateSimplexWeights(("--" + flag).toStdString(), values, count);
  } catch (const InvalidInput& e) {
    throw InputError(QString::fromStdString(e.what()));
  }
  return values;
}

}  // namespace mx::app
