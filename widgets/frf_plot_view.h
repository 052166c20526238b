#pragma once
// Measured and fitted receptance FRFs: |H| [µm/N] over the phase [deg], or Re H over Im H [µm/N], and
// below them the residual |ΔH| = |H_measured - H_fitted| [µm/N] at the fitted curve's frequencies. A small
// toolbar switches the display and the frequency axis scale. Values come in SI (m/N). QCustomPlot stays
// behind this class.
#include <QString>
#include <QStringList>
#include <QWidget>
#include <complex>
#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QComboBox;
class QCheckBox;

namespace mx::widgets {

struct FrfCurve {
  QString label;  // e.g. "measured x", "fitted x"
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> h_m_per_n;
};

class FrfPlotView : public QWidget {
  Q_OBJECT
 public:
  enum class Display { MagnitudePhase, RealImaginary };

  explicit FrfPlotView(QWidget* parent = nullptr);

  void setMeasured(const std::vector<FrfCurve>& curves);  // one per direction
  // Drawn dashed over the measurement. A fitted curve's residual is taken against the measured curve
  // of the same direction (the label's last word, "fitted x" - "measured x"), else the one at its index.
  void setFitted(const std::vector<FrfCurve>& curves);
  void setDisplay(Display display);
  void setLogFrequency(bool on);
  void clear();

  Display display() const { return display_; }
  bool logFrequency() const;  // the frequency axes' scale
  // For tests: graphs with data per panel, the axis labels, the legend and the residual points.
  int upperGraphCount() const;
  int lowerGraphCount() const;
  int residualGraphCount() const;
  QString frequencyAxisLabel() const;
  QString upperAxisLabel() const;
  QString lowerAxisLabel() const;
  QString residualAxisLabel() const;
  QStringList legendNames() const;
  // The lower panel's values of a curve (measured ones first, then the fitted): phase [deg] or Im H [µm/N].
  std::vector<double> lowerPanelValues(int curve_index) const;
  std::vector<double> residualFrequencies(int fitted_index) const;
  std::vector<double> residualMicrometrePerNewton(int fitted_index) const;  // |H_m - H_f| [µm/N]

 private:
  void rebuild();
  void addCurve(const FrfCurve& curve, const QPen& pen);
  void addResidual(const FrfCurve& fitted, const FrfCurve& measured, const QPen& pen);
  const FrfCurve* measuredFor(const FrfCurve& fitted, std::size_t index) const;
  void applyAxes();

  QComboBox* display_box_;
  QCheckBox* log_box_;
  QCustomPlot* plot_;
  QCPAxisRect* upper_;
  QCPAxisRect* lower_;
  QCPAxisRect* residual_;
  std::vector<FrfCurve> measured_, fitted_;
  std::vector<QCPGraph*> residual_graphs_;  // one per fitted curve
  Display display_ = Display::MagnitudePhase;
};

}  // namespace mx::widgets
