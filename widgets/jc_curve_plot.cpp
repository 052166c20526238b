#include "jc_curve_plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "glossary.h"
#include "plot_legend.h"

namespace mx::widgets {

namespace {
const QColor kCurveColor(31, 119, 180);
const QColor kBestColor(44, 160, 44);
const QColor kCurrentColor(214, 39, 40);
const QColor kRegionColor(214, 39, 40, 40);
constexpr double kBetaMin = -1.0, kBetaMax = 1.0;
constexpr int kLegendColumns = 2;  // at most; one when the entries do not fit side by side
constexpr double kHeadroom = 1.3;  // J_c axis up to 1.3 max J_c: the region's label above the curve

QString betaText(double beta) {
  return QString::number(beta, 'f', 2).replace(QLatin1Char('-'), QChar(0x2212));
}
}  // namespace

JcCurvePlot::JcCurvePlot(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(plot_);
  // As wide as the longest legend entry: the current beta in the unstable-zero region with a J_c of 1.235e+04.
  setMinimumSize(390, 250);
  plot_->setToolTip(
      tr("Cost J_c(\u03b2) (eq. 34): the area between the continuous plant output and the linear interpolation of "
         "its samples; smaller means fewer overshoots between samples. Shaded: \u03b2 where H_\u03b2 has an "
         "unstable zero."));
  setWhatsThis(glossaryText(Term::Jc));  // the plot has none: What's This reaches this widget
  plot_->xAxis->setLabel(tr("FROH gain \u03b2 [\u2013]"));
  plot_->yAxis->setLabel(tr("Cost J_c [N\u00b7s]"));
  plot_->xAxis->setRange(kBetaMin - 0.05, kBetaMax + 0.05);
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 9));
  placeLegendUnderPlot(plot_, kLegendColumns);  // never over the curve, the markers or the region
  plot_->legend->setMargins(QMargins(6, 1, 6, 1));
  plot_->legend->setRowSpacing(0);
  plot_->legend->setColumnSpacing(16);
  connect(plot_, &QCustomPlot::beforeReplot, this,
          [this] { fitLegendColumns(plot_->legend, plot_->viewport().width(), kLegendColumns); });
  plot_->addLayer(QStringLiteral("shading"), plot_->layer(QStringLiteral("grid")), QCustomPlot::limBelow);

  region_ = new QCPItemRect(plot_);
  region_->setLayer(QStringLiteral("shading"));
  region_->setPen(Qt::NoPen);
  region_->setBrush(kRegionColor);
  for (QCPItemPosition* p : {region_->topLeft, region_->bottomRight}) {
    p->setTypeX(QCPItemPosition::ptPlotCoords);
    p->setTypeY(QCPItemPosition::ptAxisRectRatio);
  }
  region_label_ = new QCPItemText(plot_);
  region_label_->setLayer(QStringLiteral("shading"));
  region_label_->position->setTypeX(QCPItemPosition::ptPlotCoords);
  region_label_->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
  region_label_->setPositionAlignment(Qt::AlignHCenter | Qt::AlignTop);
  region_label_->setColor(QColor(160, 30, 30));
  region_label_->setFont(QFont(font().family(), 8));
  region_label_->setText(tr("unstable\nzero"));
  region_label_->setClipToAxisRect(true);

  region_legend_ = plot_->addGraph();
  region_legend_->setPen(Qt::NoPen);
  region_legend_->setBrush(kRegionColor);
  curve_ = plot_->addGraph();
  curve_->setName(tr("J_c(\u03b2) [N\u00b7s]"));
  curve_->setPen(QPen(kCurveColor, 2.0));
  curve_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 5));
  best_ = plot_->addGraph();
  best_->setLineStyle(QCPGraph::lsNone);
  best_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssStar, QPen(kBestColor, 2.5), Qt::NoBrush, 16));
  current_legend_ = plot_->addGraph();
  current_legend_->setPen(QPen(kCurrentColor, 1.5, Qt::DashLine));
  current_legend_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kCurrentColor, 2.0), Qt::white, 9));

  current_line_ = new QCPItemStraightLine(plot_);
  current_line_->setLayer(QStringLiteral("overlay"));
  current_line_->setPen(QPen(kCurrentColor, 1.5, Qt::DashLine));
  current_point_ = new QCPItemTracer(plot_);
  current_point_->setLayer(QStringLiteral("overlay"));
  current_point_->setInterpolating(true);
  current_point_->setStyle(QCPItemTracer::tsCircle);
  current_point_->setPen(QPen(kCurrentColor, 2.0));
  current_point_->setBrush(Qt::white);
  current_point_->setSize(9);
  clear();
}

void JcCurvePlot::clear() {
  setCurve(JcCurveView{});
}

