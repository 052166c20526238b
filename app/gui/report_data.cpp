#include "report_data.h"

#include <QDir>
#include <cmath>
#include <stdexcept>

#include "model/milling_setup.h"
#include "mx_version.h"
#include "report_figures.h"

namespace mx::gui {

namespace {

QVector<double> toQVector(const std::vector<double>& v) {
  return QVector<double>(v.begin(), v.end());
}

using widgets::Quantity;

// The lobe figure's power-limit label (services/report_data.cpp writes it in metric), in shop units.
QString powerLimitLabel(const ReportData& d, const widgets::ShopUnits& u) {
  if (d.lobes.power_limit_label.isEmpty()) return {};
  const SpindlePowerCurve spindle = d.settings.limits.spindlePower();
  const QString torque =
      std::isfinite(spindle.max_torque_nm) ? QString(", %1 N\u00b7m").arg(spindle.max_torque_nm, 0, 'f', 2) : QString();
  return QString("power limit %1%2%3 at s_t = %4")
      .arg(u.format(Quantity::Power, d.settings.limits.spindle_power_w), torque,
           spindle.curve.empty() ? QString() : QString(", power curve"),
           u.format(Quantity::ChipLoad, d.result.ranking.selected().q.feed_per_tooth_m * 1e3));
}

// "R1 at q**: N = 5800 rpm, b = 0.5048 mm, s_t = 0.1000 mm/tooth", in shop units.
QString simulationTitle(const ReportData& d, const widgets::ShopUnits& u) {
  const ExpertPoint& qq = d.result.refinement->chosen().q;
  return QString("%1 at q**: N = %2 rpm, b = %3, s_t = %4")
      .arg(d.selectedId())
      .arg(revPerSToRpm(qq.speed_rev_per_s), 0, 'f', 0)
      .arg(u.format(Quantity::Length, qq.depth_m * 1e3), u.format(Quantity::ChipLoad, qq.feed_per_tooth_m * 1e3));
}

LobeFigureInput lobeFigure(const ReportData& d, const widgets::ShopUnits& units) {
  LobeFigureInput in;
  in.series.tool_id = d.selectedId();
  in.series.speed_rpm = toQVector(d.lobes.speed_rpm);
  in.series.nominal_mm = toQVector(d.lobes.nominal_mm);
  in.series.margined_mm = toQVector(d.lobes.margined_mm);
  in.delta_per_s = d.settings.stability.delta_per_s;
  in.alpha = d.settings.stability.alpha;
  in.power_limit_mm = toQVector(d.lobes.power_limit_mm);
  in.power_limit_label = powerLimitLabel(d, units);
  const ExpertPoint& q = d.result.ranking.selected().q;
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

SweepFigureInput sweepFigure(const ReportData& d) {
  SweepFigureInput sweep;
  sweep.c3 = d.sweep.c3;
  sweep.current_c1 = d.weights.c[0];
  sweep.c1 = d.sweep.c1;
  sweep.tool_ids = d.tool_ids;
  sweep.cost = d.sweep.min_cost;
  return sweep;
}

void require(bool ok, const QString& path) {
  if (!ok) throw std::runtime_error(QString("cannot write the figure '%1'").arg(path).toStdString());
}

}  // namespace

ReportData collectReportData(const QString& project_path, const ReportOptions& options) {
  ReportData d = app::computeReportData(project_path, {options.c, options.sweep_step, QString(app::kVersion)});
  const QDir dir(options.image_dir);
  const ReportFigureRenderer renderer(options.image_width, options.image_height, options.units);
  d.lobe_image = dir.filePath("figure-1-lobes.png");
  require(renderer.renderLobes(lobeFigure(d, options.units), d.lobe_image), d.lobe_image);
  if (d.simulation) {
    d.simulation_title = simulationTitle(d, options.units);
    d.simulation_image = dir.filePath("figure-2-simulation.png");
    const double p_av = d.settings.limits.spindlePower().available(d.result.refinement->chosen().q.speed_rev_per_s);
    require(renderer.renderSimulation(*d.simulation, p_av, d.simulation_title, d.simulation_image), d.simulation_image);
  }
  d.sweep_image = dir.filePath("figure-3-weights-sweep.png");
  require(renderer.renderSweep(sweepFigure(d), d.sweep_image), d.sweep_image);
  return d;
}

}  // namespace mx::gui
