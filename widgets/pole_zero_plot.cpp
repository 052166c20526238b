#include "pole_zero_plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "plot_legend.h"

namespace mx::widgets {

namespace {
const QColor kCircleColor(120, 120, 120);
const QColor kPoleColor(31, 119, 180);
const QColor kZeroColor(44, 160, 44);
const QColor kUnstableColor(214, 39, 40);
constexpr int kCirclePoints = 181;
constexpr double kCoincident = 1e-6;  // roots closer than this (relative) are one point
constexpr int kLegendColumns = 4;     // at most: every entry in one row when the width holds them

QCPCurve* addScatter(QCustomPlot* plot, const QString& name, const QCPScatterStyle& style) {
  auto* curve = new QCPCurve(plot->xAxis, plot->yAxis);
  curve->setName(name);
  curve->setLineStyle(QCPCurve::lsNone);
  curve->setScatterStyle(style);
  return curve;
}

bool finite(const std::complex<double>& z) {
  return std::isfinite(z.real()) && std::isfinite(z.imag());
}
}  // namespace

PoleZeroPlot::PoleZeroPlot(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  setMinimumSize(220, 210);  // as wide as "Unstable zeros |z| > 1"
  plot_->setToolTip(
      tr("Poles (\u00d7) and zeros (\u25cb) of the discretized plant H_\u03b2(z). A zero outside the unit circle "
         "(red) is an unstable zero: the model-following controller does not cancel it."));
  plot_->xAxis->setLabel(tr("Re z [\u2013]"));
  plot_->yAxis->setLabel(tr("Im z [\u2013]"));
  for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) axis->grid()->setZeroLinePen(QPen(QColor(170, 170, 170), 1.0));
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  placeLegendUnderPlot(plot_, kLegendColumns);  // never over the unit circle or a root
  plot_->legend->setMargins(QMargins(6, 1, 6, 1));
  plot_->legend->setRowSpacing(0);
  plot_->legend->setColumnSpacing(16);
  connect(plot_, &QCustomPlot::beforeReplot, this,
          [this] { fitLegendColumns(plot_->legend, plot_->viewport().width(), kLegendColumns); });
  caption_ = new QCPTextElement(plot_, QString(), QFont(font().family(), 10, QFont::Bold));
  plot_->plotLayout()->insertRow(0);
  plot_->plotLayout()->addElement(0, 0, caption_);
  plot_->plotLayout()->setRowStretchFactor(0, 0.001);

  circle_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
  circle_->setName(tr("Unit circle |z| = 1"));
  circle_->setPen(QPen(kCircleColor, 1.2, Qt::DashLine));
  QVector<double> t, x, y;
  for (int i = 0; i < kCirclePoints; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / (kCirclePoints - 1);
    t << i;
    x << std::cos(phi);
    y << std::sin(phi);
  }
  circle_->setData(t, x, y);
  poles_ = addScatter(plot_, tr("Poles \u00d7"),
                      QCPScatterStyle(QCPScatterStyle::ssCross, QPen(kPoleColor, 2.0), Qt::NoBrush, 12));
  zeros_ = addScatter(plot_, tr("Zeros \u25cb"),
                      QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kZeroColor, 2.0), Qt::NoBrush, 11));
  unstable_zeros_ = addScatter(plot_, tr("Unstable zeros |z| > 1"),
                               QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kUnstableColor, 2.5), Qt::NoBrush, 11));
  connect(plot_, &QCustomPlot::afterLayout, this, &PoleZeroPlot::applyEqualAspect);
  clear();
}

void PoleZeroPlot::clear() {
  setPoleZero(PoleZeroView{});
}

