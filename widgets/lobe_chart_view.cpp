#include "lobe_chart_view.h"

#include <qcustomplot.h>

#include <QHBoxLayout>
#include <QKeyEvent>
#include <QPainter>
#include <QSvgGenerator>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cost_map_layer.h"
#include "lobe_pockets.h"
#include "lobe_tool_panel.h"
#include "plot_legend.h"

namespace mx::widgets {

namespace {
const QColor kUnstableFill(214, 39, 40, 38);
const QColor kAdmissibleFill(44, 160, 44, 40);
const QColor kStyleKey(70, 70, 70);
constexpr int kLegendColumns = 2;
constexpr int kExportLegendColumns = 3;
constexpr int kMinExportPlotHeight = 560;  // px of axes and title an exported chart keeps

// A tool's list icon: its nominal line with its marker over its dashed margined line.
QIcon toolSwatch(int index) {
  QPixmap pixmap(44, 14);
  pixmap.fill(Qt::transparent);
  QCPPainter painter(&pixmap);
  painter.setRenderHint(QPainter::Antialiasing);
  const QColor c = LobeChartView::toolColor(index);
  painter.setPen(QPen(c, 2.0));
  painter.drawLine(QPointF(1, 4), QPointF(43, 4));
  painter.setPen(QPen(c, 1.5, Qt::DashLine));
  painter.drawLine(QPointF(1, 11), QPointF(43, 11));
  QCPScatterStyle shape(static_cast<QCPScatterStyle::ScatterShape>(LobeChartView::toolShape(index)), c, Qt::white, 8);
  shape.applyTo(&painter, QPen(c, 1.5));
  shape.drawShape(&painter, 22, 5);
  return QIcon(pixmap);
}

QColor verdictColor(PointVerdict v) {
  switch (v) {
    case PointVerdict::Stable:
      return QColor(30, 150, 30);
    case PointVerdict::Marginal:
      return QColor(200, 150, 0);
    case PointVerdict::Unstable:
      return QColor(200, 20, 20);
    case PointVerdict::LimitExceeded:
      return QColor(230, 120, 0);
    case PointVerdict::Unknown:
      break;
  }
  return QColor(90, 90, 90);
}
}  // namespace

LobeChartView::LobeChartView(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this)), costs_(new CostMapLayer(plot_)) {
  panel_ = new LobeToolPanel(this);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(plot_, 1);
  layout->addWidget(panel_);
  setFocusPolicy(Qt::StrongFocus);
  plot_->setFocusPolicy(Qt::NoFocus);
  plot_->setMouseTracking(true);  // the cursor readout follows the mouse without a button held
  plot_->installEventFilter(this);
  plot_->xAxis->setLabel("Spindle speed N [rpm]");
  plot_->yAxis->setLabel("Axial depth of cut b [mm]");
  title_ = new QCPTextElement(plot_, QString(), QFont(font().family(), 10, QFont::Bold));
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  plot_->legend->setBrush(QColor(255, 255, 255, 220));
  placeLegendUnderPlot(plot_, kLegendColumns);  // never over a lobe, a marker or the operating point
  plot_->setInteractions(QCP::iRangeZoom);      // left drag moves the point; right drag pans (below)
  plot_->setToolTip(
      tr("Drag with the left button to pick the operating point; arrow keys nudge it "
         "(Shift snaps to the grid). Wheel zooms, right button pans."));
  marker_ = new QCPItemTracer(plot_);
  marker_->setLayer("overlay");
  marker_->setStyle(QCPItemTracer::tsCircle);
  marker_->setSize(14);
  marker_->setVisible(false);
  marker_label_ = new QCPItemText(plot_);
  marker_label_->setLayer("overlay");
  marker_label_->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
  marker_label_->position->setParentAnchor(marker_->position);
  marker_label_->position->setCoords(10, -8);
  marker_label_->setVisible(false);
  connect(plot_, &QCustomPlot::mousePress, this, &LobeChartView::onMousePress);
  connect(plot_, &QCustomPlot::mouseMove, this, &LobeChartView::onMouseMove);
  connect(plot_, &QCustomPlot::mouseRelease, this, &LobeChartView::onMouseRelease);
  connect(panel_, &LobeToolPanel::toolVisibilityToggled, this, [this](int index, bool visible) {
    if (index < 0 || index >= series_.size()) return;
    setToolVisible(series_[index].tool_id, visible);
    emit toolVisibilityChanged(series_[index].tool_id, visible);
  });
  connect(panel_, &LobeToolPanel::toolClicked, this, [this](int index) {
    if (index >= 0 && index < series_.size()) emit activeToolRequested(index);
  });
  connect(panel_, &LobeToolPanel::activeToolOnlyToggled, this, [this] {
    applyToolVisibility();
    plot_->replot(QCustomPlot::rpQueuedReplot);
  });
  connect(panel_, &LobeToolPanel::pocketChosen, this, [this](double speed_rpm, double depth_mm) {
    movePointTo(speed_rpm, depth_mm, false, false);
    emit pointReleased(point_rpm_, point_mm_);
  });
}

