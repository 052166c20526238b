#include "control_view.h"

#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QVBoxLayout>

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

QString betaText(double beta) {
  return QString::number(beta, 'f', 2).replace(QLatin1Char('-'), QChar(0x2212));
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
      pole_zero_(new PoleZeroPlot(this)) {
  sweep_->setObjectName(QStringLiteral("controlSweepButton"));
  sweep_->setToolTip(tr("Run the closed loop over \u03b2 in [\u22121, 1] and plot J_c(\u03b2) (figure 13)"));
  busy_bar_->setRange(0, 0);  // indeterminate
  busy_bar_->setMaximumHeight(8);
  busy_bar_->setTextVisible(false);
  busy_bar_->setVisible(false);
  status_->setObjectName(QStringLiteral("controlStatus"));
  status_->setWordWrap(true);

  auto* right = new QSplitter(Qt::Vertical, this);
  right->addWidget(jc_);
  right->addWidget(pole_zero_);
  right->setStretchFactor(0, 1);
  right->setStretchFactor(1, 1);
  right->setChildrenCollapsible(false);

  auto* columns = new QSplitter(Qt::Horizontal, this);
  columns->addWidget(buildLeftColumn());
  columns->addWidget(plots_);
  columns->addWidget(right);
  columns->setStretchFactor(0, 0);
  columns->setStretchFactor(1, 3);
  columns->setStretchFactor(2, 2);
  columns->setChildrenCollapsible(false);
  columns->setSizes({360, 960, 560});
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

  auto* scroll = new QScrollArea(this);
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(content->minimumSizeHint().width() + 24);
  return scroll;
}

void ControlView::showBeta(double beta) {
  jc_->setCurrentBeta(beta);
  pole_zero_->setCaption(tr("Poles and zeros of H_\u03b2(z), \u03b2 = %1").arg(betaText(beta)));
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
