#include "trace_graph.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "trace_envelope.h"

namespace mx::widgets {

namespace {

QCPGraph* addGraph(QCustomPlot* plot, QCPAxis* value_axis, const QPen& pen) {
  QCPGraph* graph = plot->addGraph(plot->xAxis, value_axis);
  graph->setPen(pen);
  graph->setAdaptiveSampling(false);  // at most ~2 points per pixel column already
  return graph;
}

QVector<double> toVector(const std::vector<double>& v) {
  return QVector<double>(v.begin(), v.end());
}
}  // namespace

TraceGraph::TraceGraph(QCustomPlot* plot, QCPAxis* value_axis, const QColor& color, int band_alpha)
    : plot_(plot),
      raw_(addGraph(plot, value_axis, QPen(color, 1.0))),
      lower_(addGraph(plot, value_axis, QPen(color, 1.0))),
      upper_(addGraph(plot, value_axis, QPen(color, 1.0))) {
  band_ = color;
  band_.setAlpha(band_alpha);
  lower_->setBrush(band_);
  lower_->setChannelFillGraph(upper_);
  // The legend keeps the raw graph's entry (an entry added during a replot is not drawn).
  lower_->removeFromLegend();
  upper_->removeFromLegend();
  useEnvelope(false);
}

void TraceGraph::setName(const QString& name) {
  raw_->setName(name);
}

void TraceGraph::setShortestBucket(double seconds) {
  shortest_bucket_s_ = std::isfinite(seconds) && seconds > 0.0 ? seconds : 0.0;
}

// The raw graph has no data under an envelope; its brush then only draws the band in its legend icon.
void TraceGraph::useEnvelope(bool envelope) {
  envelope_ = envelope;
  raw_->setBrush(envelope ? QBrush(band_) : QBrush(Qt::NoBrush));
  lower_->setVisible(envelope);
  upper_->setVisible(envelope);
}

void TraceGraph::show(std::span<const double> time, std::span<const double> value) {
  const QCPRange range = plot_->xAxis->range();
  columns_ = std::max(1, plot_->axisRect()->width());
  const std::size_t n = std::min(time.size(), value.size());
  time = time.first(n);
  const bool envelope = samplesIn(time, range.lower, range.upper) > std::size_t(kRawSamplesPerColumn) * columns_;
  if (envelope != envelope_) useEnvelope(envelope);
  if (!envelope) {
    // The samples in range and one beyond each end, so that the trace reaches the axes.
    const auto first = std::lower_bound(time.begin(), time.end(), range.lower) - time.begin();
    const auto last = std::upper_bound(time.begin(), time.end(), range.upper) - time.begin();
    const auto from = std::max<std::ptrdiff_t>(0, first - 1);
    const auto to = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(n), last + 1);
    QVector<QCPGraphData> data;
    data.reserve(to - from);
    for (auto i = from; i < to; ++i) data.push_back(QCPGraphData(time[std::size_t(i)], value[std::size_t(i)]));
    raw_->data()->set(data, true);
    lower_->data()->clear();
    upper_->data()->clear();
    return;
  }
  buckets_ = columns_;
  if (shortest_bucket_s_ > 0.0) buckets_ = std::clamp(static_cast<int>(range.size() / shortest_bucket_s_), 1, columns_);
  const TraceEnvelope e = traceEnvelope(time, value, range.lower, range.upper, buckets_);
  const QVector<double> t = toVector(e.t);
  lower_->setData(t, toVector(e.lower), true);
  upper_->setData(t, toVector(e.upper), true);
  raw_->data()->clear();
}

int TraceGraph::drawnPoints() const {
  return envelope_ ? lower_->dataCount() + upper_->dataCount() : raw_->dataCount();
}

std::pair<double, double> TraceGraph::drawnRange() const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto widen = [&](const QCPGraph* g) {
    for (const QCPGraphData& d : *g->data()) {
      lo = std::min(lo, d.value);
      hi = std::max(hi, d.value);
    }
  };
  if (envelope_) {
    widen(lower_);
    widen(upper_);
  } else {
    widen(raw_);
  }
  return lo <= hi ? std::pair(lo, hi) : std::pair(0.0, 0.0);
}

}  // namespace mx::widgets
