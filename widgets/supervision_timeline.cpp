#include "supervision_timeline.h"

#include <qcustomplot.h>

#include <QHelpEvent>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mx::widgets {

namespace {
const QColor kForce(31, 119, 180), kPower(255, 127, 14), kLimit(214, 39, 40), kReference(60, 60, 60);
const char* const kLetters = "ABCDEFGHIJKL";
const char* const kCaptions[] = {"feedrate routine",  "operator input",  "feed hold",           "operator chatter",
                                 "auto chatter det.", "chatter suppr.",  "suppression routine", "parameter estim.",
                                 "force processor",   "contact monitor", "adaptive force ctrl", "model-based ctrl"};
const QColor kModuleColors[] = {QColor(31, 119, 180),  QColor(174, 199, 232), QColor(214, 39, 40),
                                QColor(255, 152, 150), QColor(148, 103, 189), QColor(197, 176, 213),
                                QColor(140, 86, 75),   QColor(227, 119, 194), QColor(44, 160, 44),
                                QColor(152, 223, 138), QColor(255, 127, 14),  QColor(188, 189, 34)};
constexpr double kEventsRow = -1.0;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

QColor eventColor(const QString& type) {
  if (type.contains(QLatin1String("chatter"), Qt::CaseInsensitive)) return QColor(214, 39, 40);
  if (type.contains(QLatin1String("hold"), Qt::CaseInsensitive)) return QColor(255, 127, 14);
  if (type.contains(QLatin1String("contact"), Qt::CaseInsensitive)) return QColor(44, 160, 44);
  return QColor(110, 110, 110);
}
}  // namespace

QString SupervisionTimeline::moduleCaption(const QString& letter) {
  const int i = letter.size() == 1 ? static_cast<int>(QByteArray(kLetters).indexOf(letter.at(0).toLatin1())) : -1;
  return i >= 0 ? letter + QStringLiteral("  ") + QLatin1String(kCaptions[i]) : letter;
}

SupervisionTimeline::SupervisionTimeline(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  setObjectName(QStringLiteral("supervisionTimeline"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  setMinimumSize(520, 320);
  plot_->setToolTip(
      tr("Wheel zooms and drag pans the shared time axis; a double click fits the data. Hover an "
         "event marker for its details."));
  plot_->installEventFilter(this);
  plot_->plotLayout()->clear();
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setPlottingHint(QCP::phFastPolylines, true);
  const QFont label_font(font().family(), 9);

  auto* group = new QCPMarginGroup(plot_);
  auto* legend = new QCPLegend;
  plot_->plotLayout()->addElement(0, 0, legend);
  legend->setLayer(QStringLiteral("legend"));
  legend->setFont(QFont(font().family(), 9));
  legend->setBorderPen(Qt::NoPen);
  legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  legend->setWrap(3);
  legend->setColumnSpacing(20);
  legend->setMargins(QMargins(4, 2, 4, 2));
  plot_->plotLayout()->setRowStretchFactor(0, 0.001);

  signals_rect_ = new QCPAxisRect(plot_);
  modules_rect_ = new QCPAxisRect(plot_);
  plot_->plotLayout()->addElement(1, 0, signals_rect_);
  plot_->plotLayout()->addElement(2, 0, modules_rect_);
  plot_->plotLayout()->setRowStretchFactor(1, 1.2);
  plot_->plotLayout()->setRowStretchFactor(2, 1.0);
  for (QCPAxisRect* rect : {signals_rect_, modules_rect_}) {
    rect->setMarginGroup(QCP::msLeft | QCP::msRight, group);
    rect->setRangeDrag(Qt::Horizontal);
    rect->setRangeZoom(Qt::Horizontal);
    for (QCPAxis* axis : rect->axes()) axis->setLabelFont(label_font);
    connect(rect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
            [this, rect] { syncTime(rect); });
  }
  QCPAxis* t_top = signals_rect_->axis(QCPAxis::atBottom);
  QCPAxis* f_axis = signals_rect_->axis(QCPAxis::atLeft);
  QCPAxis* p_axis = signals_rect_->axis(QCPAxis::atRight);
  f_axis->setLabelColor(kForce);
  p_axis->setVisible(true);
  p_axis->setLabelColor(kPower.darker(130));
  auto add = [&](QCPAxis* value, const QString& name, const QPen& pen) {
    QCPGraph* g = plot_->addGraph(t_top, value);
    g->setName(name);
    g->setPen(pen);
    g->setAdaptiveSampling(true);
    if (plot_->legend) g->removeFromLegend(plot_->legend);
    g->addToLegend(legend);
    return g;
  };
  force_ = add(f_axis, QString(), QPen(kForce, 1.6));
  reference_ = add(f_axis, QString(), QPen(kReference, 1.4, Qt::DashLine));
  power_ = add(p_axis, QString(), QPen(kPower, 1.6));
  limit_ = add(p_axis, QString(), QPen(kLimit, 1.6, Qt::DashLine));
  relabel();

  QCPAxis* t_axis = modules_rect_->axis(QCPAxis::atBottom);
  QCPAxis* m_axis = modules_rect_->axis(QCPAxis::atLeft);
  t_axis->setLabel(tr("Time t [s]"));
  m_axis->setLabel(tr("Module (Table 1)"));
  m_axis->setRangeReversed(true);
  m_axis->grid()->setVisible(false);
  m_axis->setTickLabelFont(QFont(font().family(), 8));
  event_marks_ = plot_->addGraph(t_axis, m_axis);
  event_marks_->setName(tr("Event (hover for details)"));
  event_marks_->setLineStyle(QCPGraph::lsNone);
  event_marks_->setScatterStyle(
      QCPScatterStyle(QCPScatterStyle::ssTriangleInverted, QColor(60, 60, 60), QColor(60, 60, 60), 9));
  if (plot_->legend) event_marks_->removeFromLegend(plot_->legend);
  event_marks_->addToLegend(legend);
  for (int i = 0; i < 12; ++i) moduleGraph(QString(QLatin1Char(kLetters[i])));
  clear();
}

void SupervisionTimeline::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &SupervisionTimeline::rescale);
}

