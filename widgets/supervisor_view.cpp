#include "supervisor_view.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTabWidget>
#include <QTextDocument>
#include <QVBoxLayout>

#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "supervision_timeline.h"
#include "supervisor_comparison.h"

namespace mx::widgets {

SupervisorView::SupervisorView(QWidget* parent)
    : QWidget(parent),
      controller_(new QComboBox(this)),
      speed_(new QComboBox(this)),
      run_(new QPushButton(tr("Run"), this)),
      stop_(new QPushButton(tr("Stop"), this)),
      feed_hold_(new QPushButton(tr("Feed hold"), this)),
      chatter_(new QPushButton(tr("Chatter!"), this)),
      compare_(new QPushButton(tr("Compare none / SMC I / SMC II"), this)),
      time_constant_(new QDoubleSpinBox(this)),
      reset_feed_(new QComboBox(this)),
      status_(new QLabel(this)),
      metrics_(new QLabel(this)),
      tabs_(new QTabWidget(this)),
      chart_scroll_(new QScrollArea(this)),
      chart_(new GrafcetChartView(this)),
      timeline_(new SupervisionTimeline(this)),
      comparison_(new SupervisorComparison(this)),
      editor_(new GrafcetChartEditor(this)) {
  setObjectName(QStringLiteral("supervisorView"));
  controller_->setToolTip(
      tr("Supervisory controller: none (constant feed), SMC I (transfer line: model-based force "
         "control, two 1 mm passes) or SMC II (job shop: adaptive force control with chatter "
         "detection and suppression)"));
  speed_->addItem(tr("1\u00d7 (real time)"), 1.0);
  speed_->addItem(tr("5\u00d7"), 5.0);
  speed_->addItem(tr("20\u00d7"), 20.0);
  speed_->addItem(tr("max"), 0.0);
  speed_->setToolTip(tr("Simulated time per wall-clock time; max runs as fast as possible"));
  feed_hold_->setCheckable(true);
  feed_hold_->setToolTip(tr("Operator feed hold (signal a): press to hold the axes, press again to release"));
  chatter_->setToolTip(tr("Operator chatter signal (c): the operator heard chatter"));
  run_->setToolTip(tr("Run the supervised face-milling operation with the selected controller"));
  stop_->setToolTip(tr("Stop the running simulation"));
  compare_->setToolTip(tr("Run the operation with each controller and compare them"));
  status_->setObjectName(QStringLiteral("supervisorStatus"));
  metrics_->setObjectName(QStringLiteral("supervisorMetrics"));
  metrics_->setWordWrap(true);
  metrics_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  setUpModelController();

  chart_->setFitToWidget(true);  // the whole chart beside the timeline; the editor tab shows it full size
  chart_scroll_->setWidget(chart_);
  chart_scroll_->setWidgetResizable(true);
  chart_scroll_->setMinimumWidth(360);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(chart_scroll_);
  split->addWidget(timeline_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  split->setChildrenCollapsible(false);
  split->setSizes({900, 900});
  auto* run_tab = new QWidget(this);
  auto* run_layout = new QVBoxLayout(run_tab);
  run_layout->setContentsMargins(4, 4, 4, 4);
  run_layout->addWidget(split, 1);
  run_layout->addWidget(metrics_);

  auto* compare_tab = new QWidget(this);
  auto* compare_layout = new QVBoxLayout(compare_tab);
  compare_layout->setContentsMargins(4, 4, 4, 4);
  auto* compare_row = new QHBoxLayout;
  compare_row->addWidget(compare_);
  compare_row->addStretch(1);
  compare_layout->addLayout(compare_row);
  compare_layout->addWidget(comparison_, 1);

  tabs_->addTab(run_tab, tr("Run"));
  tabs_->addTab(compare_tab, tr("Compare"));
  tabs_->addTab(editor_, tr("Edit chart"));
  // Beside the tabs: the settings apply to Run and Compare alike and cost no height of the plots.
  tabs_->setCornerWidget(buildModelControllerRow(), Qt::TopRightCorner);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(buildToolbar());
  layout->addWidget(tabs_, 1);

  connect(controller_, &QComboBox::currentIndexChanged, this, [this] { emit controllerChanged(controller()); });
  connect(run_, &QPushButton::clicked, this, &SupervisorView::runRequested);
  connect(stop_, &QPushButton::clicked, this, &SupervisorView::stopRequested);
  connect(compare_, &QPushButton::clicked, this, &SupervisorView::compareRequested);
  connect(feed_hold_, &QPushButton::toggled, this, [this](bool on) {
    feed_hold_->setText(on ? tr("Release feed hold") : tr("Feed hold"));
    emit feedHoldToggled(on);
  });
  connect(chatter_, &QPushButton::clicked, this, &SupervisorView::chatterSignalled);
  connect(time_constant_, &QDoubleSpinBox::valueChanged, this, &SupervisorView::timeConstantEdited);
  connect(reset_feed_, &QComboBox::currentIndexChanged, this, [this] { emit resetFeedEdited(resetFeed()); });
  connect(chart_, &GrafcetChartView::activeStepsChanged, this, [this] { followTokens(); });
  setControllers({QStringLiteral("none"), QStringLiteral("smc1"), QStringLiteral("smc2")});
  setRunning(false);
  setMetrics({});
  setStatus(tr("Ready."));
}

QWidget* SupervisorView::buildToolbar() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(new QLabel(tr("Controller:"), bar));
  row->addWidget(controller_);
  row->addWidget(run_);
  row->addWidget(stop_);
  row->addWidget(new QLabel(tr("Speed:"), bar));
  row->addWidget(speed_);
  row->addSpacing(16);
  row->addWidget(new QLabel(tr("Operator:"), bar));
  row->addWidget(feed_hold_);
  row->addWidget(chatter_);
  row->addSpacing(16);
  row->addWidget(status_, 1);
  return bar;
}

// Module L (SMC I's model-based force controller): the limits are those of the project file.
void SupervisorView::setUpModelController() {
  time_constant_->setObjectName(QStringLiteral("supervisorTimeConstant"));
  time_constant_->setRange(1.0, 1e5);
  time_constant_->setDecimals(1);
  time_constant_->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);  // a tenth of the decade: 1 ms at 50 ms
  time_constant_->setKeyboardTracking(false);  // one edit per committed value, not per keystroke
  time_constant_->setValue(200.0);
  time_constant_->setToolTip(
      tr("Closed-loop force time constant \u03c4 of SMC I's model-based force controller (module L, "
         "supervisor.model_controller.time_constant_ms): after each contact F_Y approaches F_ref as a "
         "first-order response with this time constant. Smaller settles faster; larger changes the feed "
         "more gently. 1 to 100000 ms, default 200 ms."));
  reset_feed_->setObjectName(QStringLiteral("supervisorResetFeed"));
  reset_feed_->addItem(tr("from the force model"), QStringLiteral("model"));
  reset_feed_->addItem(tr("from the current feed (bumpless)"), QStringLiteral("current"));
  reset_feed_->setToolTip(
      tr("Where SMC I's model-based force controller (module L) restarts at each contact "
         "(supervisor.model_controller.reset_feed):\n"
         "from the force model: the feed that gives F_ref at the pass depth in the inverse force model "
         "(model, the default);\n"
         "from the current feed (bumpless): the feed the axis is moving at (current)."));
}

