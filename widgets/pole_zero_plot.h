#pragma once
// The pole-zero map of H_beta(z) for the current beta: the unit circle, poles as crosses, zeros as
// circles (red when outside the unit circle: an unstable zero, which the controller must not cancel),
// coincident roots labelled with their multiplicity. Equal aspect: one unit of Re z spans as many
// pixels as one unit of Im z whatever the widget's shape. QCustomPlot stays behind this class.
#include <QPair>
#include <QStringList>
#include <QVector>
#include <QWidget>
#include <complex>

#include "control_data.h"

class QCustomPlot;
class QCPCurve;
class QCPTextElement;
class QCPAbstractItem;

namespace mx::widgets {

class PoleZeroPlot : public QWidget {
  Q_OBJECT
 public:
  explicit PoleZeroPlot(QWidget* parent = nullptr);

  void setPoleZero(const PoleZeroView& pz);  // non-finite roots are left out
  void setCaption(const QString& caption);   // shown above the map, e.g. "Poles and zeros, β = 0.30"
  void clear();

  int poleCount() const;
  int zeroCount() const;          // all plotted zeros, inside or outside the unit circle
  int unstableZeroCount() const;  // zeros with |z| > 1
  int multiplicityLabelCount() const { return static_cast<int>(labels_.size()); }
  QStringList legendNames() const;
  QString xAxisLabel() const;
  QString yAxisLabel() const;
  QPair<double, double> xRange() const;
  QPair<double, double> yRange() const;
  // (Re units per pixel) / (Im units per pixel) of the last layout: 1 for an equal aspect.
  double aspectRatio() const;
  bool savePng(const QString& path, int width, int height);

 private:
  void applyEqualAspect();
  void addMultiplicityLabels(const QVector<std::complex<double>>& roots);  // "2" beside a double root

  QCustomPlot* plot_;
  QCPCurve* circle_;
  QCPCurve* poles_;
  QCPCurve* zeros_;
  QCPCurve* unstable_zeros_;
  QCPTextElement* caption_;
  QVector<QCPAbstractItem*> labels_;
  double x_lo_ = -1.2, x_hi_ = 1.2, y_lo_ = -1.2, y_hi_ = 1.2;  // data bounds to show
};

}  // namespace mx::widgets