void PoleZeroPlot::setCaption(const QString& caption) {
  caption_->setText(caption);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PoleZeroPlot::setPoleZero(const PoleZeroView& pz) {
  x_lo_ = y_lo_ = -1.0;
  x_hi_ = y_hi_ = 1.0;
  for (QCPAbstractItem* item : std::as_const(labels_)) plot_->removeItem(item);
  labels_.clear();
  QVector<std::complex<double>> plotted;
  auto fill = [&](QCPCurve* curve, const QVector<std::complex<double>>& roots, auto keep) {
    QVector<QCPCurveData> points;
    for (const auto& z : roots) {
      if (!finite(z) || !keep(z)) continue;
      points.push_back(QCPCurveData(static_cast<double>(points.size()), z.real(), z.imag()));
      plotted.push_back(z);
      x_lo_ = std::min(x_lo_, z.real());
      x_hi_ = std::max(x_hi_, z.real());
      y_lo_ = std::min(y_lo_, z.imag());
      y_hi_ = std::max(y_hi_, z.imag());
    }
    curve->data()->set(points, true);
  };
  fill(poles_, pz.poles, [](const auto&) { return true; });
  addMultiplicityLabels(plotted);
  plotted.clear();
  fill(zeros_, pz.zeros, [](const auto& z) { return std::abs(z) <= 1.0; });
  fill(unstable_zeros_, pz.zeros, [](const auto& z) { return std::abs(z) > 1.0; });
  addMultiplicityLabels(plotted);
  if (unstable_zeros_->dataCount() > 0)
    unstable_zeros_->addToLegend();
  else
    unstable_zeros_->removeFromLegend();
  // A margin around the roots and the circle.
  const double pad = 0.12 * std::max(x_hi_ - x_lo_, y_hi_ - y_lo_);
  x_lo_ -= pad;
  x_hi_ += pad;
  y_lo_ -= pad;
  y_hi_ += pad;
  applyEqualAspect();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PoleZeroPlot::addMultiplicityLabels(const QVector<std::complex<double>>& roots) {
  QVector<bool> counted(roots.size(), false);
  for (qsizetype i = 0; i < roots.size(); ++i) {
    if (counted[i]) continue;
    int multiplicity = 1;
    for (qsizetype j = i + 1; j < roots.size(); ++j)
      if (!counted[j] && std::abs(roots[j] - roots[i]) <= kCoincident * std::max(1.0, std::abs(roots[i]))) {
        counted[j] = true;
        ++multiplicity;
      }
    if (multiplicity < 2) continue;
    auto* text = new QCPItemText(plot_);
    text->setLayer(QStringLiteral("overlay"));
    text->position->setCoords(roots[i].real(), roots[i].imag());
    text->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
    text->setPadding(QMargins(7, 0, 0, 5));
    text->setFont(QFont(font().family(), 9, QFont::Bold));
    text->setText(QString::number(multiplicity));
    labels_.push_back(text);
  }
}

void PoleZeroPlot::applyEqualAspect() {
  const QRect rect = plot_->axisRect()->rect();
  const double w = std::max(rect.width(), 1), h = std::max(rect.height(), 1);
  const double scale = std::max((x_hi_ - x_lo_) / w, (y_hi_ - y_lo_) / h);  // units per pixel
  const double cx = 0.5 * (x_lo_ + x_hi_), cy = 0.5 * (y_lo_ + y_hi_);
  plot_->xAxis->setRange(cx - 0.5 * scale * w, cx + 0.5 * scale * w);
  plot_->yAxis->setRange(cy - 0.5 * scale * h, cy + 0.5 * scale * h);
  // Called after the layout of a replot: the ticks were prepared for the old ranges.
  plot_->axisRect()->update(QCPLayoutElement::upPreparation);
}

int PoleZeroPlot::poleCount() const {
  return poles_->dataCount();
}

int PoleZeroPlot::zeroCount() const {
  return zeros_->dataCount() + unstable_zeros_->dataCount();
}

int PoleZeroPlot::unstableZeroCount() const {
  return unstable_zeros_->dataCount();
}

QStringList PoleZeroPlot::legendNames() const {
  QStringList names;
  for (int i = 0; i < plot_->legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i))) names << item->plottable()->name();
  return names;
}

QString PoleZeroPlot::xAxisLabel() const {
  return plot_->xAxis->label();
}

QString PoleZeroPlot::yAxisLabel() const {
  return plot_->yAxis->label();
}

QPair<double, double> PoleZeroPlot::xRange() const {
  return {plot_->xAxis->range().lower, plot_->xAxis->range().upper};
}

QPair<double, double> PoleZeroPlot::yRange() const {
  return {plot_->yAxis->range().lower, plot_->yAxis->range().upper};
}

double PoleZeroPlot::aspectRatio() const {
  const QRect rect = plot_->axisRect()->rect();
  if (rect.width() <= 0 || rect.height() <= 0) return 0.0;
  return (plot_->xAxis->range().size() / rect.width()) / (plot_->yAxis->range().size() / rect.height());
}

bool PoleZeroPlot::savePng(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  fitLegendColumns(plot_->legend, width, kLegendColumns);  // the image's width, not the screen's
  const bool saved = plot_->savePng(path, width, height);
  plot_->replot(QCustomPlot::rpQueuedReplot);
  return saved;
}

}  // namespace mx::widgets