QWidget* SupervisorView::buildModelControllerRow() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  auto* module = new QLabel(tr("Module L (SMC I):"), bar);
  module->setToolTip(tr("SMC I's model-based force controller; the other controllers do not use it"));
  row->addWidget(module);
  row->addSpacing(8);
  // The labels carry their field's tooltip and name it for screen readers.
  const auto addField = [bar, row](const QString& text, QWidget* field) {
    auto* label = new QLabel(text, bar);
    label->setBuddy(field);
    label->setToolTip(field->toolTip());
    row->addWidget(label);
    row->addWidget(field);
  };
  addField(tr("Force time constant \u03c4 [ms]:"), time_constant_);
  row->addSpacing(16);
  addField(tr("Restart at contact:"), reset_feed_);
  return bar;
}

void SupervisorView::followTokens() {
  const QList<int> active = chart_->activeSteps();
  if (active.isEmpty()) return;
  const QRect r = chart_->stepRect(active.front()).toAlignedRect();
  chart_scroll_->ensureVisible(r.center().x(), r.center().y(), r.width() + 60, r.height() + 60);
}

void SupervisorView::setControllers(const QStringList& names) {
  const QString current = controller();
  const QSignalBlocker block(controller_);
  controller_->clear();
  for (const QString& n : names) controller_->addItem(SupervisorComparison::controllerCaption(n), n);
  const int i = controller_->findData(current);
  controller_->setCurrentIndex(i >= 0 ? i : 0);
}