LobeChartView::~LobeChartView() {
  delete costs_;
}

void LobeChartView::setCostMap(const QVector<double>& speeds_rpm, const QVector<double>& depths_mm,
                               const QVector<double>& cost) {
  map_speeds_ = speeds_rpm, map_depths_mm_ = depths_mm, map_cost_ = cost;
  costs_->setCostMap(speeds_rpm, scaled(depths_mm), cost);
}

void LobeChartView::setGridPoints(const QVector<double>& speeds_rpm, const QVector<double>& depths_mm) {
  grid_speeds_ = speeds_rpm, grid_depths_mm_ = depths_mm;
  costs_->setGridPoints(speeds_rpm, scaled(depths_mm));
}

void LobeChartView::setCostMapVisible(bool visible) {
  costs_->setCostMapVisible(visible);
}
void LobeChartView::setGridVisible(bool visible) {
  costs_->setGridVisible(visible);
}
int LobeChartView::costCellCount() const {
  return costs_->costCellCount();
}

// The first six are the familiar Tableau ones; the other 14 were picked greedily for the largest
// smallest CIELAB distance to those before them (lightness 25-70, so that each reads on white): every
// pair differs by Delta E_76 > 29.
QColor LobeChartView::toolColor(int index) {
  static const QRgb palette[kDistinctColors] = {0x1f77b4, 0xd62728, 0x2ca02c, 0x9467bd, 0xff7f0e, 0x17becf, 0x0000e0,
                                                0xe020e0, 0x806000, 0xe02080, 0xe08080, 0x006040, 0x6000a0, 0x802040,
                                                0x0060e0, 0x80a060, 0xa0a000, 0x802000, 0x00c080, 0x206000};
  return QColor(palette[(index % kDistinctColors + kDistinctColors) % kDistinctColors]);
}

int LobeChartView::toolShape(int index) {
  static const QCPScatterStyle::ScatterShape shapes[] = {
      QCPScatterStyle::ssCircle,  QCPScatterStyle::ssSquare, QCPScatterStyle::ssTriangle,
      QCPScatterStyle::ssDiamond, QCPScatterStyle::ssCross,  QCPScatterStyle::ssTriangleInverted,
      QCPScatterStyle::ssPlus};
  constexpr int count = static_cast<int>(std::size(shapes));
  return shapes[(index % count + count) % count];
}

QWidget* LobeChartView::plotWidget() const {
  return plot_;
}

