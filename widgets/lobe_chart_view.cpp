#include "lobe_chart_view.h"

#include <QVBoxLayout>
#include <cmath>
#include <qcustomplot.h>

namespace mx::widgets {

LobeChartView::LobeChartView(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  plot_->xAxis->setLabel("Spindle speed N [rpm]");
  plot_->yAxis->setLabel("Axial depth of cut b [mm]");
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setToolTip(tr("Stability lobes: below a curve the cut is chatter-free. Wheel zooms, drag pans."));
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this](QMouseEvent* event) {
    const double rpm = plot_->xAxis->pixelToCoord(event->position().x());
    const double mm = plot_->yAxis->pixelToCoord(event->position().y());
    emit operatingPointPicked(rpm, mm);
  });
}

QColor LobeChartView::toolColor(int index) {
  static const QColor palette[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44),
                                   QColor(148, 103, 189), QColor(255, 127, 14), QColor(23, 190, 207)};
  return palette[index % 6];
}

void LobeChartView::clear() {
  plot_->clearGraphs();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void LobeChartView::setSeries(const QVector<ToolLobeSeries>& series, double delta_per_s, double alpha) {
  plot_->clearGraphs();
  double max_depth = 0.0, min_speed = 1e300, max_speed = 0.0;
  for (int i = 0; i < series.size(); ++i) {
    const ToolLobeSeries& s = series[i];
    const QColor color = toolColor(i);
    QCPGraph* nominal = plot_->addGraph();
    nominal->setName(QString("%1 nominal (\u03b4 = 0, \u03b1 = 1)").arg(s.tool_id));
    nominal->setPen(QPen(color, 2.0));
    nominal->setData(s.speed_rpm, s.nominal_mm, true);
    QCPGraph* margined = plot_->addGraph();
    margined->setName(QString("%1 margined (\u03b4 = %2 1/s, \u03b1 = %3)").arg(s.tool_id).arg(delta_per_s).arg(alpha));
    margined->setPen(QPen(color, 1.5, Qt::DashLine));
    margined->setData(s.speed_rpm, s.margined_mm, true);
    for (int j = 0; j < s.speed_rpm.size(); ++j) {
      if (std::isfinite(s.nominal_mm[j])) max_depth = std::max(max_depth, s.nominal_mm[j]);
      min_speed = std::min(min_speed, s.speed_rpm[j]);
      max_speed = std::max(max_speed, s.speed_rpm[j]);
    }
  }
  if (max_speed > min_speed) plot_->xAxis->setRange(min_speed, max_speed);
  // Show the interesting part: up to three times the highest of the tools' lowest lobes.
  double highest_minimum = 0.0;
  for (const ToolLobeSeries& s : series) {
    double lowest = max_depth;
    for (double b : s.nominal_mm)
      if (std::isfinite(b)) lowest = std::min(lowest, b);
    highest_minimum = std::max(highest_minimum, lowest);
  }
  plot_->yAxis->setRange(0.0, std::min(max_depth, std::max(3.0 * highest_minimum, 1e-3)) * 1.05 + 1e-6);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

bool LobeChartView::saveImage(const QString& path, int width, int height) {
  plot_->replot();
  if (path.endsWith(".pdf", Qt::CaseInsensitive)) return plot_->savePdf(path, width, height);
  return plot_->savePng(path, width, height);
}

}  // namespace mx::widgets
