#include "tap_test_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "frf_interpolation.h"
#include "frf_plot_view.h"
#include "modal_fit/fit_settings.h"
#include "stabilisation_diagram_view.h"

namespace mx::widgets {

namespace {
constexpr int kProgressSteps = 1000;
constexpr int kDefaultMaxModes = 10;

QTableWidgetItem* numberItem(double value, int decimals) {
  auto* item = new QTableWidgetItem(QString::number(value, 'f', decimals));
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
  return item;
}
}  // namespace

TapTestPanel::TapTestPanel(QWidget* parent)
    : QWidget(parent),
      frf_view_(new FrfPlotView(this)),
      diagram_view_(new StabilisationDiagramView(this)),
      direction_(new QComboBox(this)),
      from_hz_(new QDoubleSpinBox(this)),
      to_hz_(new QDoubleSpinBox(this)),
      max_modes_(new QSpinBox(this)),
      modes_(new QSpinBox(this)),
      method_(new QComboBox(this)),
      fit_(new QPushButton(tr("Fit"), this)),
      cancel_(new QPushButton(tr("Cancel"), this)),
      accept_(new QPushButton(tr("Accept"), this)),
      progress_(new QProgressBar(this)),
      fit_error_(new QLabel(this)),
      message_(new QLabel(this)),
      modes_table_(new QTableWidget(0, 3, this)) {
  // Side by side: the dock sits below the lobe chart, wide and short at 1080p.
  auto* plots = new QSplitter(Qt::Horizontal, this);
  plots->addWidget(frf_view_);
  plots->addWidget(diagram_view_);
  plots->setStretchFactor(0, 1);
  plots->setStretchFactor(1, 1);
  auto* layout = new QHBoxLayout(this);
  layout->addWidget(plots, 1);
  layout->addWidget(buildForm());

  connect(direction_, &QComboBox::currentIndexChanged, this, [this] {
    showDiagram();
    showModes();
    updateButtons();
  });
  connect(fit_, &QPushButton::clicked, this, [this] { emit fitRequested(formRequest()); });
  connect(cancel_, &QPushButton::clicked, this, &TapTestPanel::cancelRequested);
  connect(accept_, &QPushButton::clicked, this, [this] { emit acceptRequested(currentDirection()); });
  connect(diagram_view_, &StabilisationDiagramView::selectionChanged, this,
          [this](const std::vector<std::complex<double>>& poles) {
            if (poles.empty() || !measurements_.contains(currentDirection())) return;
            TapTestFitRequest request = formRequest();
            request.poles = poles;
            emit fitRequested(request);
          });
  updateBandLimits();
  showModes();
  updateButtons();
}

QWidget* TapTestPanel::buildForm() {
  auto* form_widget = new QWidget(this);
  form_widget->setFixedWidth(320);
  auto* column = new QVBoxLayout(form_widget);
  column->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  direction_->setObjectName(QStringLiteral("direction"));
  direction_->addItems({QStringLiteral("x"), QStringLiteral("y")});
  form->addRow(tr("direction"), direction_);
  for (QDoubleSpinBox* spin : {from_hz_, to_hz_}) {
    spin->setDecimals(1);
    spin->setSingleStep(10.0);
  }
  from_hz_->setObjectName(QStringLiteral("from_hz"));
  to_hz_->setObjectName(QStringLiteral("to_hz"));
  form->addRow(tr("from [Hz]"), from_hz_);
  form->addRow(tr("to [Hz]"), to_hz_);
  max_modes_->setObjectName(QStringLiteral("max_modes"));
  max_modes_->setRange(1, kMaxModes);
  max_modes_->setValue(kDefaultMaxModes);
  form->addRow(tr("max modes"), max_modes_);
  modes_->setObjectName(QStringLiteral("modes"));
  modes_->setRange(0, kMaxModes);
  modes_->setSpecialValueText(tr("automatic"));
  form->addRow(tr("modes"), modes_);
  method_->setObjectName(QStringLiteral("method"));
  method_->addItems({tr("LSCF"), tr("peak picking")});
  form->addRow(tr("method"), method_);
  column->addLayout(form);

  auto* buttons = new QHBoxLayout;
  fit_->setObjectName(QStringLiteral("fit"));
  cancel_->setObjectName(QStringLiteral("cancel"));
  accept_->setObjectName(QStringLiteral("accept"));
  for (QPushButton* b : {fit_, cancel_, accept_}) buttons->addWidget(b);
  column->addLayout(buttons);
  progress_->setObjectName(QStringLiteral("progress"));
  progress_->setRange(0, kProgressSteps);
  progress_->setValue(0);
  column->addWidget(progress_);

  fit_error_->setObjectName(QStringLiteral("fit_error"));
  column->addWidget(fit_error_);
  modes_table_->setObjectName(QStringLiteral("modes_table"));
  modes_table_->setHorizontalHeaderLabels({tr("f [Hz]"), tr("\u03b6 [%]"), tr("k [N/\u00b5m]")});
  modes_table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  modes_table_->verticalHeader()->setVisible(false);
  modes_table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  column->addWidget(modes_table_, 1);
  message_->setObjectName(QStringLiteral("message"));
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  column->addWidget(message_);
  return form_widget;
}

QString TapTestPanel::currentDirection() const {
  return direction_->currentText();
}

void TapTestPanel::setCurrentDirection(const QString& direction) {
  direction_->setCurrentText(direction);
}

void TapTestPanel::requestFit() {
  if (fit_->isEnabled()) fit_->click();
}

TapTestFitRequest TapTestPanel::formRequest() const {
  TapTestFitRequest request;
  request.direction = currentDirection();
  request.from_hz = from_hz_->value();
  request.to_hz = to_hz_->value();
  request.max_modes = max_modes_->value();
  if (modes_->value() > 0) request.modes = modes_->value();
  request.peak = method_->currentIndex() == 1;
  return request;
}

void TapTestPanel::setMeasurement(const QString& direction, const std::vector<double>& frequency_hz,
                                  const std::vector<std::complex<double>>& h_m_per_n) {
  const bool first = measurements_.empty();
  measurements_[direction] = {frequency_hz, h_m_per_n};
  results_.erase(direction);
  diagrams_.erase(direction);
  updateBandLimits();
  if (first) {
    from_hz_->setValue(from_hz_->minimum());
    to_hz_->setValue(to_hz_->maximum());
  }
  if (direction == currentDirection()) showModes();
  showCurves();
  showDiagram();
  updateButtons();
}

void TapTestPanel::clearMeasurement(const QString& direction) {
  measurements_.erase(direction);
  results_.erase(direction);
  diagrams_.erase(direction);
  updateBandLimits();
  showCurves();
  showDiagram();
  showModes();
  updateButtons();
}

// The band may cover every measured line above 0 Hz (the fit leaves 0 Hz out).
void TapTestPanel::updateBandLimits() {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& [direction, m] : measurements_)
    for (const double f : m.frequency_hz)
      if (f > 0.0 && std::isfinite(f)) {
        lo = std::min(lo, f);
        hi = std::max(hi, f);
      }
  if (!(lo < hi)) {
    lo = 0.0;
    hi = 0.0;
  }
  for (QDoubleSpinBox* spin : {from_hz_, to_hz_}) spin->setRange(lo, hi);
}

