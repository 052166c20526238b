#include "control_plots.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "plot_legend.h"

namespace mx::widgets {

namespace {
const QColor kReferenceColor(30, 30, 30);
const QColor kModelColor(255, 127, 14);
const QColor kPlantColor(31, 119, 180);
const QColor kDepthColor(150, 150, 150);
const QColor kErrorColor(214, 39, 40);
const QColor kFeedColor(44, 160, 44);
const QColor kLimitColor(214, 39, 40);
const QColor kThetaColors[] = {QColor(31, 119, 180),  QColor(255, 127, 14), QColor(44, 160, 44),  QColor(214, 39, 40),
                               QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194)};
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMinWidth = 340;      // the view fits 1366 px wide screens
constexpr int kLegendColumns = 5;   // at most: the force row's and the estimates' entries
constexpr int kValueTicks = 3;      // value axes: labels that stay apart in a row of kMinRowHeight
constexpr int kMarginsGuess = 140;  // the rows' left and right margins before the first layout

// Sets (keys, values) on a graph, the common length only, skipping non-finite values.
void setSeries(QCPGraph* graph, const QVector<double>& keys, const QVector<double>& values) {
  const qsizetype n = std::min(keys.size(), values.size());
  QVector<QCPGraphData> data;
  data.reserve(n);
  for (qsizetype i = 0; i < n; ++i)
    if (std::isfinite(keys[i]) && std::isfinite(values[i])) data.push_back(QCPGraphData(keys[i], values[i]));
  graph->data()->set(data, true);
}

QVector<double> times(const QVector<double>& v, double factor) {
  QVector<double> out(v);
  for (double& x : out) x *= factor;
  return out;
}

// The traces (N, mm, mm/s) in shop units: every conversion is a factor.
ControlTraces inUnits(const ControlTraces& t, const ShopUnits& u) {
  const double force = u.fromBase(Quantity::Force, 1.0);
  const double depth = u.fromBase(Quantity::Length, 1.0);
  const double feed = u.fromBase(Quantity::Feed, perMinute(1.0));
  ControlTraces s = t;
  for (auto [values, factor] : {std::pair{&s.reference_n, force},
                                {&s.model_n, force},
                                {&s.force_sampled_n, force},
                                {&s.error_n, force},
                                {&s.dense_force_n, force},
                                {&s.feed_mm_s, feed},
                                {&s.dense_feed_mm_s, feed},
                                {&s.depth_mm, depth}})
    *values = times(*values, factor);
  return s;
}

void widen(const QCPGraph* graph, double& lo, double& hi) {
  for (const QCPGraphData& d : *graph->data()) {
    lo = std::min(lo, d.value);
    hi = std::max(hi, d.value);
  }
}
}  // namespace

