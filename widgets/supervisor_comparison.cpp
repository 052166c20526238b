#include "supervisor_comparison.h"

#include <qcustomplot.h>

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace mx::widgets {

namespace {
const QColor kForce(31, 119, 180), kPower(255, 127, 14), kLimit(214, 39, 40), kBad(190, 20, 20);

// "0.39", "0.39 (1 never)" when some restarts never settled, "never", or a dash without a restart.
QString settlingText(const SupervisionMetricsView& m) {
  if (!m.longest_settling_s && m.unsettled == 0) return QStringLiteral("\u2013");
  if (!m.longest_settling_s) return SupervisorComparison::tr("never");
  const QString t = QString::number(*m.longest_settling_s, 'f', 2);
  return m.unsettled == 0 ? t : SupervisorComparison::tr("%1 (%2 never)").arg(t).arg(m.unsettled);
}
}  // namespace

SupervisorComparison::SupervisorComparison(QWidget* parent)
    : QWidget(parent), plots_layout_(new QHBoxLayout), table_(new QTableWidget(this)) {
  setObjectName(QStringLiteral("supervisorComparison"));
  table_->setRowCount(static_cast<int>(metricKeys().size()));
  table_->setVerticalHeaderLabels({tr("Max. spindle power [% of limit]"), tr("Force overshoot over F_ref [%]"),
                                   tr("Force settling after contact [s]"), tr("Chatter detected"),
                                   tr("Chatter detected at t [s]"), tr("Passes executed"), tr("Cycle time [s]")});
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  const int row_h = fontMetrics().height() + 10;
  table_->verticalHeader()->setMinimumSectionSize(row_h);
  table_->setFixedHeight((table_->rowCount() + 1) * row_h + 8);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(plots_layout_, 1);
  layout->addWidget(table_, 0);
  for (const char* c : {"none", "smc1", "smc2"}) columnOf(QLatin1String(c));
}

QStringList SupervisorComparison::metricKeys() {
  return {QStringLiteral("max_power_pct_of_limit"),
          QStringLiteral("overshoot_pct"),
          QStringLiteral("settling_s"),
          QStringLiteral("chatter_detected"),
          QStringLiteral("chatter_time_s"),
          QStringLiteral("passes"),
          QStringLiteral("cycle_time_s")};
}

QString SupervisorComparison::controllerCaption(const QString& controller) {
  if (controller == QLatin1String("none")) return tr("No control (baseline)");
  if (controller == QLatin1String("smc1")) return tr("SMC I (transfer line)");
  if (controller == QLatin1String("smc2")) return tr("SMC II (job shop)");
  return controller;
}

int SupervisorComparison::columnOf(const QString& controller) {
  const int existing = static_cast<int>(columns_.indexOf(controller));
  if (existing >= 0) return existing;
  columns_ << controller;
  const int column = static_cast<int>(columns_.size()) - 1;
  table_->setColumnCount(column + 1);
  table_->setHorizontalHeaderItem(column, new QTableWidgetItem(controllerCaption(controller)));
  QCustomPlot* plot = makePlot(controller);
  plots_ << plot;
  plots_layout_->addWidget(plot, 1);
  showResult(column);
  return column;
}

QCustomPlot* SupervisorComparison::makePlot(const QString& controller) {
  auto* plot = new QCustomPlot(this);
  plot->setMinimumSize(300, 260);
  const QFont small(font().family(), 8);
  plot->plotLayout()->insertRow(0);
  plot->plotLayout()->addElement(
      0, 0, new QCPTextElement(plot, controllerCaption(controller), QFont(font().family(), 10, QFont::Bold)));
  QCPAxisRect* rect = plot->axisRect();
  rect->axis(QCPAxis::atBottom)->setLabel(tr("Time t [s]"));
  rect->axis(QCPAxis::atLeft)->setLabelColor(kForce);
  rect->axis(QCPAxis::atRight)->setVisible(true);
  rect->axis(QCPAxis::atRight)->setLabelColor(kPower.darker(130));
  for (QCPAxis* a : rect->axes()) {
    a->setLabelFont(small);
    a->setTickLabelFont(small);
  }
  QCPGraph* force = plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  force->setPen(QPen(kForce, 1.3));
  QCPGraph* power = plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atRight));
  power->setPen(QPen(kPower, 1.3));
  QCPGraph* limit = plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atRight));
  limit->setPen(QPen(kLimit, 1.5, Qt::DashLine));
  // The legend in a row of its own between the title and the axes, so it never hides a trace.
  plot->legend->setVisible(true);
  plot->legend->setFont(small);
  plot->legend->setBorderPen(Qt::NoPen);
  plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  plot->legend->setWrap(3);
  plot->legend->setColumnSpacing(10);
  rect->insetLayout()->take(plot->legend);
  plot->plotLayout()->insertRow(1);
  plot->plotLayout()->addElement(1, 0, plot->legend);
  plot->plotLayout()->setRowStretchFactor(0, 0.001);
  plot->plotLayout()->setRowStretchFactor(1, 0.001);
  plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  rect->setRangeDrag(Qt::Horizontal);
  rect->setRangeZoom(Qt::Horizontal);
  return plot;
}

void SupervisorComparison::setUnits(DisplayUnits* units) {
  const auto apply = [this] {
    for (int column = 0; column < columns_.size(); ++column) showResult(column);
  };
  followUnits(this, units_, units, apply);
}

void SupervisorComparison::setResult(const QString& controller, const SupervisionSeries& series,
                                     const SupervisionMetricsView& metrics) {
  results_.insert(controller, Result{series, metrics});
  showResult(columnOf(controller));
}

