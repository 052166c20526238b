#pragma once
// The beta of the beta-FROH hold: a slider over [-1, 1] in steps of 0.01 and a spin box, kept in sync.
// A user change emits betaChanged once, kDebounceMs after the last movement, or at once when the
// slider is released; setBeta() emits nothing. The value emitted is always a multiple of 0.01.
// gesture() numbers the slider drags, so that the values one drag emits can be one undo step.
#include <QWidget>

class QDoubleSpinBox;
class QSlider;
class QTimer;

namespace mx::widgets {

class ControlBetaSlider : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kDebounceMs = 150;
  static constexpr int kStepsPerUnit = 100;  // slider ticks per unit of beta: step 0.01

  explicit ControlBetaSlider(QWidget* parent = nullptr);

  void setBeta(double beta);  // clamped to [-1, 1], rounded to 0.01; no signal
  double beta() const;
  bool pending() const;                                  // a user change waits for the debounce
  int gesture() const { return dragging_ ? drag_ : 0; }  // the drag emitting (press to release), else 0

  QSlider* slider() const { return slider_; }
  QDoubleSpinBox* spin() const { return spin_; }

 signals:
  void betaChanged(double beta);

 private:
  void userChanged();
  void emitIfChanged();

  QSlider* slider_;
  QDoubleSpinBox* spin_;
  QTimer* debounce_;
  double emitted_ = 0.0;  // the last value set or emitted
  int drag_ = 0;
  bool dragging_ = false;
};

}  // namespace mx::widgets
