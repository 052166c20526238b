#pragma once
// The LSCF stabilisation diagram (Peeters et al. 2004, sec. 3): a marker per pole at (frequency, model
// order) by stability class, behind them on a right-hand axis the summed measured magnitude
// sum_dirs |H| [µm/N]. A click chooses the nearest pole (within 10 px) or takes it back; one chosen pole
// per 1 % frequency cluster. QCustomPlot stays behind this class.
#include <QStringList>
#include <QWidget>
#include <complex>
#include <vector>

#include "modal_fit/stabilisation.h"

class QCustomPlot;
class QCPGraph;
class QMouseEvent;

namespace mx::widgets {

class StabilisationDiagramView : public QWidget {
  Q_OBJECT
 public:
  explicit StabilisationDiagramView(QWidget* parent = nullptr);

  // Clears the selection.
  void setDiagram(const mx::StabilisationDiagram& diagram, const std::vector<double>& frequency_hz,
                  const std::vector<double>& summed_magnitude_m_per_n);
  void setSelectedPoles(const std::vector<std::complex<double>>& poles);  // no selectionChanged
  std::vector<std::complex<double>> selectedPoles() const { return selected_; }
  void clear();
  // Toggles the pole nearest (frequency_hz, order) on screen, within 10 px; choosing a pole replaces a
  // chosen one within 1 % in frequency. Returns true (and emits selectionChanged) when the selection
  // changed.
  bool togglePoleNear(double frequency_hz, double order);

  // For tests.
  int markerCount(mx::PoleStability stability) const;
  int chosenMarkerCount() const;
  int magnitudePointCount() const;
  QStringList legendNames() const;
  QString xAxisLabel() const;
  QString yAxisLabel() const;
  QString magnitudeAxisLabel() const;

 signals:
  void selectionChanged(const std::vector<std::complex<double>>& poles);

 private:
  struct PlacedPole {
    std::complex<double> lambda;
    double frequency_hz;
    int order;
  };
  void onMousePress(QMouseEvent* event);
  void showSelection();
  QPointF toScreen(double frequency_hz, double order) const;

  QCustomPlot* plot_;
  QCPGraph* magnitude_;
  QCPGraph* stable_;
  QCPGraph* frequency_stable_;
  QCPGraph* unstable_;
  QCPGraph* chosen_;
  std::vector<PlacedPole> poles_;
  std::vector<std::complex<double>> selected_;
};

}  // namespace mx::widgets
