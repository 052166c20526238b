#pragma once
// Live readouts of the operating point: speed, depth, feed per tooth, surface speed, feed rate, peak power and its
// fraction of the spindle limit, MRR, b_lim at that speed, Delta N_s, ROS, the stable / marginal / unstable verdict of
// the lobes, and the time-domain simulation of the same point. When the lobes and the simulation disagree, a note under
// the verdict shows both and says that the verdict follows the lobes. Every value is shown in the window's shop units
// (DisplayUnits) with its unit.
#include <QLabel>
#include <QPointer>
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
  void setSimulation(const SimulationCheck& check);  // of the shown point only
  QString agreementNote() const;                     // "" unless the lobes and the simulation disagree
  QString text(const QString& field) const;          // the shown text of a field (tests): "speed", "blim", ...

 private:
  void refresh();
  QLabel* addRow(const QString& key, const QString& label, const QString& tooltip);

  QPointer<DisplayUnits> units_;
  void refreshSimulation();

  PointReadout readout_;
  SimulationCheck simulation_;
  QHash<QString, QLabel*> values_;
  QLabel* verdict_;
  QLabel* agreement_;
};

}  // namespace mx::widgets
