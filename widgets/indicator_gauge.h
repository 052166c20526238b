#pragma once
// A chatter indicator against its threshold (eta >= 1.3, chip ratio >= 1.25): the value as text and as
// a horizontal bar with the threshold marked, green below the threshold and red at or above it.
#include <QString>
#include <QWidget>
#include <optional>

namespace mx::widgets {

class IndicatorGauge : public QWidget {
  Q_OBJECT
 public:
  // `symbol` is shown before the value (e.g. "\u03b7"), `description` in the tooltip.
  IndicatorGauge(const QString& symbol, const QString& description, double threshold, QWidget* parent = nullptr);

  void setThreshold(double threshold);
  void setValue(double value);
  void clear();  // no value: grey, "–"

  std::optional<double> value() const { return value_; }
  double threshold() const { return threshold_; }
  bool exceeded() const { return value_ && *value_ >= threshold_; }
  QString text() const;

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

  static QColor okColor() { return QColor(44, 160, 44); }
  static QColor alarmColor() { return QColor(214, 39, 40); }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QString symbol_;
  double threshold_;
  std::optional<double> value_;
};

}  // namespace mx::widgets
