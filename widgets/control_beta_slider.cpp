#include "control_beta_slider.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace mx::widgets {

namespace {
int toTicks(double beta) {
  if (!std::isfinite(beta)) beta = 0.0;
  const int ticks = static_cast<int>(std::lround(beta * ControlBetaSlider::kStepsPerUnit));
  return std::clamp(ticks, -ControlBetaSlider::kStepsPerUnit, ControlBetaSlider::kStepsPerUnit);
}
double fromTicks(int ticks) {
  return static_cast<double>(ticks) / ControlBetaSlider::kStepsPerUnit;
}
}  // namespace

ControlBetaSlider::ControlBetaSlider(QWidget* parent)
    : QWidget(parent),
      slider_(new QSlider(Qt::Horizontal, this)),
      spin_(new QDoubleSpinBox(this)),
      debounce_(new QTimer(this)) {
  const QString tip =
      tr("Gain \u03b2 of the fractional-order hold: \u03b2 = 0 is the zero-order hold, \u03b2 = 1 the first-order "
         "hold. The closed loop is recomputed %1 ms after you stop moving.")
          .arg(kDebounceMs);
  auto* label = new QLabel(tr("\u03b2 [\u2013]:"), this);
  label->setToolTip(tip);
  slider_->setObjectName(QStringLiteral("betaSlider"));
  slider_->setRange(-kStepsPerUnit, kStepsPerUnit);
  slider_->setSingleStep(1);
  slider_->setPageStep(10);
  slider_->setTickPosition(QSlider::TicksBelow);
  slider_->setTickInterval(25);
  slider_->setMinimumWidth(160);
  slider_->setToolTip(tip);
  spin_->setObjectName(QStringLiteral("betaSpin"));
  spin_->setRange(-1.0, 1.0);
  spin_->setSingleStep(0.01);
  spin_->setDecimals(2);
  spin_->setKeyboardTracking(false);  // typed text counts when finished, not per keystroke
  spin_->setToolTip(tip);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(label);
  layout->addWidget(slider_, 1);
  layout->addWidget(spin_);

  debounce_->setSingleShot(true);
  debounce_->setInterval(kDebounceMs);
  connect(debounce_, &QTimer::timeout, this, &ControlBetaSlider::emitIfChanged);
  connect(slider_, &QSlider::valueChanged, this, [this](int ticks) {
    const QSignalBlocker block(spin_);
    spin_->setValue(fromTicks(ticks));
    userChanged();
  });
  connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
    const QSignalBlocker block(slider_);
    slider_->setValue(toTicks(value));
    userChanged();
  });
  connect(slider_, &QSlider::sliderPressed, this, [this] {
    ++drag_;
    dragging_ = true;
  });
  connect(slider_, &QSlider::sliderReleased, this, [this] {
    debounce_->stop();
    emitIfChanged();  // still part of the drag
    dragging_ = false;
  });
  setBeta(0.0);
}

void ControlBetaSlider::setBeta(double beta) {
  const int ticks = toTicks(beta);
  debounce_->stop();
  {
    const QSignalBlocker block_slider(slider_);
    const QSignalBlocker block_spin(spin_);
    slider_->setValue(ticks);
    spin_->setValue(fromTicks(ticks));
  }
  emitted_ = fromTicks(ticks);
}

double ControlBetaSlider::beta() const {
  return fromTicks(slider_->value());
}

bool ControlBetaSlider::pending() const {
  return debounce_->isActive();
}

void ControlBetaSlider::userChanged() {
  // Live while dragging: a pause of kDebounceMs recomputes; the release recomputes at once.
  debounce_->start();
}

void ControlBetaSlider::emitIfChanged() {
  const double value = beta();
  if (value == emitted_) return;
  emitted_ = value;
  emit betaChanged(value);
}

}  // namespace mx::widgets