ControlPlots::ControlPlots(Rows rows, QWidget* parent)
    : QWidget(parent), rows_(rows), plot_(new QCustomPlot(this)), margin_group_(new QCPMarginGroup(plot_)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  plot_->setToolTip(
      tr("Closed loop under the \u03b2-FROH: wheel zooms and drag pans the shared time axis; a double click fits "
         "the data."));
  plot_->plotLayout()->clear();
  plot_->plotLayout()->setRowSpacing(0);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  // Dense continuous traces: fast polylines keep a repaint in milliseconds.
  plot_->setPlottingHint(QCP::phFastPolylines, true);

  QCPAxisRect* force = addRow(QString());
  force->axis(QCPAxis::atRight)->setVisible(true);
  QCPAxis* depth_axis = force->axis(QCPAxis::atRight);
  QCPAxis* force_axis = force->axis(QCPAxis::atLeft);
  QCPGraph* depth = addGraph(0, depth_axis, "depth", QString(), QPen(kDepthColor, 1.5));
  depth->setLineStyle(QCPGraph::lsStepLeft);
  depth->setBrush(QColor(150, 150, 150, 40));
  addGraph(0, force_axis, "force continuous", tr("Plant F_p between samples"), QPen(QColor(31, 119, 180, 150), 1.0));
  QCPGraph* reference =
      addGraph(0, force_axis, "reference", tr("Reference F_r"), QPen(kReferenceColor, 1.5, Qt::DashLine));
  reference->setLineStyle(QCPGraph::lsStepLeft);
  QCPGraph* model = addGraph(0, force_axis, "model", tr("Model output F_m"), QPen(kModelColor, 1.5));
  model->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 3));
  QCPGraph* sampled = addGraph(0, force_axis, "force sampled", tr("Plant F_p at the samples"), QPen(kPlantColor, 1.5));
  sampled->setLineStyle(QCPGraph::lsNone);
  sampled->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));

  QCPAxisRect* error = addRow(QString());
  QCPGraph* e = addGraph(1, error->axis(QCPAxis::atLeft), "error", QString(), QPen(kErrorColor, 1.2));
  e->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 3));
  error->axis(QCPAxis::atLeft)->grid()->setZeroLinePen(QPen(QColor(90, 90, 90), 1.0));

  QCPAxisRect* feed = addRow(QString());
  QCPAxis* feed_axis = feed->axis(QCPAxis::atLeft);
  addGraph(2, feed_axis, "feed continuous", tr("Feed between samples"), QPen(QColor(44, 160, 44, 150), 1.0));
  QCPGraph* f = addGraph(2, feed_axis, "feed", tr("Control law f at the samples"), QPen(kFeedColor, 1.5));
  f->setLineStyle(QCPGraph::lsNone);
  f->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 4));
  addGraph(2, feed_axis, "feed limit", tr("Feed limit f_max"), QPen(kLimitColor, 1.5, Qt::DashLine));
  // Pareto paper, Fig. 6: the programmed point (N, b) changes, as vertical lines over the feed
  QCPGraph* changes = addGraph(2, feed_axis, "changes", tr("Change of programmed N or b"),
                               QPen(QColor(120, 70, 160), 1.2, Qt::DashDotLine));
  changes->setLineStyle(QCPGraph::lsImpulse);

  if (rows_ == Rows::All) addRow(tr("Estimates \u03b8 [\u2013]"));
  rects_.back()->axis(QCPAxis::atBottom)->setLabel(timeAxisLabel());
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] {
    fitRanges();
    plot_->replot(QCustomPlot::rpQueuedReplot);
  });
  connect(plot_, &QCustomPlot::beforeReplot, this, [this] { fitLegends(plot_->viewport().width()); });
  connect(plot_, &QCustomPlot::afterLayout, this, &ControlPlots::followLayout);
  relabel();
  // Every graph is still shown, so each legend holds all its entries. A first guess of the rows'
  // height; followLayout() makes it exact after each layout.
  plot_->setMinimumSize(legendsMinimumWidth(), static_cast<int>(rects_.size()) * (kMinRowHeight + 70));
  clear();
}

void ControlPlots::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, [this] {
    relabel();
    setTraces(ControlTraces(traces_));
  });
}

// The axis labels and legend names that carry a shop unit.
void ControlPlots::relabel() {
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString force = u.symbol(Quantity::Force), length = u.symbol(Quantity::Length);
  rects_[0]->axis(QCPAxis::atLeft)->setLabel(tr("Force F [%1]").arg(force));
  rects_[0]->axis(QCPAxis::atRight)->setLabel(tr("Depth of cut b [%1]").arg(length));
  rects_[1]->axis(QCPAxis::atLeft)->setLabel(tr("Error e [%1]").arg(force));
  rects_[2]->axis(QCPAxis::atLeft)->setLabel(tr("Feed f [%1]").arg(u.symbol(Quantity::Feed)));
  graphs_["depth"]->setName(tr("Depth b [%1] (right axis)").arg(length));
  graphs_["error"]->setName(tr("Tracking error e [%1]").arg(force));
  for (int row = 0; row < legends_.size(); ++row) refreshLegend(row);
}

