#pragma once
// Live readouts of the operating point: speed, depth, feed per tooth, peak power and its fraction of
// the spindle limit, MRR, b_lim at that speed, Delta N_s, ROS and the stable / unstable verdict.
#include <QLabel>
#include <QWidget>

#include "display_units.h"
#include "point_readout.h"

namespace mx::widgets {

class OperatingPointReadout : public QWidget {
  Q_OBJECT
 public:
  explicit OperatingPointReadout(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);
  void setReadout(const PointReadout& readout);
  const PointReadout& readout() const { return readout_; }
  QString text(const QString& field) const;  // the shown text of a field (tests): "speed", "blim", ...

 private:
  void refresh();
  QLabel* addRow(const QString& key, const QString& label, const QString& tooltip);

  DisplayUnits* units_ = nullptr;
  PointReadout readout_;
  QHash<QString, QLabel*> values_;
  QLabel* verdict_;
};

}  // namespace mx::widgets