QString SupervisorView::controller() const {
  return controller_->currentData().toString();
}

void SupervisorView::setController(const QString& name) {
  const int i = controller_->findData(name);
  if (i < 0) return;
  const QSignalBlocker block(controller_);
  controller_->setCurrentIndex(i);
}

void SupervisorView::setRunning(bool running) {
  running_ = running;
  run_->setEnabled(!running);
  compare_->setEnabled(!running);
  controller_->setEnabled(!running);
  stop_->setEnabled(running);
  feed_hold_->setEnabled(running);
  chatter_->setEnabled(running);
  time_constant_->setEnabled(!running);  // the running cycle keeps the settings it started with
  reset_feed_->setEnabled(!running);
  if (!running && feed_hold_->isChecked()) {  // a finished run releases the hold without an event
    const QSignalBlocker block(feed_hold_);
    feed_hold_->setChecked(false);
    feed_hold_->setText(tr("Feed hold"));
  }
}

void SupervisorView::setMetrics(const SupervisionMetricsView& m) {
  if (m.controller.isEmpty()) {
    metrics_->setText(tr("No supervised run yet."));
    return;
  }
  const QString chatter = m.chatter_detected
                              ? (m.chatter_time_s ? tr("chatter detected at %1 s").arg(*m.chatter_time_s, 0, 'f', 2)
                                                  : tr("chatter detected"))
                              : tr("no chatter");
  const QString power = QString::number(m.max_power_pct_of_limit, 'f', 0);
  metrics_->setText(
      tr("<b>%1</b>: max. power <span style='color:%2'>%3 % of the limit</span> \u00b7 force overshoot %4 % "
         "\u00b7 %5 \u00b7 %6 pass(es) \u00b7 cycle time %7 s")
          .arg(SupervisorComparison::controllerCaption(m.controller),
               m.max_power_pct_of_limit > 100.0 ? QStringLiteral("#b41414") : QStringLiteral("#207020"), power,
               QString::number(m.overshoot_pct, 'f', 0), chatter, QString::number(m.passes),
               QString::number(m.cycle_time_s, 'f', 2)));
}

QString SupervisorView::metricsText() const {
  QTextDocument doc;
  doc.setHtml(metrics_->text());
  return doc.toPlainText();
}

void SupervisorView::setStatus(const QString& text) {
  status_->setText(text);
}

QString SupervisorView::statusText() const {
  return status_->text();
}

bool SupervisorView::feedHoldOn() const {
  return feed_hold_->isChecked();
}

double SupervisorView::speedFactor() const {
  return speed_->currentData().toDouble();
}

void SupervisorView::setModelController(double time_constant_ms, const QString& reset_feed) {
  const QSignalBlocker block_time(time_constant_);
  const QSignalBlocker block_reset(reset_feed_);
  time_constant_->setValue(time_constant_ms);
  const int i = reset_feed_->findData(reset_feed);
  if (i >= 0) reset_feed_->setCurrentIndex(i);
}

double SupervisorView::timeConstantMs() const {
  return time_constant_->value();
}

QString SupervisorView::resetFeed() const {
  return reset_feed_->currentData().toString();
}

}  // namespace mx::widgets
