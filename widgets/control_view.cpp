#include "control_view.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>

#include "control_beta_slider.h"
#include "control_metrics_panel.h"
#include "control_plots.h"
#include "control_settings_editor.h"
#include "depth_profile_editor.h"
#include "jc_curve_plot.h"
#include "pole_zero_plot.h"

namespace mx::widgets {

namespace {
constexpr int kSpacing = 8;
constexpr double kSideBySideAspect = 1.5;  // the right column's width / height above which its charts go side by side

QString betaText(double beta) {
  return QString::number(beta, 'f', 2).replace(QLatin1Char('-'), QChar(0x2212));
}

// `content` at the scroll area's width, scrolling vertically when the dock is shorter than its minimum.
QScrollArea* verticalScroll(QWidget* content, const QString& name, QWidget* parent) {
  auto* scroll = new QScrollArea(parent);
  scroll->setObjectName(name);
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  const int width = std::max(content->minimumSizeHint().width(), content->minimumWidth());
  scroll->setMinimumWidth(width + scroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent));
  return scroll;
}

QGroupBox* group(const QString& title, QWidget* content, QWidget* parent) {
  auto* box = new QGroupBox(title, parent);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(kSpacing, kSpacing, kSpacing, kSpacing);
  layout->setSpacing(kSpacing);
  layout->addWidget(content);
  return box;
}
}  // namespace

ControlView::ControlView(QWidget* parent)
    : QWidget(parent),
      beta_(new ControlBetaSlider(this)),
      sweep_(new QPushButton(tr("Sweep \u03b2"), this)),
      busy_bar_(new QProgressBar(this)),
      status_(new QLabel(this)),
      metrics_(new ControlMetricsPanel(this)),
      settings_(new ControlSettingsEditor(this)),
      depth_(new DepthProfileEditor(this)),
      plots_(new ControlPlots(ControlPlots::Rows::All, this)),
      jc_(new JcCurvePlot(this)),
      pole_zero_(new PoleZeroPlot(this)),
      charts_(new QSplitter(Qt::Vertical, this)) {
  sweep_->setObjectName(QStringLiteral("controlSweepButton"));
  sweep_->setToolTip(tr("Run the closed loop over \u03b2 in [\u22121, 1] and plot J_c(\u03b2) (figure 13)"));
  busy_bar_->setRange(0, 0);  // indeterminate
  busy_bar_->setMaximumHeight(8);
  busy_bar_->setTextVisible(false);
  busy_bar_->setVisible(false);
  status_->setObjectName(QStringLiteral("controlStatus"));
  status_->setWordWrap(true);

  charts_->addWidget(jc_);
  charts_->addWidget(pole_zero_);
  charts_->setStretchFactor(0, 3);
  charts_->setStretchFactor(1, 2);
  charts_->setChildrenCollapsible(false);
  // In a short dock the centre and right columns scroll: the plots keep a readable height.
  plots_scroll_ = verticalScroll(plots_, QStringLiteral("controlPlotsScroll"), this);
  charts_scroll_ = verticalScroll(charts_, QStringLiteral("controlChartsScroll"), this);
  charts_scroll_->installEventFilter(this);

  auto* columns = new QSplitter(Qt::Horizontal, this);
  columns->addWidget(buildLeftColumn());
  columns->addWidget(plots_scroll_);
  columns->addWidget(charts_scroll_);
  columns->setStretchFactor(0, 0);
  columns->setStretchFactor(1, 1);
  columns->setStretchFactor(2, 1);
  columns->setChildrenCollapsible(false);
  columns->setSizes({360, 800, 720});
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(kSpacing, kSpacing, kSpacing, kSpacing);
  layout->addWidget(columns);

  connect(beta_, &ControlBetaSlider::betaChanged, this, &ControlView::betaChanged);
  connect(beta_->slider(), &QSlider::valueChanged, this, [this] { showBeta(beta_->beta()); });
  connect(sweep_, &QPushButton::clicked, this, &ControlView::sweepRequested);
  connect(settings_, &ControlSettingsEditor::settingsEdited, this, [this](const ControllerSettingsView& s) {
    plots_->setFeedLimit(s.feed_max_mm_s);
    emit settingsEdited(s);
  });
  connect(depth_, &DepthProfileEditor::stepsEdited, this, &ControlView::workpieceEdited);
  plots_->setFeedLimit(settings_->settings().feed_max_mm_s);
  setStatus(tr("No closed-loop run yet."));
  showBeta(beta_->beta());
}