void SupervisorComparison::showResult(int column) {
  const QString controller = columns_[column];
  QCustomPlot* plot = plots_[column];
  const auto it = results_.constFind(controller);
  const bool has = it != results_.constEnd();
  const SupervisionSeries s = has ? it->series : SupervisionSeries{};
  // Force and power in the shop units (the series: N and W).
  const ShopUnits& u = DisplayUnits::of(units_);
  const double fu = u.fromBase(Quantity::Force, 1.0), pu = u.fromBase(Quantity::Power, 1.0);
  const QString force = u.symbol(Quantity::Force), power = u.symbol(Quantity::Power);
  plot->axisRect()->axis(QCPAxis::atLeft)->setLabel(tr("F_Y [%1]").arg(force));
  plot->axisRect()->axis(QCPAxis::atRight)->setLabel(tr("Power P [%1]").arg(power));
  plot->graph(0)->setName(tr("F_Y [%1]").arg(force));
  plot->graph(1)->setName(tr("Power P [%1]").arg(power));
  plot->graph(2)->setName(tr("Power limit [%1]").arg(power));
  const qsizetype n = std::min({s.t_s.size(), s.force_y_n.size(), s.power_w.size()});
  QVector<double> t(s.t_s.begin(), s.t_s.begin() + n), f(s.force_y_n.begin(), s.force_y_n.begin() + n),
      p(s.power_w.begin(), s.power_w.begin() + n);
  for (double& v : f) v *= fu;
  for (double& v : p) v *= pu;
  plot->graph(0)->setData(t, f, true);
  plot->graph(1)->setData(t, p, true);
  const double t0 = n ? t.front() : 0.0, t1 = n && t.back() > t0 ? t.back() : t0 + 1.0;
  if (s.power_limit_w > 0)
    plot->graph(2)->setData({t0, t1}, {pu * s.power_limit_w, pu * s.power_limit_w}, true);
  else
    plot->graph(2)->data()->clear();
  double f_hi = fu * s.force_reference_n, p_hi = pu * s.power_limit_w;
  for (qsizetype i = 0; i < n; ++i) {
    if (std::isfinite(f[i])) f_hi = std::max(f_hi, f[i]);
    if (std::isfinite(p[i])) p_hi = std::max(p_hi, p[i]);
  }
  QCPAxisRect* rect = plot->axisRect();
  rect->axis(QCPAxis::atBottom)->setRange(t0, t1);
  rect->axis(QCPAxis::atLeft)->setRange(0, f_hi > 0 ? 1.15 * f_hi : 1.0);
  rect->axis(QCPAxis::atRight)->setRange(0, p_hi > 0 ? 1.15 * p_hi : 1.0);
  plot->replot(QCustomPlot::rpQueuedReplot);

  const QStringList keys = metricKeys();
  for (int row = 0; row < keys.size(); ++row) {
    auto* item = new QTableWidgetItem(has ? metricText(controller, keys[row]) : QStringLiteral("\u2013"));
    item->setTextAlignment(Qt::AlignCenter);
    const SupervisionMetricsView& m = has ? it->metrics : SupervisionMetricsView{};
    const bool bad =
        has && ((keys[row] == QLatin1String("max_power_pct_of_limit") && m.max_power_pct_of_limit > 100.0) ||
                (keys[row] == QLatin1String("chatter_detected") && m.chatter_detected) ||
                (keys[row] == QLatin1String("settling_s") && m.unsettled > 0));
    if (bad) {
      item->setForeground(kBad);
      QFont bold = item->font();
      bold.setBold(true);
      item->setFont(bold);
    }
    table_->setItem(row, column, item);
  }
}

QString SupervisorComparison::metricText(const QString& controller, const QString& key) const {
  const auto it = results_.constFind(controller);
  if (it == results_.constEnd()) return {};
  const SupervisionMetricsView& m = it->metrics;
  if (key == QLatin1String("max_power_pct_of_limit")) return QString::number(m.max_power_pct_of_limit, 'f', 0);
  if (key == QLatin1String("overshoot_pct")) return QString::number(m.overshoot_pct, 'f', 0);
  if (key == QLatin1String("settling_s")) return settlingText(m);
  if (key == QLatin1String("chatter_detected")) return m.chatter_detected ? tr("yes") : tr("no");
  if (key == QLatin1String("chatter_time_s"))
    return m.chatter_time_s ? QString::number(*m.chatter_time_s, 'f', 2) : QStringLiteral("\u2013");
  if (key == QLatin1String("passes")) return QString::number(m.passes);
  if (key == QLatin1String("cycle_time_s")) return QString::number(m.cycle_time_s, 'f', 2);
  return {};
}

void SupervisorComparison::clear() {
  results_.clear();
  for (int c = 0; c < columns_.size(); ++c) showResult(c);
}

int SupervisorComparison::resultCount() const {
  return static_cast<int>(results_.size());
}

int SupervisorComparison::plotPointCount(const QString& controller) const {
  const int c = static_cast<int>(columns_.indexOf(controller));
  return c >= 0 && results_.contains(controller) ? plots_[c]->graph(0)->dataCount() : -1;
}

bool SupervisorComparison::saveImage(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  // A copy rendered off screen, so the docked view keeps its own size.
  SupervisorComparison copy;
  copy.setAttribute(Qt::WA_DontShowOnScreen);
  for (const QString& c : std::as_const(columns_)) {
    copy.columnOf(c);
    if (results_.contains(c)) copy.setResult(c, results_[c].series, results_[c].metrics);
  }
  copy.resize(width, height);
  copy.show();
  copy.layout()->activate();
  for (QCustomPlot* plot : std::as_const(copy.plots_)) plot->replot(QCustomPlot::rpImmediateRefresh);
  const bool ok = copy.grab().save(path, "PNG");
  copy.hide();
  return ok;
}

}  // namespace mx::widgets