void JcCurvePlot::setCurve(const JcCurveView& c) {
  QVector<double> beta, jc;
  double top = 0.0;
  const qsizetype n = std::min(c.beta.size(), c.jc_n_s.size());
  for (qsizetype i = 0; i < n; ++i) {
    if (!std::isfinite(c.beta[i]) || !std::isfinite(c.jc_n_s[i])) continue;
    beta.push_back(c.beta[i]);
    jc.push_back(c.jc_n_s[i]);
    top = std::max(top, c.jc_n_s[i]);
  }
  curve_->setData(beta, jc);  // sorts by beta
  plot_->yAxis->setRange(0.0, top > 0.0 ? kHeadroom * top : 1.0);

  threshold_ = std::isfinite(c.threshold_beta) ? std::clamp(c.threshold_beta, kBetaMin, kBetaMax) : kBetaMin;
  const bool shaded = regionShaded();
  region_->setVisible(shaded);
  region_label_->setVisible(shaded);
  region_->topLeft->setCoords(plot_->xAxis->range().lower, 0.0);
  region_->bottomRight->setCoords(threshold_, 1.0);
  region_label_->position->setCoords(0.5 * (plot_->xAxis->range().lower + threshold_), 0.02);
  region_legend_->setName(tr("Unstable zero of H_\u03b2: \u03b2 < %1").arg(betaText(threshold_)));

  best_->data()->clear();
  if (c.best_beta && std::isfinite(*c.best_beta) && curve_->dataCount() > 0) {
    const double b = *c.best_beta;
    // J_c at the best beta: the sweep point there (else the nearest one).
    auto nearest = std::min_element(
        curve_->data()->constBegin(), curve_->data()->constEnd(),
        [b](const QCPGraphData& l, const QCPGraphData& r) { return std::abs(l.key - b) < std::abs(r.key - b); });
    best_->addData(b, nearest->value);
    best_->setName(tr("Minimum: \u03b2 = %1, J_c = %2 N\u00b7s").arg(betaText(b)).arg(nearest->value, 0, 'g', 4));
  }
  // Legend order: curve, region, minimum, current beta.
  for (QCPGraph* g : {region_legend_, best_, current_legend_}) g->removeFromLegend();
  if (shaded) region_legend_->addToLegend();
  if (best_->dataCount() > 0) best_->addToLegend();
  current_legend_->addToLegend();
  updateMarker();
}

void JcCurvePlot::setCurrentBeta(double beta) {
  const double clamped = std::isfinite(beta) ? std::clamp(beta, kBetaMin, kBetaMax) : 0.0;
  if (clamped != current_beta_) computed_jc_.reset();  // the run at the new beta is still to come
  current_beta_ = clamped;
  updateMarker();
}

void JcCurvePlot::setComputedJc(std::optional<double> jc_n_s) {
  computed_jc_ = jc_n_s && std::isfinite(*jc_n_s) ? jc_n_s : std::nullopt;
  updateMarker();
}

// The marker and its legend show the J_c the closed loop computed at the current beta (the number the
// metrics panel and `millexpert-cli control` give), never a value read off the sweep's interpolation.
void JcCurvePlot::updateMarker() {
  current_line_->point1->setCoords(current_beta_, 0.0);
  current_line_->point2->setCoords(current_beta_, 1.0);
  const std::optional<double> jc = computed_jc_;
  current_point_->position->setCoords(current_beta_, jc.value_or(0.0));
  current_point_->setVisible(jc.has_value());
  QString name = tr("Current \u03b2 = %1").arg(betaText(current_beta_));
  name += jc ? tr(", J_c = %1 N\u00b7s").arg(*jc, 0, 'g', 4) : tr(", J_c: computing");
  if (current_beta_ < threshold_) name += tr(" (unstable zero)");
  current_legend_->setName(name);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

int JcCurvePlot::pointCount() const {
  return curve_->dataCount();
}

std::optional<double> JcCurvePlot::bestBeta() const {
  if (best_->dataCount() == 0) return std::nullopt;
  return best_->data()->constBegin()->key;
}

bool JcCurvePlot::regionShaded() const {
  return threshold_ > kBetaMin;
}

QPair<double, double> JcCurvePlot::shadedRange() const {
  return regionShaded() ? QPair<double, double>(kBetaMin, threshold_) : QPair<double, double>(0.0, 0.0);
}

QStringList JcCurvePlot::legendNames() const {
  QStringList names;
  for (int i = 0; i < plot_->legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i))) names << item->plottable()->name();
  return names;
}

QString JcCurvePlot::xAxisLabel() const {
  return plot_->xAxis->label();
}

QString JcCurvePlot::yAxisLabel() const {
  return plot_->yAxis->label();
}

bool JcCurvePlot::savePng(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  fitLegendColumns(plot_->legend, width, kLegendColumns);  // the image's width, not the screen's
  const bool saved = plot_->savePng(path, width, height);
  plot_->replot(QCustomPlot::rpQueuedReplot);
  return saved;
}

}  // namespace mx::widgets