void LobeChartView::setModelLabel(const QString& text) {
  const bool shown = plot_->plotLayout()->hasElement(0, 0) && plot_->plotLayout()->element(0, 0) == title_;
  if (text.isEmpty() && shown) {
    plot_->plotLayout()->take(title_);
    plot_->plotLayout()->simplify();
  } else if (!text.isEmpty() && !shown) {
    plot_->plotLayout()->insertRow(0);
    plot_->plotLayout()->addElement(0, 0, title_);
  }
  title_->setText(text);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

QString LobeChartView::modelLabel() const {
  return title_->text();
}

void LobeChartView::clear() {
  series_.clear();
  tool_graphs_.clear();
  panel_->setTools({});
  panel_->setPockets({}, {}, scale_, unit_);
  power_mm_.clear();
  costs_->clear();
  plot_->clearGraphs();
  unstable_top_ = unstable_fill_ = admissible_fill_ = power_graph_ = nullptr;
  setModelLabel({});  // replots
}

QVector<double> LobeChartView::scaled(const QVector<double>& mm) const {
  QVector<double> out(mm);
  for (double& v : out) v *= scale_;
  return out;
}

void LobeChartView::setLengthUnit(double display_per_mm, const QString& suffix) {
  if (display_per_mm == scale_ && suffix == unit_) return;
  const double ratio = display_per_mm / scale_;
  const QCPRange y = plot_->yAxis->range();
  scale_ = display_per_mm;
  unit_ = suffix;
  plot_->yAxis->setLabel(QString("Axial depth of cut b [%1]").arg(unit_));
  const QVector<ToolLobeSeries> series = series_;
  const QVector<double> power = power_mm_;
  const QString power_label = power_graph_ ? power_graph_->name() : QString();
  const QCPRange x = plot_->xAxis->range();
  setSeries(series, delta_, alpha_);
  setPowerLimit(power, power_label);
  plot_->xAxis->setRange(x);
  plot_->yAxis->setRange(y.lower * ratio, y.upper * ratio);
  for (const auto& [group, item] : extra_markers_)
    if (auto* tracer = qobject_cast<QCPItemTracer*>(item))
      tracer->position->setCoords(tracer->position->coords().x(), tracer->position->coords().y() * ratio);
  if (marker_->visible()) setOperatingPoint(point_rpm_, point_mm_, verdict_);
}

void LobeChartView::setSeries(const QVector<ToolLobeSeries>& series, double delta_per_s, double alpha) {
  clear();
  series_ = series;
  delta_ = delta_per_s;
  alpha_ = alpha;
  // Region fills first so that the curves are drawn over them.
  unstable_top_ = plot_->addGraph();
  unstable_top_->removeFromLegend();
  unstable_top_->setPen(Qt::NoPen);
  unstable_fill_ = plot_->addGraph();
  unstable_fill_->setName(tr("unstable (nominal lobes)"));
  unstable_fill_->setPen(Qt::NoPen);
  unstable_fill_->setBrush(kUnstableFill);
  unstable_fill_->setChannelFillGraph(unstable_top_);
  admissible_fill_ = plot_->addGraph();
  admissible_fill_->setName(tr("admissible (below margined lobe and power limit)"));
  admissible_fill_->setPen(Qt::NoPen);
  admissible_fill_->setBrush(kAdmissibleFill);
  double max_depth = 0.0, highest_minimum = 0.0;
  QVector<LobeToolEntry> entries;
  bool any_measured = false;
  for (int i = 0; i < series.size(); ++i) {
    const ToolLobeSeries& s = series[i];
    const QString dynamics = s.dynamics.isEmpty() ? QString() : QString(" (%1)").arg(s.dynamics);
    QCPGraph* nominal = plot_->addGraph();
    nominal->setName(s.tool_id + dynamics);
    nominal->setPen(QPen(toolColor(i), 2.0));
    // The marker every ~1/12 of the curve: a second cue where two colours look alike.
    nominal->setScatterStyle(
        QCPScatterStyle(static_cast<QCPScatterStyle::ScatterShape>(toolShape(i)), toolColor(i), Qt::white, 7));
    nominal->setScatterSkip(std::max<int>(1, static_cast<int>(s.speed_rpm.size() / 12)));
    nominal->setData(s.speed_rpm, scaled(s.nominal_mm), true);
    QCPGraph* margined = plot_->addGraph();
    margined->setName(s.tool_id + tr(" margined"));
    margined->setPen(QPen(toolColor(i), 1.5, Qt::DashLine));
    margined->setData(s.speed_rpm, scaled(s.margined_mm), true);
    QVector<QCPGraph*> graphs{nominal, margined};
    if (!s.measured_mm.isEmpty()) {
      QCPGraph* measured = plot_->addGraph();
      measured->setName(s.tool_id + tr(" measured FRF"));
      measured->setPen(QPen(toolColor(i).darker(140), 1.5, Qt::DotLine));
      measured->setData(s.speed_rpm, scaled(s.measured_mm), true);
      graphs.push_back(measured);
      any_measured = true;
    }
    for (QCPGraph* g : graphs) g->removeFromLegend();
    tool_graphs_.push_back(graphs);
    const QString margin = s.margin_needs_modes
                               ? tr("margined: \u03b4 = 0 (\u03b4 > 0 needs fitted modes), \u03b1 = %1").arg(alpha)
                               : tr("margined: \u03b4 = %1 1/s, \u03b1 = %2").arg(delta_per_s).arg(alpha);
    entries.push_back({s.tool_id, tr("%1%2\nnominal: \u03b4 = 0, \u03b1 = 1; %3").arg(s.tool_id, dynamics, margin),
                       toolSwatch(i), !hidden_.contains(s.tool_id)});
    double lowest = std::numeric_limits<double>::infinity();
    for (double b : s.nominal_mm)
      if (std::isfinite(b)) {
        max_depth = std::max(max_depth, b);
        lowest = std::min(lowest, b);
      }
    if (std::isfinite(lowest)) highest_minimum = std::max(highest_minimum, lowest);
  }
  addLineStyleKeys(delta_per_s, alpha, any_measured);
  power_graph_ = plot_->addGraph();
  power_graph_->setPen(QPen(QColor(40, 40, 40), 1.5, Qt::DashDotLine));
  power_graph_->removeFromLegend();
  panel_->setTools(entries);
  fitLegendColumns();
  if (!series.isEmpty() && !series.front().speed_rpm.isEmpty()) {
    home_x0_ = series.front().speed_rpm.front();
    home_x1_ = series.front().speed_rpm.back();
  }
  home_y1_ = std::min(max_depth, std::max(3.0 * highest_minimum, 1e-3)) * 1.05 + 1e-6;
  if (active_ >= series.size()) active_ = series.isEmpty() ? -1 : 0;
  if (active_ < 0 && !series.isEmpty()) active_ = 0;
  panel_->setActiveTool(active_);
  applyToolVisibility();
  updatePockets();
  updateRegions();
  if (!map_cost_.isEmpty()) costs_->setCostMap(map_speeds_, scaled(map_depths_mm_), map_cost_);
  if (!grid_speeds_.isEmpty()) costs_->setGridPoints(grid_speeds_, scaled(grid_depths_mm_));
  resetView();
}

// Legend entries without data that key the line styles every tool shares.
void LobeChartView::addLineStyleKeys(double delta_per_s, double alpha, bool measured) {
  const auto key = [this](const QString& name, const QPen& pen) {
    QCPGraph* g = plot_->addGraph();
    g->setName(name);
    g->setPen(pen);
  };
  key(tr("nominal lobe of each tool (\u03b4 = 0, \u03b1 = 1)"), QPen(kStyleKey, 2.0));
  key(tr("margined lobe (\u03b4 = %1 1/s, \u03b1 = %2)").arg(delta_per_s).arg(alpha),
      QPen(kStyleKey, 1.5, Qt::DashLine));
  if (measured) key(tr("measured-FRF lobe (ZOA, \u03b4 = 0, \u03b1 = 1)"), QPen(kStyleKey, 1.5, Qt::DotLine));
}

// A tool shows when the user has not hidden it and, with "Active tool only", when it is the active one.
void LobeChartView::applyToolVisibility() {
  const bool only_active = panel_->activeToolOnly();
  for (int i = 0; i < series_.size() && i < tool_graphs_.size(); ++i) {
    const bool visible = !hidden_.contains(series_[i].tool_id) && (!only_active || i == active_);
    for (QCPGraph* g : tool_graphs_[i]) g->setVisible(visible);
  }
}

void LobeChartView::updatePockets() {
  if (active_ < 0 || active_ >= series_.size()) {
    panel_->setPockets({}, {}, scale_, unit_);
    return;
  }
  const ToolLobeSeries& s = series_[active_];
  panel_->setPockets(s.tool_id, findStabilityPockets(s.speed_rpm, s.margined_mm), scale_, unit_);
}

void LobeChartView::setActiveTool(int index) {
  active_ = (index >= 0 && index < series_.size()) ? index : -1;
  panel_->setActiveTool(active_);
  applyToolVisibility();
  updatePockets();
  updateRegions();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void LobeChartView::setToolVisible(const QString& tool_id, bool visible) {
  if (visible)
    hidden_.remove(tool_id);
  else
    hidden_.insert(tool_id);
  for (int i = 0; i < series_.size(); ++i)
    if (series_[i].tool_id == tool_id) panel_->setToolVisible(i, visible);
  applyToolVisibility();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void LobeChartView::setPowerLimit(const QVector<double>& depth_mm, const QString& label) {
  power_mm_ = depth_mm;
  if (power_graph_) {
    if (depth_mm.isEmpty()) {
      power_graph_->data()->clear();
      power_graph_->removeFromLegend();
    } else {
      power_graph_->setName(label);
      power_graph_->addToLegend();
    }
  }
  fitLegendColumns();
  updateRegions();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

// Unstable region: above the active tool's nominal envelope. Admissible: below the margined
// envelope and the power limit.
void LobeChartView::updateRegions() {
  if (!unstable_fill_) return;
  QVector<double> x, top, unstable, admissible;
  if (active_ >= 0) {
    const ToolLobeSeries& s = series_[active_];
    const double ceiling = home_y1_ * 1000.0;
    for (int j = 0; j < s.speed_rpm.size(); ++j) {
      x.push_back(s.speed_rpm[j]);
      top.push_back(ceiling);
      unstable.push_back(std::isfinite(s.nominal_mm[j]) ? s.nominal_mm[j] : ceiling);
      double allowed = std::isfinite(s.margined_mm[j]) ? s.margined_mm[j] : ceiling;
      if (j < power_mm_.size()) allowed = std::min(allowed, power_mm_[j]);
      admissible.push_back(allowed);
    }
  }
  unstable_top_->setData(x, scaled(top), true);
  unstable_fill_->setData(x, scaled(unstable), true);
  admissible_fill_->setData(x, scaled(admissible), true);
  if (power_graph_ && active_ >= 0 && power_mm_.size() == x.size()) power_graph_->setData(x, scaled(power_mm_), true);
}

void LobeChartView::resetView() {
  plot_->xAxis->setRange(home_x0_, home_x1_);
  plot_->yAxis->setRange(0.0, home_y1_ * scale_);
  plot_->replot(QCustomPlot::rpQueuedReplot);
  emit viewReset();
}

void LobeChartView::setSnapGrid(double speed_origin_rpm, double speed_step_rpm, double depth_step_mm) {
  if (std::isfinite(speed_origin_rpm)) snap_origin_rpm_ = speed_origin_rpm;
  if (speed_step_rpm > 0.0) snap_rpm_ = speed_step_rpm;
  if (depth_step_mm > 0.0) snap_mm_ = depth_step_mm;
}

void LobeChartView::setOperatingPoint(double speed_rpm, double depth_mm, PointVerdict verdict) {
  point_rpm_ = speed_rpm;
  point_mm_ = depth_mm;
  verdict_ = verdict;
  const QColor c = verdictColor(verdict);
  marker_->position->setCoords(speed_rpm, depth_mm * scale_);
  marker_->setPen(QPen(c.darker(130), 2.0));
  marker_->setBrush(c);
  marker_->setVisible(true);
  marker_label_->setText(QString("%1 rpm, %2 %3")
                             .arg(speed_rpm, 0, 'f', 0)
                             .arg(depth_mm * scale_, 0, 'f', scale_ == 1.0 ? 3 : 4)
                             .arg(unit_));
  marker_label_->setColor(c.darker(150));
  // On the side facing the middle of the view, so that the right edge never cuts it.
  const bool right_half = speed_rpm > plot_->xAxis->range().center();
  marker_label_->position->setCoords(right_half ? -10 : 10, -8);
  marker_label_->setPositionAlignment((right_half ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignBottom);
  marker_label_->setVisible(true);
  replotOverlay();
}

void LobeChartView::setMarker(const QString& name, double speed_rpm, double depth_mm, const QColor& color,
                              const QString& group) {
  auto* tracer = new QCPItemTracer(plot_);
  tracer->setLayer("overlay");
  tracer->setStyle(QCPItemTracer::tsSquare);
  tracer->setSize(10);
  tracer->setPen(QPen(color, 2.0));
  tracer->position->setCoords(speed_rpm, depth_mm * scale_);
  auto* text = new QCPItemText(plot_);
  text->setLayer("overlay");
  text->position->setParentAnchor(tracer->position);
  // The label on the side of the marker facing the middle of the view, so that no axis cuts it.
  const bool right_half = speed_rpm > plot_->xAxis->range().center();
  text->setPositionAlignment((right_half ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
  text->setText(name);
  placeBelowOtherLabels(text, right_half ? -8 : 8);
  text->setColor(color);
  extra_markers_.push_back({group, tracer});
  extra_markers_.push_back({group, text});
  replotQueued();
}

namespace {
QRectF labelRect(QCPItemText* text) {
  return QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition());
}
}  // namespace

// A new marker label hangs below its marker, one text row lower for each label of another marker it
// would overprint ("q* (R1)" and "q**" at neighbouring points).
void LobeChartView::placeBelowOtherLabels(QCPItemText* text, double dx) {
  const double row = QFontMetrics(text->font()).height();
  const auto overprints = [this, text] {
    const QRectF mine = labelRect(text);
    return std::any_of(extra_markers_.begin(), extra_markers_.end(), [&](const auto& marker) {
      auto* other = qobject_cast<QCPItemText*>(marker.second);
      return other && other != text && labelRect(other).intersects(mine);
    });
  };
  constexpr int kMaxRows = 6;
  for (int rows = 0; rows <= kMaxRows; ++rows) {
    text->position->setCoords(dx, 8 + rows * row);
    if (!overprints()) return;
  }
  text->position->setCoords(dx, 8);
}

void LobeChartView::clearMarkers() {
  // Labels before the tracers they are anchored to: the reverse of the order they were added.
  std::for_each(extra_markers_.rbegin(), extra_markers_.rend(), [this](const auto& m) { plot_->removeItem(m.second); });
  extra_markers_.clear();
  replotQueued();
}

QStringList LobeChartView::markerNames() const {
  QStringList names;
  for (const auto& [group, item] : extra_markers_)
    if (auto* text = qobject_cast<QCPItemText*>(item)) names << text->text();
  return names;
}

void LobeChartView::clearMarkers(const QString& group) {
  std::for_each(extra_markers_.rbegin(), extra_markers_.rend(), [&](const auto& m) {
    if (m.first == group) plot_->removeItem(m.second);
  });
  extra_markers_.removeIf([&group](const auto& marker) { return marker.first == group; });
  replotQueued();
}

void LobeChartView::replotOverlay() {
  // Markers live on the buffered overlay layer: only that layer repaints while dragging.
  if (QCPLayer* overlay = plot_->layer("overlay")) overlay->replot();
  plot_->update();
}

// An item added to or removed from a layer invalidates its buffer, and the layer's own replot then
// replots the whole chart at once: the markers of one change (q* and q** after a weight step) share one
// replot when the event loop turns.
void LobeChartView::replotQueued() {
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

QPoint LobeChartView::pixelFor(double speed_rpm, double depth_mm) const {
  return QPoint(qRound(plot_->xAxis->coordToPixel(speed_rpm)), qRound(plot_->yAxis->coordToPixel(depth_mm * scale_)));
}

void LobeChartView::movePointTo(double speed_rpm, double depth_mm, bool snap_speed, bool snap_depth) {
  if (snap_speed) speed_rpm = snap_origin_rpm_ + std::round((speed_rpm - snap_origin_rpm_) / snap_rpm_) * snap_rpm_;
  if (snap_depth) depth_mm = std::round(depth_mm / snap_mm_) * snap_mm_;
  speed_rpm = std::max(speed_rpm, 1.0);
  depth_mm = std::max(depth_mm, 0.0);
  point_rpm_ = speed_rpm;
  point_mm_ = depth_mm;
}

void LobeChartView::onMousePress(QMouseEvent* event) {
  setFocus(Qt::MouseFocusReason);
  const QPointF p = event->position();
  if (event->button() == Qt::RightButton) {
    panning_ = true;
    pan_start_ = p.toPoint();
    pan_x0_ = plot_->xAxis->range().lower, pan_x1_ = plot_->xAxis->range().upper;
    pan_y0_ = plot_->yAxis->range().lower, pan_y1_ = plot_->yAxis->range().upper;
    return;
  }
  if (event->button() != Qt::LeftButton || !plot_->axisRect()->rect().contains(p.toPoint())) return;
  dragging_ = true;
  const bool snap = event->modifiers() & Qt::ShiftModifier;
  movePointTo(plot_->xAxis->pixelToCoord(p.x()), plot_->yAxis->pixelToCoord(p.y()) / scale_, snap, snap);
  emit pointDragged(point_rpm_, point_mm_);
}

void LobeChartView::onMouseMove(QMouseEvent* event) {
  const QPointF p = event->position();
  if (panning_) {
    const double dx = plot_->xAxis->pixelToCoord(pan_start_.x()) - plot_->xAxis->pixelToCoord(p.x());
    const double dy = plot_->yAxis->pixelToCoord(pan_start_.y()) - plot_->yAxis->pixelToCoord(p.y());
    plot_->xAxis->setRange(pan_x0_ + dx, pan_x1_ + dx);
    plot_->yAxis->setRange(pan_y0_ + dy, pan_y1_ + dy);
    pan_start_ = p.toPoint();
    pan_x0_ += dx, pan_x1_ += dx, pan_y0_ += dy, pan_y1_ += dy;
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return;
  }
  showCursorLimit(p);
  if (!dragging_) return;
  const bool snap = event->modifiers() & Qt::ShiftModifier;
  movePointTo(plot_->xAxis->pixelToCoord(p.x()), plot_->yAxis->pixelToCoord(p.y()) / scale_, snap, snap);
  emit pointDragged(point_rpm_, point_mm_);
}

void LobeChartView::onMouseRelease(QMouseEvent* event) {
  if (event->button() == Qt::RightButton) {
    panning_ = false;
    return;
  }
  if (!dragging_ || event->button() != Qt::LeftButton) return;
  dragging_ = false;
  emit pointReleased(point_rpm_, point_mm_);
}

namespace {
// The next line origin + k step beyond x in the direction of `sign` (+1 or -1).
double nextGridLine(double x, double origin, double step, int sign) {
  constexpr double kOnLine = 1e-9;  // a point on a line moves to the next one
  const double k = (x - origin) / step;
  return origin + step * (sign > 0 ? std::floor(k + kOnLine) + 1.0 : std::ceil(k - kOnLine) - 1.0);
}
}  // namespace

// Arrows move the point by 1/200 of the view; with Shift, to the next grid line of that axis.
void LobeChartView::keyPressEvent(QKeyEvent* event) {
  const bool snap = event->modifiers() & Qt::ShiftModifier;
  const double step_rpm = plot_->xAxis->range().size() / 200.0;
  const double step_mm = plot_->yAxis->range().size() / scale_ / 200.0;
  double n = point_rpm_, b = point_mm_;
  switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right: {
      const int sign = event->key() == Qt::Key_Right ? 1 : -1;
      n = snap ? nextGridLine(n, snap_origin_rpm_, snap_rpm_, sign) : n + sign * step_rpm;
      break;
    }
    case Qt::Key_Up:
    case Qt::Key_Down: {
      const int sign = event->key() == Qt::Key_Up ? 1 : -1;
      b = snap ? nextGridLine(b, 0.0, snap_mm_, sign) : b + sign * step_mm;
      break;
    }
    case Qt::Key_Home:
      resetView();
      return;
    default:
      QWidget::keyPressEvent(event);
      return;
  }
  movePointTo(n, b, false, false);
  emit pointReleased(point_rpm_, point_mm_);
}

bool LobeChartView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == plot_ && event->type() == QEvent::Leave) panel_->setCursorText({});
  return QWidget::eventFilter(watched, event);
}

// "N = 3400 rpm, b = 0.500 mm" and the active tool's nominal and margined limits at that speed.
void LobeChartView::showCursorLimit(const QPointF& pixel) {
  if (!plot_->axisRect()->rect().contains(pixel.toPoint())) {
    panel_->setCursorText({});
    return;
  }
  const double speed = plot_->xAxis->pixelToCoord(pixel.x());
  const double depth = plot_->yAxis->pixelToCoord(pixel.y());
  const int decimals = scale_ == 1.0 ? 3 : 4;
  QString text = tr("Cursor: N = %1 rpm, b = %2 %3").arg(speed, 0, 'f', 0).arg(depth, 0, 'f', decimals).arg(unit_);
  if (active_ >= 0 && active_ < series_.size()) {
    const ToolLobeSeries& s = series_[active_];
    const double nominal = envelopeAt(s.speed_rpm, s.nominal_mm, speed) * scale_;
    const double margined = envelopeAt(s.speed_rpm, s.margined_mm, speed) * scale_;
    const auto depth_text = [&](double b) {
      return std::isfinite(b) ? QString("%1 %2").arg(b, 0, 'f', decimals).arg(unit_) : tr("above the chart");
    };
    if (speed < s.speed_rpm.value(0) || speed > s.speed_rpm.value(s.speed_rpm.size() - 1))
      text += tr("\n%1: outside the computed speeds").arg(s.tool_id);
    else
      text += tr("\nb_lim of %1: %2 nominal, %3 margined").arg(s.tool_id, depth_text(nominal), depth_text(margined));
  }
  panel_->setCursorText(text);
}

// As many legend columns (at most two) as the entries fit in the plot's width at their full size.
void LobeChartView::fitLegendColumns() {
  if (widgets::fitLegendColumns(plot_->legend, plot_->width(), kLegendColumns))
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void LobeChartView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  fitLegendColumns();
}

QStringList LobeChartView::legendNames() const {
  QStringList names;
  for (int i = 0; i < plot_->legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i))) names << item->plottable()->name();
  return names;
}

// An exported image has no tool list beside it: its legend names every shown tool by its nominal line.
void LobeChartView::setToolsInLegend(bool shown) {
  for (const auto& graphs : tool_graphs_) {
    QCPGraph* nominal = graphs.front();
    if (shown && nominal->visible())
      nominal->addToLegend();
    else
      nominal->removeFromLegend();
  }
  plot_->legend->setWrap(shown ? kExportLegendColumns : kLegendColumns);
  plot_->legend->setFillOrder(QCPLegend::foColumnsFirst, true);  // re-flows the entries into the columns
  if (!shown) fitLegendColumns();
}

int LobeChartView::exportHeight(int width, int height) {
  setToolsInLegend(true);
  plot_->legend->setMaximumSize(width, QWIDGETSIZE_MAX);
  const int legend = plot_->legend->minimumOuterSizeHint().height();
  setToolsInLegend(false);
  plot_->legend->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
  return std::max(height, kMinExportPlotHeight + legend);
}

bool LobeChartView::saveImage(const QString& path, int width, int height) {
  height = exportHeight(width, height);
  setToolsInLegend(true);
  const bool saved = writeImage(path, width, height);
  setToolsInLegend(false);
  plot_->replot(QCustomPlot::rpQueuedReplot);
  return saved;
}

bool LobeChartView::writeImage(const QString& path, int width, int height) {
  plot_->replot();
  if (path.endsWith(".pdf", Qt::CaseInsensitive)) return plot_->savePdf(path, width, height);
  if (path.endsWith(".svg", Qt::CaseInsensitive)) {
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(QSize(width, height));
    svg.setViewBox(QRect(0, 0, width, height));
    svg.setTitle("MillExpert stability lobes");
    QCPPainter painter(&svg);
    plot_->toPainter(&painter, width, height);
    return painter.end();
  }
  return plot_->savePng(path, width, height);
}

}  // namespace mx::widgets
