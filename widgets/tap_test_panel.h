#pragma once
// The tap-test fit panel a dock hosts: the measured and fitted FRFs above the stabilisation diagram,
// and the fit's form (direction, band, model size, method), its buttons, progress and the fitted modes.
// The panel asks for fits through fitRequested; a runner answers with setFitResult.
#include <QMetaType>
#include <QString>
#include <QWidget>
#include <complex>
#include <map>
#include <optional>
#include <vector>

#include "modal_fit/modal_fit.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QPushButton;
class QProgressBar;
class QLabel;
class QTableWidget;

namespace mx::widgets {

class FrfPlotView;
class StabilisationDiagramView;

struct TapTestFitRequest {
  QString direction;
  double from_hz = 0.0, to_hz = 0.0;
  int max_modes = 10;
  std::optional<int> modes;                 // automatic when empty
  bool peak = false;                        // peak picking instead of LSCF
  std::vector<std::complex<double>> poles;  // non-empty: fit at these chosen poles
};

class TapTestPanel : public QWidget {
  Q_OBJECT
 public:
  explicit TapTestPanel(QWidget* parent = nullptr);

  FrfPlotView* frfView() { return frf_view_; }
  StabilisationDiagramView* diagramView() { return diagram_view_; }

  // Receptance [m/N]; the band limits span every measured direction.
  void setMeasurement(const QString& direction, const std::vector<double>& frequency_hz,
                      const std::vector<std::complex<double>>& h_m_per_n);
  void clearMeasurement(const QString& direction);
  // The fitted curve, modes and fit error; the diagram too unless keep_diagram (a fit at chosen poles).
  void setFitResult(const QString& direction, const mx::ModalFitResult& result, bool keep_diagram);
  void setBusy(bool busy);
  void setProgress(double fraction);
  void setMessage(const QString& text);
  QString currentDirection() const;
  void setCurrentDirection(const QString& direction);  // "x" or "y"
  void requestFit();                                   // as the Fit button, when it is enabled

 signals:
  // The Fit button (no poles), and a changed non-empty diagram selection (its poles).
  void fitRequested(const mx::widgets::TapTestFitRequest& request);
  void cancelRequested();
  void acceptRequested(const QString& direction);

 private:
  struct Measurement {
    std::vector<double> frequency_hz;
    std::vector<std::complex<double>> h_m_per_n;
  };
  QWidget* buildForm();
  TapTestFitRequest formRequest() const;
  void updateBandLimits();
  void showCurves();
  void showDiagram();
  void showModes();
  void updateButtons();

  FrfPlotView* frf_view_;
  StabilisationDiagramView* diagram_view_;
  QComboBox* direction_;
  QDoubleSpinBox* from_hz_;
  QDoubleSpinBox* to_hz_;
  QSpinBox* max_modes_;
  QSpinBox* modes_;
  QComboBox* method_;
  QPushButton* fit_;
  QPushButton* cancel_;
  QPushButton* accept_;
  QProgressBar* progress_;
  QLabel* fit_error_;
  QLabel* message_;
  QTableWidget* modes_table_;
  std::map<QString, Measurement> measurements_;
  std::map<QString, mx::ModalFitResult> results_;
  std::map<QString, mx::StabilisationDiagram> diagrams_;
  bool busy_ = false;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::TapTestFitRequest)