// The force and power axes and names in the shop units.
void SupervisionTimeline::relabel() {
  const ShopUnits& u = DisplayUnits::of(units_);
  const QString force = u.symbol(Quantity::Force), power = u.symbol(Quantity::Power);
  signals_rect_->axis(QCPAxis::atLeft)->setLabel(tr("Force F_Y [%1]").arg(force));
  signals_rect_->axis(QCPAxis::atRight)->setLabel(tr("Spindle power P [%1]").arg(power));
  force_->setName(tr("F_Y = max |F_y| per revolution [%1]").arg(force));
  reference_->setName(tr("Force reference F_ref [%1]").arg(force));
  power_->setName(tr("Spindle power P [%1] (right axis)").arg(power));
  limit_->setName(tr("Power limit [%1] (right axis)").arg(power));
}

// The plotted force and power are in display units: a change of units scales them in place.
void SupervisionTimeline::rescale() {
  const ShopUnits& u = DisplayUnits::of(units_);
  const double force = u.fromBase(Quantity::Force, 1.0), power = u.fromBase(Quantity::Power, 1.0);
  for (auto [graph, ratio] : {std::pair{force_, force / force_scale_}, {power_, power / power_scale_}})
    for (QCPGraphData& point : *graph->data()) point.value *= ratio;
  force_scale_ = force;
  power_scale_ = power;
  relabel();
  updateLimitLines();
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

QCPGraph* SupervisionTimeline::moduleGraph(const QString& module) {
  if (QCPGraph* g = modules_.value(module)) return g;
  const int row = static_cast<int>(rows_.size());
  QCPGraph* g = plot_->addGraph(modules_rect_->axis(QCPAxis::atBottom), modules_rect_->axis(QCPAxis::atLeft));
  g->setName(module);
  if (plot_->legend) g->removeFromLegend(plot_->legend);
  QPen pen(kModuleColors[static_cast<std::size_t>(row) % std::size(kModuleColors)], 9);
  pen.setCapStyle(Qt::FlatCap);
  g->setPen(pen);
  g->setAdaptiveSampling(false);
  // Marks at the ends keep a short activity (an impulse action, F) visible at any zoom.
  g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, pen.color(), pen.color(), 7));
  modules_.insert(module, g);
  rows_ << module;
  auto ticker = QSharedPointer<QCPAxisTickerText>::create();
  ticker->addTick(kEventsRow, tr("Events"));
  for (int i = 0; i < rows_.size(); ++i) ticker->addTick(i, moduleCaption(rows_[i]));
  modules_rect_->axis(QCPAxis::atLeft)->setTicker(ticker);
  modules_rect_->axis(QCPAxis::atLeft)->setRange(kEventsRow - 0.7, rows_.size() - 0.4);
  return g;
}

