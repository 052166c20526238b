#include "spectrum_plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "plot_legend.h"
#include "simulation/amplitude_spectrum.h"

namespace mx::widgets {

namespace {
const QColor kSpectrumColor(31, 119, 180);
const QColor kHarmonicColor(110, 110, 110);
const QColor kChatterColor(214, 39, 40);
constexpr int kMaxHarmonicMarkers = 24;
constexpr int kMaxHarmonicLabels = 8;
}  // namespace

SpectrumSeries SpectrumPlot::computeSpectrum(std::span<const double> signal, double sample_rate_hz,
                                             double tooth_passing_hz, double extra_hz, int max_points) {
  SpectrumSeries out;
  if (signal.size() < 4 || !(sample_rate_hz > 0.0) || !std::isfinite(sample_rate_hz)) return out;
  const AmplitudeSpectrum spectrum(signal, sample_rate_hz);
  const double bin = spectrum.binHz();
  const double ftp = tooth_passing_hz > 0.0 ? tooth_passing_hz : 0.0;
  double max_hz = 5.0 * ftp;
  if (ftp > 0.0) {
    const auto peak = spectrum.largestPeak([&](double f) {
      const double h = std::round(f / ftp);
      return std::abs(f - h * ftp) <= std::max(3.0 * bin, 0.02 * ftp);
    });
    if (peak) max_hz = std::max(max_hz, 1.25 * peak->frequency_hz);
  }
  if (extra_hz > 0.0) max_hz = std::max(max_hz, 1.25 * extra_hz);
  const double nyquist = 0.5 * sample_rate_hz;
  max_hz = max_hz > 0.0 ? std::min(max_hz, nyquist) : nyquist;

  const auto bins = std::min(spectrum.bins(), static_cast<std::size_t>(std::floor(max_hz / bin)) + 1);
  const auto group = std::max<std::size_t>(1, (bins + static_cast<std::size_t>(std::max(max_points, 1)) - 1) /
                                                  static_cast<std::size_t>(std::max(max_points, 1)));
  const std::vector<double>& a = spectrum.amplitude();
  for (std::size_t k = 0; k < bins; k += group) {
    std::size_t best = k;  // keep each group's peak, at its own frequency
    for (std::size_t j = k; j < std::min(k + group, bins); ++j)
      if (a[j] > a[best]) best = j;
    out.hz.push_back(spectrum.frequencyOfBin(best));
    out.amplitude.push_back(a[best]);
  }
  return out;
}

SpectrumPlot::SpectrumPlot(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  plot_->xAxis->setLabel(tr("Frequency f [Hz]"));
  plot_->yAxis->setLabel(tr("Force amplitude |F| [N]"));
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->legend->setBrush(QColor(255, 255, 255, 210));
  placeLegendUnderPlot(plot_, 2);  // never over a peak or a harmonic's label
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setToolTip(
      tr("Amplitude spectrum of the resultant cutting force. Peaks away from the tooth-passing "
         "harmonics (grey) are self-excited vibration (chatter)."));

  amplitude_ = plot_->addGraph();
  amplitude_->setName(tr("Resultant force |F|"));
  amplitude_->setPen(QPen(kSpectrumColor, 1.5));
  harmonic_legend_ = plot_->addGraph();
  harmonic_legend_->setName(tr("Tooth-passing harmonics h\u00b7f_tp"));
  harmonic_legend_->setPen(QPen(kHarmonicColor, 1.0, Qt::DashLine));
  chatter_legend_ = plot_->addGraph();
  chatter_legend_->setName(tr("Chatter frequency f_c"));
  chatter_legend_->setPen(QPen(kChatterColor, 2.0));
  harmonic_legend_->removeFromLegend();
  chatter_legend_->removeFromLegend();
  plot_->xAxis->setRange(0.0, 1000.0);
  plot_->yAxis->setRange(0.0, 1.0);
}

int SpectrumPlot::pointCount() const {
  return amplitude_->dataCount();
}

void SpectrumPlot::setSpectrum(const SpectrumSeries& spectrum, const QString& label) {
  amplitude_->setData(spectrum.hz, spectrum.amplitude, true);
  amplitude_->setName(label.isEmpty() ? tr("Resultant force |F|") : tr("Resultant force |F| (%1)").arg(label));
  double top = 0.0;
  // The mean (f = 0) is removed; scale to the largest bin.
  for (double v : spectrum.amplitude) top = std::max(top, v);
  // Show where the content is: up to 1.25 times the highest bin above 1 % of the largest, and at
  // least four tooth-passing harmonics (not the whole Nyquist range).
  max_hz_ = 0.0;
  for (qsizetype i = spectrum.hz.size() - 1; i >= 0; --i)
    if (spectrum.amplitude[i] > 0.01 * top) {
      max_hz_ = 1.25 * spectrum.hz[i];
      break;
    }
  max_hz_ = std::max(max_hz_, 4.5 * tooth_passing_hz_);
  if (!spectrum.hz.isEmpty()) max_hz_ = std::min(max_hz_, spectrum.hz.back());
  if (max_hz_ > 0.0) plot_->xAxis->setRange(0.0, max_hz_);
  plot_->yAxis->setRange(0.0, top > 0.0 ? 1.12 * top : 1.0);
  rebuildMarkers();
}

void SpectrumPlot::setAmplitudeUnit(const QString& symbol) {
  plot_->yAxis->setLabel(tr("Force amplitude |F| [%1]").arg(symbol));
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SpectrumPlot::setToothPassingHz(double hz) {
  tooth_passing_hz_ = hz > 0.0 && std::isfinite(hz) ? hz : 0.0;
  rebuildMarkers();
}

void SpectrumPlot::setChatterFrequency(std::optional<double> hz) {
  chatter_hz_ = hz && std::isfinite(*hz) && *hz > 0.0 ? hz : std::nullopt;
  rebuildMarkers();
}

void SpectrumPlot::clear() {
  amplitude_->data()->clear();
  amplitude_->setName(tr("Resultant force |F|"));
  chatter_hz_.reset();
  max_hz_ = 0.0;
  plot_->yAxis->setRange(0.0, 1.0);
  rebuildMarkers();
}

void SpectrumPlot::replotQueued() {
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SpectrumPlot::rebuildMarkers() {
  for (QCPAbstractItem* item : markers_) plot_->removeItem(item);
  markers_.clear();
  auto addLine = [&](double f, const QPen& pen) {
    auto* line = new QCPItemStraightLine(plot_);
    line->setPen(pen);
    line->point1->setCoords(f, 0.0);
    line->point2->setCoords(f, 1.0);
    markers_.push_back(line);
  };
  auto addLabel = [&](double f, const QString& text, const QColor& color, double y_ratio) {
    auto* label = new QCPItemText(plot_);
    label->position->setTypeX(QCPItemPosition::ptPlotCoords);
    label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    label->position->setCoords(f, y_ratio);
    label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    label->setPadding(QMargins(3, 0, 0, 0));
    label->setColor(color);
    label->setFont(QFont(font().family(), 9));
    label->setText(text);
    label->setClipToAxisRect(true);
    markers_.push_back(label);
  };

  harmonic_count_ = 0;
  const double range_hz = max_hz_ > 0.0 ? max_hz_ : plot_->xAxis->range().upper;
  if (tooth_passing_hz_ > 0.0) {
    for (int h = 1; h <= kMaxHarmonicMarkers && h * tooth_passing_hz_ <= range_hz; ++h) {
      addLine(h * tooth_passing_hz_, QPen(kHarmonicColor, 1.0, Qt::DashLine));
      if (h <= kMaxHarmonicLabels)
        addLabel(h * tooth_passing_hz_, h == 1 ? tr("f_tp") : tr("%1f_tp").arg(h), kHarmonicColor, 0.02);
      ++harmonic_count_;
    }
    harmonic_legend_->setName(
        tr("Tooth-passing harmonics h\u00b7f_tp (f_tp = %1 Hz)").arg(tooth_passing_hz_, 0, 'f', 1));
    harmonic_legend_->addToLegend();
  } else {
    harmonic_legend_->removeFromLegend();
  }
  if (chatter_hz_) {
    addLine(*chatter_hz_, QPen(kChatterColor, 2.0));
    addLabel(*chatter_hz_, tr("f_c = %1 Hz").arg(*chatter_hz_, 0, 'f', 1), kChatterColor, 0.10);
    chatter_legend_->setName(tr("Chatter frequency f_c = %1 Hz").arg(*chatter_hz_, 0, 'f', 1));
    chatter_legend_->addToLegend();
  } else {
    chatter_legend_->removeFromLegend();
  }
  replotQueued();
}

}  // namespace mx::widgets
