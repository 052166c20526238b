#include "report_data.h"

#include <QCoreApplication>
#include <QDir>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cli/cli_application.h"
#include "cli/cli_support.h"
#include "cli/expert_request.h"
#include "model/job_control.h"
#include "report_figures.h"
#include "simulation/milling_simulation.h"
#include "stability/zero_order_lobes.h"

#ifndef MX_REPORT_VERSION
#define MX_REPORT_VERSION "unknown"
#endif

namespace mx::gui {

namespace {

constexpr double kLobeStepRpm = 10.0;

QVector<double> envelopeMm(const LobeDiagram& lobes, double factor) {
  QVector<double> out;
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

// Figure 1: nominal and margined ZOA lobes of the selected tool, the power limit at q*'s feed (peak
// power is proportional to N b s_t in the straight-tooth model), q* and q**.
LobeFigureInput lobeFigure(const ReportData& d, const MillingSetup& setup) {
  const ExpertGrid& grid = d.settings.grid;
  const ToolChoice& chosen = d.result.ranking.selected();
  double top_rpm = revPerSToRpm(grid.speed_to_rev_per_s);
  if (d.result.refinement) top_rpm = std::max(top_rpm, revPerSToRpm(d.result.refinement->chosen().q.speed_rev_per_s));
  std::vector<double> speeds;
  for (double rpm = revPerSToRpm(grid.speed_from_rev_per_s); rpm <= top_rpm * 1.15 + 1e-9; rpm += kLobeStepRpm)
    speeds.push_back(rpmToRevPerS(rpm));
  ZoaOptions nominal;
  nominal.max_depth_m = d.settings.stability.max_depth_m;
  ZoaOptions margined = nominal;
  margined.delta_per_s = d.settings.stability.delta_per_s;
  const LobeDiagram lobes0 = computeZoaLobes(setup, speeds, nominal);
  const LobeDiagram lobesd = computeZoaLobes(setup, speeds, margined);

  LobeFigureInput in;
  in.series.tool_id = d.selectedId();
  for (double n : speeds) in.series.speed_rpm.push_back(revPerSToRpm(n));
  in.series.nominal_mm = envelopeMm(lobes0, 1.0);
  in.series.margined_mm = envelopeMm(lobesd, d.settings.stability.alpha);
  in.delta_per_s = d.settings.stability.delta_per_s;
  in.alpha = d.settings.stability.alpha;
  const ExpertPoint& q = chosen.q;
  const double p_av = d.settings.limits.spindle_power_w;
  if (std::isfinite(p_av) && q.power_w > 0.0) {
    const double per_unit = q.power_w / (q.speed_rev_per_s * q.depth_m * 1e3);  // W per (rev/s * mm)
    for (double n : speeds) in.power_limit_mm.push_back(p_av / (per_unit * n));
    in.power_limit_label = QString("power limit %1 W at s_t = %2 mm/tooth").arg(p_av, 0, 'f', 1).arg(q.feed_per_tooth_m * 1e3, 0, 'f', 3);
  }
  in.q_star_rpm = revPerSToRpm(q.speed_rev_per_s);
  in.q_star_mm = q.depth_m * 1e3;
  if (d.result.refinement) {
    const ExpertPoint& qq = d.result.refinement->chosen().q;
    in.has_q_star_star = true;
    in.q_star_star_rpm = revPerSToRpm(qq.speed_rev_per_s);
    in.q_star_star_mm = qq.depth_m * 1e3;
  }
  return in;
}

void require(bool ok, const QString& path) {
  if (!ok) throw std::runtime_error(QString("cannot write the figure '%1'").arg(path).toStdString());
}

}  // namespace

ReportData collectReportData(const QString& project_path, const ReportOptions& options) {
  ReportData d;
  d.project_path = project_path;
  d.project = app::loadProject(project_path);
  app::ExpertRequest request = app::expertRequestFromProject(d.project);
  if (options.c) {
    const std::vector<double> c(options.c->begin(), options.c->end());
    try {
      validateSimplexWeights("c", c, 3);
    } catch (const InvalidInput& e) {
      throw app::CliError(QString::fromStdString(e.what()), app::kExitBadInput);
    }
    request.weights.c = *options.c;
  }
  d.tool_ids = request.tool_ids;
  d.settings = request.settings;
  d.weights = request.weights;
  d.version = QString(MX_REPORT_VERSION);
  d.generated = QDateTime::currentDateTime();

  ExpertSession session(request.tools, request.settings);
  if (session.empty()) throw app::CliError(QString::fromStdString(session.emptyReason()), app::kExitComputationFailed);
  d.result = session.run(request.weights, true);
  d.normalisation = session.normalisation();
  d.sweep = figure4Sweep(session, request.weights.c[2], options.sweep_step);

  const QDir dir(options.image_dir);
  ReportFigureRenderer renderer(options.image_width, options.image_height);
  const MillingSetup& setup = request.tools.at(d.result.ranking.selected().tool);
  d.lobe_image = dir.filePath("figure-1-lobes.png");
  require(renderer.renderLobes(lobeFigure(d, setup), d.lobe_image), d.lobe_image);

  if (d.result.refinement) {
    const ExpertPoint& qq = d.result.refinement->chosen().q;
    SimulationOptions sim;
    sim.revolutions = d.settings.refinement.revolutions;
    sim.evaluated_revolutions = d.settings.refinement.evaluated_revolutions;
    const SimulationResult run =
        simulateMilling(setup, OperatingPoint{qq.speed_rev_per_s, qq.depth_m, qq.feed_per_tooth_m}, sim);
    d.simulation_revolutions = run.simulated_revolutions;
    d.simulation_image = dir.filePath("figure-2-simulation.png");
    const QString title = QString("%1 at q**: N = %2 rpm, b = %3 mm, s_t = %4 mm/tooth")
                              .arg(d.selectedId())
                              .arg(revPerSToRpm(qq.speed_rev_per_s), 0, 'f', 0)
                              .arg(qq.depth_m * 1e3, 0, 'f', 3)
                              .arg(qq.feed_per_tooth_m * 1e3, 0, 'f', 3);
    require(renderer.renderSimulation(run.trace, d.settings.limits.spindle_power_w, title, d.simulation_image),
            d.simulation_image);
  }

  SweepFigureInput sweep;
  sweep.c3 = d.sweep.c3;
  sweep.current_c1 = d.weights.c[0];
  sweep.c1 = d.sweep.c1;
  sweep.tool_ids = d.tool_ids;
  sweep.cost = d.sweep.min_cost;
  d.sweep_image = dir.filePath("figure-3-weights-sweep.png");
  require(renderer.renderSweep(sweep, d.sweep_image), d.sweep_image);
  return d;
}

}  // namespace mx::gui