void SupervisionTimeline::clear() {
  for (QCPGraph* g : {force_, reference_, power_, limit_, event_marks_}) g->data()->clear();
  for (QCPGraph* g : std::as_const(modules_)) g->data()->clear();
  for (QCPItemStraightLine* line : std::as_const(event_lines_)) plot_->removeItem(line);
  event_lines_.clear();
  spans_.clear();
  events_.clear();
  power_limit_w_ = force_reference_n_ = force_max_ = power_max_ = 0;
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SupervisionTimeline::appendSeries(const SupervisionSeries& chunk) {
  if (chunk.power_limit_w > 0) power_limit_w_ = chunk.power_limit_w;
  if (chunk.force_reference_n > 0) force_reference_n_ = chunk.force_reference_n;
  for (qsizetype i = 0; i < chunk.t_s.size(); ++i) {
    const double t = chunk.t_s[i];
    if (!std::isfinite(t)) continue;
    const double f = i < chunk.force_y_n.size() ? chunk.force_y_n[i] : kNaN;
    const double p = i < chunk.power_w.size() ? chunk.power_w[i] : kNaN;
    force_->addData(t, force_scale_ * f);
    power_->addData(t, power_scale_ * p);
    if (std::isfinite(f)) force_max_ = std::max(force_max_, f);
    if (std::isfinite(p)) power_max_ = std::max(power_max_, p);
  }
  updateLimitLines();
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SupervisionTimeline::setSeries(const SupervisionSeries& all) {
  force_->data()->clear();
  power_->data()->clear();
  force_max_ = power_max_ = 0;
  power_limit_w_ = force_reference_n_ = 0;
  appendSeries(all);
}

void SupervisionTimeline::updateLimitLines() {
  const int n = force_->dataCount();
  const double t0 = n ? force_->data()->constBegin()->key : 0.0, t1 = n ? (force_->data()->constEnd() - 1)->key : 1.0;
  const double limit = power_scale_ * power_limit_w_, reference = force_scale_ * force_reference_n_;
  if (power_limit_w_ > 0)
    limit_->setData({t0, t1}, {limit, limit}, true);
  else
    limit_->data()->clear();
  if (force_reference_n_ > 0)
    reference_->setData({t0, t1}, {reference, reference}, true);
  else
    reference_->data()->clear();
}

void SupervisionTimeline::setModuleSpans(const QVector<ModuleSpan>& spans) {
  spans_ = spans;
  for (QCPGraph* g : std::as_const(modules_)) g->data()->clear();
  QHash<QString, QVector<QCPGraphData>> module_points;
  for (const ModuleSpan& s : spans) {
    if (s.module.isEmpty() || !(s.to_s >= s.from_s)) continue;
    moduleGraph(s.module);
    QVector<QCPGraphData>& d = module_points[s.module];
    d << QCPGraphData(s.from_s, 0) << QCPGraphData(s.to_s, 0) << QCPGraphData(s.to_s, kNaN);
  }
  for (auto it = module_points.begin(); it != module_points.end(); ++it) {
    QCPGraph* g = modules_[it.key()];
    const double row = static_cast<double>(rows_.indexOf(it.key()));
    std::stable_sort(it.value().begin(), it.value().end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    for (QCPGraphData& p : it.value())
      if (!std::isnan(p.value)) p.value = row;
    g->data()->set(it.value(), true);
  }
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SupervisionTimeline::appendEvents(const QVector<SupervisionEventView>& events) {
  for (const SupervisionEventView& e : events) {
    events_ << e;
    event_marks_->addData(e.t_s, kEventsRow);
    for (QCPAxisRect* rect : {signals_rect_, modules_rect_}) {
      auto* line = new QCPItemStraightLine(plot_);
      line->setClipAxisRect(rect);
      line->setLayer(QStringLiteral("overlay"));
      for (QCPItemPosition* pos : {line->point1, line->point2}) {
        pos->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        pos->setAxisRect(rect);
      }
      line->point1->setCoords(e.t_s, 0);
      line->point2->setCoords(e.t_s, 1);
      QColor c = eventColor(e.type);
      c.setAlpha(150);
      line->setPen(QPen(c, 1.0, Qt::DotLine));
      event_lines_ << line;
    }
  }
  fitRanges();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void SupervisionTimeline::fitRanges() {
  double t0 = std::numeric_limits<double>::infinity(), t1 = -t0;
  if (force_->dataCount()) {
    t0 = force_->data()->constBegin()->key;
    t1 = (force_->data()->constEnd() - 1)->key;
  }
  for (const ModuleSpan& s : std::as_const(spans_)) {
    t0 = std::min(t0, s.from_s);
    t1 = std::max(t1, s.to_s);
  }
  for (const SupervisionEventView& e : std::as_const(events_)) {
    t0 = std::min(t0, e.t_s);
    t1 = std::max(t1, e.t_s);
  }
  if (!(t1 > t0)) {
    t0 = std::isfinite(t0) ? t0 : 0.0;
    t1 = t0 + 1.0;
  }
  syncing_ = true;
  signals_rect_->axis(QCPAxis::atBottom)->setRange(t0, t1 + 0.01 * (t1 - t0));
  modules_rect_->axis(QCPAxis::atBottom)->setRange(t0, t1 + 0.01 * (t1 - t0));
  syncing_ = false;
  const double f_hi = force_scale_ * std::max(force_max_, force_reference_n_);
  const double p_hi = power_scale_ * std::max(power_max_, power_limit_w_);
  signals_rect_->axis(QCPAxis::atLeft)->setRange(0, f_hi > 0 ? 1.12 * f_hi : 1.0);
  signals_rect_->axis(QCPAxis::atRight)->setRange(0, p_hi > 0 ? 1.12 * p_hi : 1.0);
}

void SupervisionTimeline::syncTime(QCPAxisRect* source) {
  if (syncing_) return;
  syncing_ = true;
  QCPAxisRect* other = source == signals_rect_ ? modules_rect_ : signals_rect_;
  other->axis(QCPAxis::atBottom)->setRange(source->axis(QCPAxis::atBottom)->range());
  syncing_ = false;
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

bool SupervisionTimeline::eventFilter(QObject* watched, QEvent* event) {
  if (watched == plot_ && event->type() == QEvent::MouseButtonDblClick) {
    fitRanges();
    plot_->replot(QCustomPlot::rpQueuedReplot);
  }
  if (watched == plot_ && event->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(event);
    const QCPAxis* t_axis = modules_rect_->axis(QCPAxis::atBottom);
    const double t = t_axis->pixelToCoord(help->pos().x());
    const double tol = std::abs(t_axis->pixelToCoord(help->pos().x() + 6) - t);
    const QString tip = eventToolTipAt(t, tol);
    if (!tip.isEmpty()) {
      QToolTip::showText(help->globalPos(), tip, plot_);
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

QString SupervisionTimeline::valueAxisLabel(bool power) const {
  return signals_rect_->axis(power ? QCPAxis::atRight : QCPAxis::atLeft)->label();
}

double SupervisionTimeline::valueAxisUpper(bool power) const {
  return signals_rect_->axis(power ? QCPAxis::atRight : QCPAxis::atLeft)->range().upper;
}

QString SupervisionTimeline::eventToolTipAt(double t_s, double tolerance_s) const {
  QStringList lines;
  for (const SupervisionEventView& e : events_)
    if (std::abs(e.t_s - t_s) <= tolerance_s)
      lines << tr("t = %1 s  %2%3")
                   .arg(e.t_s, 0, 'f', 3)
                   .arg(e.type, e.detail.isEmpty() ? QString() : QStringLiteral(": ") + e.detail);
  return lines.join(QLatin1Char('\n'));
}

int SupervisionTimeline::pointCount() const {
  return force_->dataCount();
}

int SupervisionTimeline::spanCount() const {
  return static_cast<int>(spans_.size());
}

int SupervisionTimeline::eventCount() const {
  return static_cast<int>(events_.size());
}

QStringList SupervisionTimeline::moduleRows() const {
  QStringList out;
  for (const QString& r : rows_) out << moduleCaption(r);
  return out;
}

double SupervisionTimeline::activeTimeOf(const QString& module) const {
  double total = 0;
  for (const ModuleSpan& s : spans_)
    if (s.module == module && s.to_s > s.from_s) total += s.to_s - s.from_s;
  return total;
}

QPair<double, double> SupervisionTimeline::timeRange() const {
  const QCPRange r = modules_rect_->axis(QCPAxis::atBottom)->range();
  return {r.lower, r.upper};
}

bool SupervisionTimeline::saveImage(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  return plot_->savePng(path, width, height);
}

}  // namespace mx::widgets