QCPAxisRect* ControlPlots::addRow(const QString& value_label) {
  const int row = plot_->plotLayout()->rowCount();
  // The legend above its row, packed from the left where the axis rect starts: a strip of the legend
  // and a spacer (a legend alone would cap the width of the whole column at its own).
  auto* strip = new QCPLayoutGrid;
  plot_->plotLayout()->addElement(row, 0, strip);
  strip->setMarginGroup(QCP::msLeft | QCP::msRight, margin_group_);
  auto* legend = new QCPLegend;
  strip->addElement(0, 0, legend);
  strip->addElement(0, 1, new QCPLayoutElement(plot_));
  strip->setColumnSpacing(0);
  // The legend as narrow as its entries allow, the spacer taking the rest. A maximum width per entry
  // would do it too, but a column holding two entries then has its maximum below its minimum, which
  // QCPLayout::getSectionSizes cannot solve (it aborts the layout with a debug message).
  strip->setColumnStretchFactors({0.001, 1.0});
  legend->setLayer(QStringLiteral("legend"));
  legend->setFont(QFont(font().family(), 9));
  legend->setBorderPen(Qt::NoPen);
  legend->setBrush(Qt::NoBrush);
  legend->setMargins(QMargins(0, 4, 0, 1));  // flush with the axis rect's left edge
  legend->setRowSpacing(0);
  legend->setColumnSpacing(16);
  legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  legend->setWrap(kLegendColumns);
  auto* rect = new QCPAxisRect(plot_);
  plot_->plotLayout()->addElement(row + 1, 0, rect);
  plot_->plotLayout()->setRowStretchFactor(row, 0.001);
  rect->setMinimumSize(50, kMinRowHeight);
  rect->setMarginGroup(QCP::msLeft | QCP::msRight, margin_group_);
  rect->setRangeDrag(Qt::Horizontal);
  rect->setRangeZoom(Qt::Horizontal);
  rect->axis(QCPAxis::atLeft)->setLabel(value_label);
  for (QCPAxis* axis : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atRight)})
    axis->ticker()->setTickCount(kValueTicks);
  // The time axis is shared: ticks on every row, its label on the last one.
  QCPAxis* time = rect->axis(QCPAxis::atBottom);
  for (QCPAxis* axis : rect->axes()) axis->setLabelFont(QFont(font().family(), 9));
  connect(time, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this, rect] { syncTime(rect); });
  rects_.push_back(rect);
  legends_.push_back(legend);
  row_graphs_.push_back({});
  return rect;
}

QCPGraph* ControlPlots::addGraph(int row, QCPAxis* value_axis, const QString& key, const QString& legend_name,
                                 const QPen& pen) {
  QCPAxisRect* rect = rects_[row];
  QCPGraph* graph = plot_->addGraph(rect->axis(QCPAxis::atBottom), value_axis);
  graph->setName(legend_name);
  graph->setPen(pen);
  graph->setAdaptiveSampling(true);
  if (plot_->legend) graph->removeFromLegend(plot_->legend);
  graphs_.insert(key, graph);
  row_graphs_[row].push_back(graph);
  refreshLegend(row);
  return graph;
}

// The row's named, visible graphs in their order.
void ControlPlots::refreshLegend(int row) {
  QCPLegend* legend = legends_[row];
  legend->clearItems();
  for (QCPGraph* graph : std::as_const(row_graphs_[row])) {
    if (graph->name().isEmpty() || !graph->visible()) continue;
    graph->addToLegend(legend);
  }
  legend->setFillOrder(QCPLegend::foColumnsFirst, true);
}

// As wide as the widest legend entry needs beside the rows' margins: no name is cut at the minimum.
int ControlPlots::legendsMinimumWidth() const {
  int legends = 0;
  for (const QCPLegend* legend : legends_) legends = std::max(legends, legendWidthInOneColumn(legend));
  return std::max(kMinWidth, legends + kMarginsGuess);
}

// The legends' strips span the axis rects (one margin group).
int ControlPlots::legendWidth(int plot_width) const {
  const QMargins m = rects_.front()->margins();
  const int sides = m.left() + m.right() > 0 ? m.left() + m.right() : kMarginsGuess;
  return plot_width - sides;
}

bool ControlPlots::legendsFit(int plot_width) const {
  const int width = legendWidth(plot_width);
  for (const QCPLegend* legend : legends_)
    if (legend->wrap() != legendColumnsFitting(legend, width, kLegendColumns)) return false;
  return true;
}

void ControlPlots::fitLegends(int plot_width) {
  const int width = legendWidth(plot_width);
  for (QCPLegend* legend : std::as_const(legends_)) fitLegendColumns(legend, width, kLegendColumns);
}

