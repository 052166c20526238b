#include "report_figures.h"

#include <qcustomplot.h>

#include <QPen>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mx::gui {

namespace {

constexpr std::size_t kMaxSamples = 6000;

QFont plotFont(int point_size) {
  return QFont("DejaVu Sans", point_size);
}

void styleAxes(QCPAxisRect* rect) {
  for (QCPAxis* axis : rect->axes()) {
    axis->setLabelFont(plotFont(14));
    axis->setTickLabelFont(plotFont(13));
  }
}

QCPGraph* addCurve(QCustomPlot& plot, QCPAxisRect* rect, const QVector<double>& x, const QVector<double>& y,
                   const QString& name, const QPen& pen) {
  QCPGraph* graph = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  graph->setName(name);
  graph->setPen(pen);
  graph->setData(x, y, true);
  return graph;
}

QCPLegend* addLegend(QCPAxisRect* rect) {
  auto* legend = new QCPLegend;
  rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
  legend->setLayer("legend");
  legend->setFont(plotFont(12));
  legend->setBrush(QColor(255, 255, 255, 220));
  return legend;
}

}  // namespace

bool ReportFigureRenderer::renderLobes(const LobeFigureInput& in, const QString& path) const {
  // The chart uses the widget font: render it smaller than the other figures so that its text is legible
  // once scaled to the page width.
  const int width = width_ * 4 / 5, height = height_ * 4 / 5;
  widgets::LobeChartView view;
  view.resize(width, height);
  view.setLengthUnit(units_.fromBase(widgets::Quantity::Length, 1.0), units_.symbol(widgets::Quantity::Length));
  view.setSeries({in.series}, in.delta_per_s, in.alpha);
  view.setActiveTool(0);
  if (auto* plot = qobject_cast<QCustomPlot*>(view.plotWidget())) plot->replot();  // paint buffers for the overlay
  if (!in.power_limit_mm.isEmpty()) view.setPowerLimit(in.power_limit_mm, in.power_limit_label);
  view.setMarker("q*", in.q_star_rpm, in.q_star_mm, QColor(0, 90, 200));
  if (in.has_q_star_star) view.setMarker("q**", in.q_star_star_rpm, in.q_star_star_mm, QColor(200, 60, 0));
  return view.saveImage(path, width, height);
}

bool ReportFigureRenderer::renderSimulation(const SimulationTrace& trace, double power_limit_w, const QString& title,
                                            const QString& path) const {
  QCustomPlot plot;
  plot.plotLayout()->clear();
  auto* heading = new QCPTextElement(&plot, title, plotFont(15));
  plot.plotLayout()->addElement(0, 0, heading);
  QVector<QCPAxisRect*> rects;
  for (int row = 0; row < 3; ++row) {
    auto* rect = new QCPAxisRect(&plot);
    plot.plotLayout()->addElement(row + 1, 0, rect);
    styleAxes(rect);
    rects.push_back(rect);
  }
  auto* group = new QCPMarginGroup(&plot);
  for (QCPAxisRect* rect : rects) rect->setMarginGroup(QCP::msLeft | QCP::msRight, group);

  const std::size_t n = trace.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + kMaxSamples - 1) / kMaxSamples);
  using widgets::Quantity;
  QVector<double> t, x, y, f, p;
  for (std::size_t i = 0; i < n; i += stride) {
    t.push_back(trace.time_s[i] * 1e3);
    x.push_back(trace.x_m[i] * 1e6);
    y.push_back(trace.y_m[i] * 1e6);
    f.push_back(units_.fromBase(Quantity::Force, trace.force_n[i]));
    p.push_back(units_.fromBase(Quantity::Power, trace.power_w[i]));
  }
  addCurve(plot, rects[0], t, x, "x", QPen(QColor(31, 119, 180), 1.2));
  addCurve(plot, rects[0], t, y, "y", QPen(QColor(214, 39, 40), 1.2));
  addCurve(plot, rects[1], t, f, "resultant |F|", QPen(QColor(44, 120, 44), 1.2));
  addCurve(plot, rects[2], t, p, "cutting power", QPen(QColor(148, 103, 189), 1.2));
  if (std::isfinite(power_limit_w) && power_limit_w > 0.0 && !t.isEmpty()) {
    const double limit = units_.fromBase(Quantity::Power, power_limit_w);
    addCurve(plot, rects[2], {t.front(), t.back()}, {limit, limit},
             QString("spindle limit %1").arg(units_.format(Quantity::Power, power_limit_w)),
             QPen(QColor(40, 40, 40), 1.5, Qt::DashLine));
  }
  const QString labels[] = {QString("Displacement [\u00b5m]"),
                            QString("Force [%1]").arg(units_.symbol(Quantity::Force)),
                            QString("Power [%1]").arg(units_.symbol(Quantity::Power))};
  for (int row = 0; row < 3; ++row) {
    rects[row]->axis(QCPAxis::atLeft)->setLabel(labels[row]);
    rects[row]->axis(QCPAxis::atBottom)->setLabel(row == 2 ? "Time t [ms]" : "");
    QCPLegend* legend = addLegend(rects[row]);
    for (int g = 0; g < plot.graphCount(); ++g)
      if (plot.graph(g)->valueAxis() == rects[row]->axis(QCPAxis::atLeft))
        legend->addItem(new QCPPlottableLegendItem(legend, plot.graph(g)));
  }
  plot.rescaleAxes();
  for (QCPAxisRect* rect : rects) {
    QCPAxis* value = rect->axis(QCPAxis::atLeft);
    const QCPRange r = value->range();
    value->setRange(r.lower - 0.05 * r.size(), r.upper + 0.25 * r.size());  // room for the legend
  }
  return plot.savePng(path, width_, static_cast<int>(height_ * 1.4));
}

bool ReportFigureRenderer::renderSweep(const SweepFigureInput& in, const QString& path) const {
  QCustomPlot plot;
  styleAxes(plot.axisRect());
  plot.legend->setVisible(true);
  plot.legend->setFont(plotFont(13));
  plot.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
  QVector<double> x(in.c1.begin(), in.c1.end());
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (std::size_t t = 0; t < in.cost.size(); ++t) {
    QVector<double> y(in.cost[t].begin(), in.cost[t].end());
    for (double v : y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    QCPGraph* g = addCurve(plot, plot.axisRect(), x, y, in.tool_ids.value(static_cast<qsizetype>(t)),
                           QPen(widgets::LobeChartView::toolColor(static_cast<int>(t)), 2.0));
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
  }
  plot.xAxis->setLabel(QString("Power weight c1 [-]   (c2 = 1 - c1 - c3, c3 = %1)").arg(in.c3, 0, 'g', 4));
  plot.yAxis->setLabel("Minimum tool cost C [-]");
  const bool log = std::isfinite(lo) && lo > 0.0 && hi / lo > 30.0;
  if (log) {
    plot.yAxis->setScaleType(QCPAxis::stLogarithmic);
    plot.yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  }
  plot.rescaleAxes();
  if (std::isfinite(lo)) plot.yAxis->setRange(log ? lo / 1.5 : 0.0, log ? hi * 3.0 : hi * 1.15);
  if (in.current_c1 >= 0.0 && std::isfinite(lo)) {
    addCurve(
        plot, plot.axisRect(), {in.current_c1, in.current_c1}, {plot.yAxis->range().lower, plot.yAxis->range().upper},
        QString("weights used (c1 = %1)").arg(in.current_c1, 0, 'g', 4), QPen(QColor(60, 60, 60), 1.2, Qt::DashLine));
  }
  return plot.savePng(path, width_, height_);
}

}  // namespace mx::gui