void TapTestPanel::setFitResult(const QString& direction, const mx::ModalFitResult& result, bool keep_diagram) {
  results_[direction] = result;
  if (!keep_diagram) diagrams_[direction] = result.diagram;
  showCurves();
  if (!keep_diagram && direction == currentDirection()) showDiagram();
  if (direction == currentDirection()) showModes();
  updateButtons();
}

void TapTestPanel::showCurves() {
  std::vector<FrfCurve> measured, fitted;
  for (const auto& [direction, m] : measurements_)
    measured.push_back({tr("measured %1").arg(direction), m.frequency_hz, m.h_m_per_n});
  for (const auto& [direction, r] : results_)
    fitted.push_back({tr("fitted %1").arg(direction), r.band_frequency_hz, r.fitted});
  frf_view_->setMeasured(measured);
  frf_view_->setFitted(fitted);
}

// The current direction's diagram over sum_dirs |H| on its grid (other directions interpolated).
void TapTestPanel::showDiagram() {
  const auto own = measurements_.find(currentDirection());
  if (own == measurements_.end()) {
    diagram_view_->clear();
    return;
  }
  const std::vector<double>& grid = own->second.frequency_hz;
  std::vector<double> summed(grid.size(), 0.0);
  for (const auto& [direction, m] : measurements_)
    for (std::size_t i = 0; i < grid.size(); ++i)
      if (const auto h = interpolateFrf(m.frequency_hz, m.h_m_per_n, grid[i])) summed[i] += std::abs(*h);
  const auto diagram = diagrams_.find(currentDirection());
  diagram_view_->setDiagram(diagram == diagrams_.end() ? StabilisationDiagram{} : diagram->second, grid, summed);
}

void TapTestPanel::showModes() {
  const auto result = results_.find(currentDirection());
  modes_table_->setRowCount(0);
  if (result == results_.end()) {
    fit_error_->setText(tr("fit error [%]: \u2013"));
    return;
  }
  const ModalAxis& modes = result->second.modes;
  modes_table_->setRowCount(static_cast<int>(modes.size()));
  for (int row = 0; row < static_cast<int>(modes.size()); ++row) {
    const Mode& m = modes[static_cast<std::size_t>(row)];
    modes_table_->setItem(row, 0, numberItem(m.natural_frequency_hz, 1));
    modes_table_->setItem(row, 1, numberItem(100.0 * m.damping_ratio, 2));
    modes_table_->setItem(row, 2, numberItem(1e-6 * m.stiffness_n_per_m, 2));
  }
  fit_error_->setText(tr("fit error [%]: %1   (%2)")
                          .arg(result->second.fit_error_pct, 0, 'f', 2)
                          .arg(QString::fromStdString(result->second.method)));
}

void TapTestPanel::setBusy(bool busy) {
  busy_ = busy;
  if (busy) progress_->setValue(0);
  updateButtons();
}

void TapTestPanel::setProgress(double fraction) {
  progress_->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kProgressSteps)));
}

void TapTestPanel::setMessage(const QString& text) {
  message_->setText(text);
}

void TapTestPanel::updateButtons() {
  const QString direction = currentDirection();
  fit_->setEnabled(!busy_ && measurements_.contains(direction));
  cancel_->setEnabled(busy_);
  accept_->setEnabled(!busy_ && results_.contains(direction));
}

}  // namespace mx::widgets