// After a layout: the minimum height that gives each row kMinRowHeight with its legend and ticks, and
// another pass when the margins just found change the legends' columns.
void ControlPlots::followLayout() {
  const int needed = plot_->plotLayout()->minimumOuterSizeHint().height();
  // Queued: a resize inside the replot would not reach the plot's viewport.
  if (needed != plot_->minimumHeight())
    QMetaObject::invokeMethod(
        plot_, [plot = plot_, needed] { plot->setMinimumHeight(needed); }, Qt::QueuedConnection);
  if (!legendsFit(plot_->viewport().width())) plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ControlPlots::rebuildThetaGraphs(const QStringList& names) {
  if (rows_ != Rows::All) return;
  QStringList current;
  for (const QCPGraph* g : std::as_const(theta_graphs_)) current << g->name();
  if (current == names) return;
  for (QCPGraph* g : std::as_const(theta_graphs_)) {
    graphs_.remove(graphs_.key(g));
    g->removeFromLegend(legends_[3]);  // the plot removes it from its default legend only
    plot_->removeGraph(g);
  }
  theta_graphs_.clear();
  row_graphs_[3].clear();
  QCPAxis* axis = rects_[3]->axis(QCPAxis::atLeft);
  for (int i = 0; i < names.size(); ++i) {
    const QColor color = kThetaColors[static_cast<std::size_t>(i) % std::size(kThetaColors)];
    QCPGraph* g = addGraph(3, axis, QStringLiteral("theta ") + names[i], names[i], QPen(color, 1.5));
    theta_graphs_.push_back(g);
  }
}

void ControlPlots::setTraces(const ControlTraces& traces) {
  traces_ = traces;
  const ControlTraces t = inUnits(traces, DisplayUnits::of(units_));
  setSeries(graphs_["reference"], t.t_s, t.reference_n);
  setSeries(graphs_["model"], t.t_s, t.model_n);
  setSeries(graphs_["force sampled"], t.t_s, t.force_sampled_n);
  setSeries(graphs_["force continuous"], t.dense_t_s, t.dense_force_n);
  setSeries(graphs_["depth"], t.depth_t_s, t.depth_mm);
  setSeries(graphs_["error"], t.t_s, t.error_n);
  setSeries(graphs_["feed"], t.t_s, t.feed_mm_s);
  setSeries(graphs_["feed continuous"], t.dense_t_s, t.dense_feed_mm_s);
  const double top = t.feed_mm_s.isEmpty() ? 1.0 : *std::max_element(t.feed_mm_s.begin(), t.feed_mm_s.end());
  setSeries(graphs_["changes"], t.change_t_s, QVector<double>(t.change_t_s.size(), top));
  graphs_["changes"]->setVisible(!t.change_t_s.isEmpty());  // its legend entry follows in fitRanges()
  // Without the continuous feed, the samples are joined.
  graphs_["feed"]->setLineStyle(graphs_["feed continuous"]->dataCount() > 0 ? QCPGraph::lsNone : QCPGraph::lsLine);
  rebuildThetaGraphs(t.theta_names);
  for (int j = 0; j < theta_graphs_.size(); ++j) {
    QVector<double> values;
    values.reserve(t.theta.size());
    for (const QVector<double>& k : t.theta) values.push_back(j < k.size() ? k[j] : std::nan(""));
    setSeries(theta_graphs_[j], t.t_s, values);
  }
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ControlPlots::setFeedLimit(double feed_max_mm_s) {
  feed_max_mm_s_ = std::isfinite(feed_max_mm_s) && feed_max_mm_s > 0.0 ? feed_max_mm_s : 0.0;
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ControlPlots::setTitle(const QString& title) {
  if (title.isEmpty()) {
    if (title_) {
      plot_->plotLayout()->remove(title_);
      plot_->plotLayout()->simplify();
      title_ = nullptr;
    }
  } else {
    if (!title_) {
      plot_->plotLayout()->insertRow(0);
      title_ = new QCPTextElement(plot_, title, QFont(font().family(), 12, QFont::Bold));
      plot_->plotLayout()->addElement(0, 0, title_);
      plot_->plotLayout()->setRowStretchFactor(0, 0.001);
    }
    title_->setText(title);
  }
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ControlPlots::clear() {
  setTraces(ControlTraces{});
}

void ControlPlots::fitRanges() {
  // Time: the samples and the continuous output.
  double t0 = kInf, t1 = -kInf;
  for (const char* key : {"reference", "force sampled", "force continuous", "feed", "feed continuous"}) {
    const QCPGraph* g = graphs_[key];
    if (g->dataCount() == 0) continue;
    t0 = std::min(t0, g->data()->constBegin()->key);
    t1 = std::max(t1, (g->data()->constEnd() - 1)->key);
  }
  if (!(t1 > t0)) {  // no data, or a single instant
    t0 = std::isfinite(t0) ? t0 : 0.0;
    t1 = t0 + 1.0;
  }
  QCPGraph* limit = graphs_["feed limit"];
  const double feed_max = DisplayUnits::of(units_).fromBase(Quantity::Feed, perMinute(feed_max_mm_s_));
  if (feed_max_mm_s_ > 0.0)
    limit->setData({t0, t1}, {feed_max, feed_max}, true);
  else
    limit->data()->clear();
  limit->setVisible(feed_max_mm_s_ > 0.0);
  refreshLegend(2);
  syncing_ = true;
  for (QCPAxisRect* rect : std::as_const(rects_)) rect->axis(QCPAxis::atBottom)->setRange(t0, t1);
  syncing_ = false;

  for (QCPAxisRect* rect : std::as_const(rects_)) {
    for (QCPAxis* axis : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atRight)}) {
      double lo = kInf, hi = -kInf;
      for (const QCPGraph* g : axis->graphs()) widen(g, lo, hi);
      if (axis->axisType() == QCPAxis::atRight) {  // depth: from 0, in the lower part of the row
        axis->setRange(0.0, hi > 0.0 ? 1.6 * hi : 1.0);
        continue;
      }
      if (!(hi >= lo)) {
        lo = 0.0;
        hi = 1.0;
      }
      const double pad = hi > lo ? 0.08 * (hi - lo) : std::max(1.0, 0.1 * std::abs(hi));
      axis->setRange(lo - pad, hi + pad);
    }
  }
}

void ControlPlots::syncTime(const QCPAxisRect* source) {
  if (syncing_) return;
  syncing_ = true;
  const QCPRange range = source->axis(QCPAxis::atBottom)->range();
  for (QCPAxisRect* rect : std::as_const(rects_))
    if (rect != source) rect->axis(QCPAxis::atBottom)->setRange(range);
  syncing_ = false;
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

int ControlPlots::graphPointCount(const QString& name) const {
  const QCPGraph* g = graphs_.value(name, nullptr);
  return g ? g->dataCount() : -1;
}

QStringList ControlPlots::graphNames() const {
  QStringList names = graphs_.keys();
  names.sort();
  return names;
}

QString ControlPlots::valueAxisLabel(int row) const {
  return row >= 0 && row < rects_.size() ? rects_[row]->axis(QCPAxis::atLeft)->label() : QString();
}

QString ControlPlots::timeAxisLabel() const {
  return tr("Time t [s]");
}

QStringList ControlPlots::legendNames(int row) const {
  QStringList names;
  if (row < 0 || row >= legends_.size()) return names;
  for (int i = 0; i < legends_[row]->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(legends_[row]->item(i)))
      if (item->plottable()->visible()) names << item->plottable()->name();
  return names;
}

QPair<double, double> ControlPlots::timeRange() const {
  const QCPRange r = rects_.front()->axis(QCPAxis::atBottom)->range();
  return {r.lower, r.upper};
}

QPair<double, double> ControlPlots::valueRange(int row) const {
  if (row < 0 || row >= rects_.size()) return {0.0, 0.0};
  const QCPRange r = rects_[row]->axis(QCPAxis::atLeft)->range();
  return {r.lower, r.upper};
}

// The legends fitted to the image's width: once with the screen's margins, again with the image's.
bool ControlPlots::savePng(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  fitLegends(width);
  plot_->toPixmap(width, height);  // lays the plot out at the image's size
  fitLegends(width);
  const bool saved = plot_->savePng(path, width, height);
  plot_->replot(QCustomPlot::rpQueuedReplot);  // back to the screen's legends
  return saved;
}

bool ControlPlots::saveResponses(const ControlTraces& traces, double feed_max_mm_s, const QString& path, int width,
                                 int height, const QString& title, DisplayUnits* units) {
  ControlPlots exporter(Rows::Responses);
  exporter.setUnits(units);
  exporter.resize(width, height);
  exporter.setFeedLimit(feed_max_mm_s);
  exporter.setTraces(traces);
  exporter.setTitle(title);
  return exporter.savePng(path, width, height);
}

}  // namespace mx::widgets
