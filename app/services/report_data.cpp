#include "services/report_data.h"

#include <cmath>
#include <limits>

#include "core/invalid_input.h"
#include "services/expert_request.h"
#include "services/service_errors.h"
#include "simulation/milling_simulation.h"
#include "stability/zero_order_lobes.h"

namespace mx::app {

namespace {

constexpr double kLobeStepRpm = 10.0;

std::vector<double> envelopeMm(const LobeDiagram& lobes, double factor) {
  std::vector<double> out;
  for (double b : lobes.envelope_depth_m)
    out.push_back(std::isfinite(b) ? b * factor * 1e3 : std::numeric_limits<double>::quiet_NaN());
  return out;
}

ReportSweep figure4Sweep(const ExpertSession& session, double c3, double step) {
  ReportSweep sweep;
  sweep.c3 = c3;
  const double span = 1.0 - c3;
  for (int i = 0; i * step <= span + 1e-12; ++i) sweep.c1.push_back(std::min(i * step, span));
  if (sweep.c1.empty() || sweep.c1.back() < span - 1e-12) sweep.c1.push_back(span);
  sweep.min_cost.assign(session.toolCount(), {});
  for (double c1 : sweep.c1) {
    const std::vector<double> costs = session.minimumCosts({c1, std::max(0.0, span - c1), c3});
    for (std::size_t t = 0; t < costs.size(); ++t) sweep.min_cost[t].push_back(costs[t]);
  }
  return sweep;
}

// Power limit at q*'s feed: peak power is proportional to N b s_t in the straight-tooth model.
ReportLobes selectedToolLobes(const ReportData& d, const MillingSetup& setup) {
  const ExpertGrid& grid = d.settings.grid;
  double top_rpm = revPerSToRpm(grid.speed_to_rev_per_s);
  if (d.result.refinement) top_rpm = std::max(top_rpm, revPerSToRpm(d.result.refinement->chosen().q.speed_rev_per_s));
  std::vector<double> speeds;
  for (double rpm = revPerSToRpm(grid.speed_from_rev_per_s); rpm <= top_rpm * 1.15 + 1e-9; rpm += kLobeStepRpm)
    speeds.push_back(rpmToRevPerS(rpm));
  ZoaOptions nominal;
  nominal.max_depth_m = d.settings.stability.max_depth_m;
  nominal.dynamics = d.settings.stability.dynamics;  // measured only with delta = 0 (measured_dynamics.h)
  ZoaOptions margined = nominal;
  margined.delta_per_s = d.settings.stability.delta_per_s;

  ReportLobes out;
  for (double n : speeds) out.speed_rpm.push_back(revPerSToRpm(n));
  out.nominal_mm = envelopeMm(computeZoaLobes(setup, speeds, nominal), 1.0);
  out.margined_mm = envelopeMm(computeZoaLobes(setup, speeds, margined), d.settings.stability.alpha);
  const ExpertPoint& q = d.result.ranking.selected().q;
  const SpindlePowerCurve spindle = d.settings.limits.spindlePower();
  const double p_max = d.settings.limits.spindle_power_w;
  if (std::isfinite(spindle.available(q.speed_rev_per_s)) && q.power_w > 0.0) {
    const double per_unit = q.power_w / (q.speed_rev_per_s * q.depth_m * 1e3);                    // W per (rev/s * mm)
    for (double n : speeds) out.power_limit_mm.push_back(spindle.available(n) / (per_unit * n));  // P_av(N) / (k N)
    const QString torque = std::isfinite(spindle.max_torque_nm)
                               ? QString(", %1 N\u00b7m").arg(spindle.max_torque_nm, 0, 'f', 2)
                               : QString();
    const QString curve = spindle.curve.empty() ? QString() : QString(", power curve");
    out.power_limit_label = QString("power limit %1 W%2%3 at s_t = %4 mm/tooth")
                                .arg(p_max, 0, 'f', 1)
                                .arg(torque, curve)
                                .arg(q.feed_per_tooth_m * 1e3, 0, 'f', 3);
  }
  return out;
}

void simulateQStarStar(ReportData& d, const MillingSetup& setup) {
  const ExpertPoint& qq = d.result.refinement->chosen().q;
  SimulationOptions sim;
  sim.revolutions = d.settings.refinement.revolutions;
  sim.evaluated_revolutions = d.settings.refinement.evaluated_revolutions;
  SimulationResult run =
      simulateMilling(setup, OperatingPoint{qq.speed_rev_per_s, qq.depth_m, qq.feed_per_tooth_m}, sim);
  d.simulation_revolutions = run.simulated_revolutions;
  d.simulation = std::move(run.trace);
  d.simulation_title = QString("%1 at q**: N = %2 rpm, b = %3 mm, s_t = %4 mm/tooth")
                           .arg(d.selectedId())
                           .arg(revPerSToRpm(qq.speed_rev_per_s), 0, 'f', 0)
                           .arg(qq.depth_m * 1e3, 0, 'f', 3)
                           .arg(qq.feed_per_tooth_m * 1e3, 0, 'f', 3);
}

}  // namespace

ReportData computeReportData(const QString& project_path, const ReportRequest& options) {
  ReportData d;
  d.project_path = project_path;
  d.project = loadProject(project_path);
  ExpertRequest request = expertRequestFromProject(d.project);
  applyExpertDynamics(d.project, request, std::nullopt, true);
  if (options.c) {
    const std::vector<double> c(options.c->begin(), options.c->end());
    try {
      validateSimplexWeights("c", c, 3);
    } catch (const InvalidInput& e) {
      throw InputError(QString::fromStdString(e.what()));
    }
    request.weights.c = *options.c;
  }
  d.tool_ids = request.tool_ids;
  d.settings = request.settings;
  d.weights = request.weights;
  d.version = options.version;
  d.generated = QDateTime::currentDateTime();

  ExpertSession session(request.tools, request.settings, request.tool_force_limits_n);
  if (session.empty()) throw ComputationError(QString::fromStdString(session.emptyReason()));
  d.result = session.run(request.weights, true);
  d.normalisation = session.normalisation();
  d.sweep = figure4Sweep(session, request.weights.c[2], options.sweep_step);
  const MillingSetup& setup = request.tools.at(d.result.ranking.selected().tool);
  d.lobes = selectedToolLobes(d, setup);
  if (d.result.refinement) simulateQStarStar(d, setup);
  return d;
}

}  // namespace mx::app
