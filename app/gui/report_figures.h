#pragma once
// Offscreen renderer of the report's figures (PNG files): the lobe chart of the selected tool with the
// q* and q** markers (widgets::LobeChartView), the time-domain simulation of q** (displacement,
// resultant force and cutting power against time; QCustomPlot) and the seed's figure 4 sweep (minimum
// tool cost of every tool against c1 at a fixed c3). Needs a QApplication (any platform, e.g.
// offscreen). Depth, force and power are drawn in the given shop units. Every render* returns false when
// the image cannot be written.
#include <QString>
#include <QStringList>
#include <QVector>
#include <vector>

#include "lobe_chart_view.h"
#include "shop_units.h"
#include "simulation/simulation_types.h"

namespace mx::gui {

struct LobeFigureInput {
  widgets::ToolLobeSeries series;  // nominal and margined envelopes of the selected tool
  double delta_per_s = 0.0;
  double alpha = 1.0;
  QVector<double> power_limit_mm;  // on series.speed_rpm; empty = none
  QString power_limit_label;
  double q_star_rpm = 0.0, q_star_mm = 0.0;
  bool has_q_star_star = false;
  double q_star_star_rpm = 0.0, q_star_star_mm = 0.0;
};

struct SweepFigureInput {
  double c3 = 0.0;
  double current_c1 = -1.0;  // vertical marker; < 0 = none
  std::vector<double> c1;
  QStringList tool_ids;
  std::vector<std::vector<double>> cost;  // [tool][i], NaN where the tool has no admissible point
};

class ReportFigureRenderer {
 public:
  explicit ReportFigureRenderer(int width = 1200, int height = 675,
                                const widgets::ShopUnits& units = widgets::ShopUnits::metric())
      : width_(width), height_(height), units_(units) {}

  bool renderLobes(const LobeFigureInput& input, const QString& path) const;
  // Displacement x, y [µm], resultant force and power (with the spindle limit, if finite)
  // against time [ms]; at most ~6000 samples per curve are drawn.
  bool renderSimulation(const SimulationTrace& trace, double power_limit_w, const QString& title,
                        const QString& path) const;
  bool renderSweep(const SweepFigureInput& input, const QString& path) const;

 private:
  int width_;
  int height_;
  widgets::ShopUnits units_;
};

}  // namespace mx::gui