QWidget* ControlView::buildLeftColumn() {
  auto* beta_panel = new QWidget(this);
  auto* beta_layout = new QVBoxLayout(beta_panel);
  beta_layout->setContentsMargins(0, 0, 0, 0);
  beta_layout->setSpacing(kSpacing);
  beta_layout->addWidget(beta_);
  auto* sweep_row = new QHBoxLayout;
  sweep_row->addWidget(sweep_);
  sweep_row->addWidget(busy_bar_, 1);
  beta_layout->addLayout(sweep_row);
  beta_layout->addWidget(status_);

  auto* content = new QWidget(this);
  auto* layout = new QVBoxLayout(content);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(kSpacing);
  layout->addWidget(group(tr("Fractional-order hold"), beta_panel, content));
  layout->addWidget(group(tr("Closed-loop metrics"), metrics_, content));
  layout->addWidget(group(tr("Controller settings"), settings_, content));
  layout->addWidget(group(tr("Workpiece depth profile"), depth_, content));
  layout->addStretch(1);

  return verticalScroll(content, QStringLiteral("controlSettingsScroll"), this);
}

bool ControlView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == charts_scroll_ && event->type() == QEvent::Resize) arrangeCharts();
  return QWidget::eventFilter(watched, event);
}

// Side by side when the column holds both at their minimum widths (and a scroll bar) and is wide for its
// height; the scroll area's own size, not its viewport's, so that a scroll bar appearing does not flip them.
void ControlView::arrangeCharts() {
  const QSize size = charts_scroll_->size();
  const int both = jc_->minimumWidth() + pole_zero_->minimumWidth() + charts_->handleWidth() +
                   charts_scroll_->style()->pixelMetric(QStyle::PM_ScrollBarExtent);
  const bool side_by_side = size.width() >= both && size.width() >= kSideBySideAspect * size.height();
  charts_->setOrientation(side_by_side ? Qt::Horizontal : Qt::Vertical);
}

Qt::Orientation ControlView::chartsOrientation() const {
  return charts_->orientation();
}

void ControlView::showBeta(double beta) {
  jc_->setCurrentBeta(beta);
  pole_zero_->setCaption(tr("Poles and zeros, \u03b2 = %1").arg(betaText(beta)));  // fits the map's width
}

void ControlView::setBeta(double beta) {
  beta_->setBeta(beta);
  showBeta(beta_->beta());
}

double ControlView::beta() const {
  return beta_->beta();
}

int ControlView::betaGesture() const {
  return beta_->gesture();
}

void ControlView::setTraces(const ControlTraces& t) {
  traces_ = t;
  plots_->setTraces(t);
  metrics_->setDepthSteps(ControlMetricsPanel::depthSteps(t.depth_mm));
}

void ControlView::setMetrics(const ControlMetricsView& m) {
  metrics_->setMetrics(m);
  jc_->setComputedJc(m.jc_n_s);
}

void ControlView::setJcCurve(const JcCurveView& c) {
  jc_->setCurve(c);
}

void ControlView::setPoleZero(const PoleZeroView& pz) {
  pole_zero_->setPoleZero(pz);
}

void ControlView::setSettings(const ControllerSettingsView& s) {
  settings_->setSettings(s);
  plots_->setFeedLimit(s.feed_max_mm_s);
}

ControllerSettingsView ControlView::settings() const {
  return settings_->settings();
}

void ControlView::setWorkpiece(const QVector<DepthStepView>& steps) {
  depth_->setSteps(steps);
}

QVector<DepthStepView> ControlView::workpiece() const {
  return depth_->steps();
}

void ControlView::setBusy(bool busy) {
  busy_ = busy;
  busy_bar_->setVisible(busy);
}

void ControlView::setStatus(const QString& text) {
  status_->setText(text);
}

QString ControlView::statusText() const {
  return status_->text();
}

void ControlView::setUnits(DisplayUnits* units) {
  units_ = units;
  plots_->setUnits(units);
  metrics_->setUnits(units);
  settings_->setUnits(units);
}

bool ControlView::saveResponsePlots(const QString& path, int width, int height, const QString& title) {
  const QString shown = title.isEmpty()
                            ? tr("Discrete and continuous responses, tracking error and programmed control law, "
                                 "\u03b2 = %1")
                                  .arg(betaText(beta()))
                            : title;
  return ControlPlots::saveResponses(traces_, settings().feed_max_mm_s, path, width, height, shown, units_);
}

bool ControlView::saveJcPlot(const QString& path, int width, int height) {
  return jc_->savePng(path, width, height);
}

int ControlView::graphPointCount(const QString& graph_name) const {
  if (graph_name == QLatin1String("Jc")) return jc_->pointCount();
  if (graph_name == QLatin1String("poles")) return pole_zero_->poleCount();
  if (graph_name == QLatin1String("zeros")) return pole_zero_->zeroCount();
  return plots_->graphPointCount(graph_name);
}

QSlider* ControlView::betaSlider() const {
  return beta_->slider();
}

QDoubleSpinBox* ControlView::betaSpin() const {
  return beta_->spin();
}

}  // namespace mx::widgets
