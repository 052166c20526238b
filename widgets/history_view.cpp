#include "history_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "monitoring_panel.h"

namespace mx::widgets {

namespace {

struct ColumnSpec {
  const char* header;
  const char* tip;
};

constexpr ColumnSpec kColumns[HistoryView::ColumnCount] = {
    {"Time", "When the point was programmed (UTC, ISO 8601)"},
    {"Tool", "Tool id"},
    {"Material", "Workpiece material"},
    {"Machine", "The machine that ran the point (the project's machine name; \u2014 when none was named)"},
    {"Source",
     "Who chose the point: operator, automatic (expert system), rule (operator rules) or feedback "
     "(Rule 15/16 re-selection)"},
    {"w_TOL [\u2013]", "Pareto weight of tool life (for a 2006 expert-system point: the cost weight c1)"},
    {"w_MRR [\u2013]", "Pareto weight of the material removal rate (2006 point: c2)"},
    {"w_SURF [\u2013]", "Pareto weight of the roughness (2006 point: c3)"},
    {"w_ROS [\u2013]", "Pareto weight of the robustness (empty for a 2006 point)"},
    {"Speed [rpm]", "Spindle speed N of the programmed point"},
    {"Depth [%1]", "Axial depth of cut b of the programmed point"},  // %1: the shop unit of the column
    {"Feed [%1]", "Feed per tooth s_t of the programmed point"},
    {"MRR [%1]", "Material removal rate of the programmed point"},
    {"TOL [min]", "Tool life (Taylor model, eq. 10)"},
    {"SURF [\u00b5m]", "Surface roughness (eq. 12)"},
    {"ROS [\u2013]", "Robustness: normalised distance to the stability boundary (eq. 13)"},
};

const QString kNoMachine = QStringLiteral("\u2014");  // the record names no machine

const char* const kSources[] = {"operator", "automatic", "rule", "feedback"};

QString fixed(double v, int decimals) {
  return std::isfinite(v) ? QString::number(v, 'f', decimals) : "\u2013";
}

}  // namespace

HistoryView::HistoryView(QWidget* parent)
    : QWidget(parent),
      tool_(new QComboBox(this)),
      material_(new QComboBox(this)),
      machine_(new QComboBox(this)),
      source_(new QComboBox(this)),
      mrr_box_(new QCheckBox(this)),
      mrr_lo_(new QDoubleSpinBox(this)),
      mrr_hi_(new QDoubleSpinBox(this)),
      table_(new QTableWidget(0, ColumnCount, this)),
      apply_(new QPushButton(tr("Apply these weights"), this)),
      refresh_(new QPushButton(tr("Refresh"), this)),
      status_(new QLabel(this)) {
  setToolTip(
      tr("Rule 14 learning database: every programmed point with the weights that produced it, newest "
         "first."));
  tool_->setObjectName("history_tool");
  material_->setObjectName("history_material");
  machine_->setObjectName("history_machine");
  source_->setObjectName("history_source");
  mrr_box_->setObjectName("history_mrr_enable");
  mrr_lo_->setObjectName("history_mrr_lo");
  mrr_hi_->setObjectName("history_mrr_hi");
  table_->setObjectName("history_table");
  apply_->setObjectName("history_apply_weights");
  refresh_->setObjectName("history_refresh");
  status_->setObjectName("history_status");

  tool_->setToolTip(tr("Show only the points of this tool (Any: all tools)."));
  material_->setToolTip(tr("Show only the points of this workpiece material (Any: all materials)."));
  machine_->setToolTip(tr("Show only the points run on this machine (Any: all machines)."));
  source_->setToolTip(
      tr("Show only the points chosen by the operator, the expert system (automatic), the "
         "operator rules (rule) or the chatter feedback (feedback)."));

  apply_->setToolTip(
      tr("Use the selected point's Pareto weights (TOL, MRR, SURF, ROS) for the next selection. "
         "Double-clicking a row does the same. Disabled for 2006 points (three cost weights)."));
  refresh_->setToolTip(tr("Query the learning database again with the current filter."));
  status_->setToolTip(tr("The learning database file, or the last error."));
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  status_->setWordWrap(true);

  setChoices(tool_, {});
  setChoices(material_, {});
  setChoices(machine_, {});
  QStringList sources;
  for (const char* s : kSources) sources << QString::fromLatin1(s);
  setChoices(source_, sources);
  for (QDoubleSpinBox* spin : {mrr_lo_, mrr_hi_}) {
    spin->setSingleStep(1.0);
    spin->setKeyboardTracking(false);
    spin->setEnabled(false);
  }
  refreshUnits();
  table_->setToolTip(
      tr("Programmed points, newest first. Select a row and press \"Apply these weights\", or "
         "double-click it, to reuse its weights."));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setSortingEnabled(false);  // the order is the database's (newest first)
  table_->setAlternatingRowColors(true);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);

  auto* filters = new QHBoxLayout;
  auto addLabelled = [this, filters](const QString& text, QWidget* w) {
    auto* label = new QLabel(text, this);
    label->setBuddy(w);
    label->setToolTip(w->toolTip());
    filters->addWidget(label);
    filters->addWidget(w);
  };
  addLabelled(tr("Tool"), tool_);
  addLabelled(tr("Material"), material_);
  addLabelled(tr("Machine"), machine_);
  addLabelled(tr("Source"), source_);
  filters->addWidget(mrr_box_);
  filters->addWidget(mrr_lo_);
  auto* to = new QLabel(tr("to"), this);
  to->setToolTip(mrr_box_->toolTip());
  filters->addWidget(to);
  filters->addWidget(mrr_hi_);
  filters->addStretch(1);
  filters->addWidget(refresh_);

  auto* bottom = new QHBoxLayout;
  bottom->addWidget(status_, 1);
  bottom->addWidget(apply_);

  auto* outer = new QVBoxLayout(this);
  outer->addLayout(filters);
  outer->addWidget(table_, 1);
  outer->addLayout(bottom);

  last_filter_ = filter();
  updateButtons();

  for (QComboBox* combo : {tool_, material_, machine_, source_})
    connect(combo, &QComboBox::currentIndexChanged, this, &HistoryView::emitIfChanged);
  connect(mrr_box_, &QCheckBox::toggled, this, [this](bool on) {
    mrr_lo_->setEnabled(on);
    mrr_hi_->setEnabled(on);
    emitIfChanged();
  });
  connect(mrr_lo_, &QDoubleSpinBox::valueChanged, this, [this] { onMrrEdited(true); });
  connect(mrr_hi_, &QDoubleSpinBox::valueChanged, this, [this] { onMrrEdited(false); });
  connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, &HistoryView::updateButtons);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) { requestApply(row); });
  connect(apply_, &QPushButton::clicked, this, [this] { requestApply(selectedRow()); });
  connect(refresh_, &QPushButton::clicked, this, &HistoryView::refreshRequested);
}

void HistoryView::setChoices(QComboBox* combo, const QStringList& values) {
  const QString current = combo->count() > 0 ? combo->currentData().toString() : QString();
  const QSignalBlocker block(combo);
  combo->clear();
  combo->addItem(tr("Any"), QString());
  for (const QString& v : values)
    if (!v.isEmpty() && combo->findData(v) < 0) combo->addItem(v, v);
  selectValue(combo, current);
}

void HistoryView::selectValue(QComboBox* combo, const QString& value) {
  const QSignalBlocker block(combo);
  int index = combo->findData(value);
  if (index < 0) {
    combo->addItem(value, value);
    index = combo->count() - 1;
  }
  combo->setCurrentIndex(index);
}

void HistoryView::setToolChoices(const QStringList& tools) {
  setChoices(tool_, tools);
}

void HistoryView::setMaterialChoices(const QStringList& materials) {
  setChoices(material_, materials);
}

void HistoryView::setMachineChoices(const QStringList& machines) {
  setChoices(machine_, machines);
}

void HistoryView::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &HistoryView::refreshUnits);
}

// The headers, the MRR band and the rows in the shop units; the filter itself does not change.
void HistoryView::refreshUnits() {
  if (band_shown_) band_ = {mrrFromSpin(mrr_lo_, band_[0]), mrrFromSpin(mrr_hi_, band_[1])};  // in the old units
  band_shown_ = true;
  shown_units_ = DisplayUnits::of(units_);
  const ShopUnits& u = shown_units_;
  const QString mrr = u.symbol(Quantity::RemovalRate);
  QStringList headers;
  for (int c = 0; c < ColumnCount; ++c) {
    const QString header = tr(kColumns[c].header);
    headers << (c == DepthColumn  ? header.arg(u.symbol(Quantity::Length))
                : c == FeedColumn ? header.arg(u.symbol(Quantity::ChipLoad))
                : c == MrrColumn  ? header.arg(mrr)
                                  : header);
  }
  table_->setHorizontalHeaderLabels(headers);
  for (int c = 0; c < ColumnCount; ++c) table_->horizontalHeaderItem(c)->setToolTip(tr(kColumns[c].tip));
  mrr_box_->setText(tr("MRR [%1]").arg(mrr));
  mrr_box_->setToolTip(tr("Show only the points whose material removal rate lies in [lower, upper] %1.").arg(mrr));
  mrr_lo_->setToolTip(tr("Lower MRR bound [%1] (inclusive); above the upper bound it moves that bound.").arg(mrr));
  mrr_hi_->setToolTip(tr("Upper MRR bound [%1] (inclusive); below the lower bound it moves that bound.").arg(mrr));
  for (QDoubleSpinBox* spin : {mrr_lo_, mrr_hi_}) {
    const QSignalBlocker block(spin);
    spin->setDecimals(u.decimals(Quantity::RemovalRate) + 1);
    spin->setRange(0.0, shownMrr(kMaxMrrCm3S));
    spin->setSuffix(" " + mrr);
  }
  {
    const QSignalBlocker blockLo(mrr_lo_), blockHi(mrr_hi_);
    mrr_lo_->setValue(shownMrr(band_[0]));
    mrr_hi_->setValue(shownMrr(band_[1]));
  }
  setRows(QVector<HistoryRow>(rows_));
}

// In the units the band and the rows are shown in (those of the last refreshUnits()).
double HistoryView::shownMrr(double cm3_s) const {
  return shown_units_.fromBase(Quantity::RemovalRate, cm3PerMinFromCm3PerS(cm3_s));
}

// A bound in cm³/s: `stored` while the box still shows it (a unit conversion would move it).
double HistoryView::mrrFromSpin(const QDoubleSpinBox* spin, double stored) const {
  const int d = spin->decimals();
  if (QString::number(spin->value(), 'f', d) == QString::number(shownMrr(stored), 'f', d)) return stored;
  return cm3PerSFromCm3PerMin(shown_units_.toBase(Quantity::RemovalRate, spin->value()));
}

HistoryFilter HistoryView::filter() const {
  HistoryFilter f;
  f.tool = tool_->currentData().toString();
  f.material = material_->currentData().toString();
  f.machine = machine_->currentData().toString();
  f.source = source_->currentData().toString();
  if (mrr_box_->isChecked()) {
    f.mrr_lo = mrrFromSpin(mrr_lo_, band_[0]);
    f.mrr_hi = mrrFromSpin(mrr_hi_, band_[1]);
  }
  return f;
}

void HistoryView::setFilter(const HistoryFilter& f) {
  selectValue(tool_, f.tool);
  selectValue(material_, f.material);
  selectValue(machine_, f.machine);
  selectValue(source_, f.source);
  const bool band = f.mrr_lo && f.mrr_hi;
  {
    const QSignalBlocker blockBox(mrr_box_);
    const QSignalBlocker blockLo(mrr_lo_);
    const QSignalBlocker blockHi(mrr_hi_);
    mrr_box_->setChecked(band);
    mrr_lo_->setEnabled(band);
    mrr_hi_->setEnabled(band);
    if (band) {
      band_ = {std::min(*f.mrr_lo, *f.mrr_hi), std::max(*f.mrr_lo, *f.mrr_hi)};
      mrr_lo_->setValue(shownMrr(band_[0]));
      mrr_hi_->setValue(shownMrr(band_[1]));
    }
  }
  last_filter_ = filter();
}

void HistoryView::onMrrEdited(bool lower) {
  if (mrr_lo_->value() > mrr_hi_->value()) {
    QDoubleSpinBox* other = lower ? mrr_hi_ : mrr_lo_;
    const QSignalBlocker block(other);
    other->setValue(lower ? mrr_lo_->value() : mrr_hi_->value());
  }
  emitIfChanged();
}

void HistoryView::emitIfChanged() {
  const HistoryFilter f = filter();
  if (f == last_filter_) return;
  last_filter_ = f;
  emit filterChanged(f);
}

void HistoryView::setRows(const QVector<HistoryRow>& rows) {
  const int selected = selectedRow();
  const bool had_selection = selected >= 0;
  const qint64 selected_id = had_selection ? rows_[selected].id : 0;
  rows_ = rows;
  const ShopUnits& units = shown_units_;
  {
    const QSignalBlocker block(table_->selectionModel());
    table_->clearSelection();
    table_->setRowCount(0);
    table_->setRowCount(static_cast<int>(rows_.size()));
    for (int r = 0; r < table_->rowCount(); ++r) {
      const HistoryRow& h = rows_[r];
      QString cells[ColumnCount];
      cells[TimeColumn] = h.time;
      cells[ToolColumn] = h.tool;
      cells[MaterialColumn] = h.material;
      cells[MachineColumn] = h.machine.isEmpty() ? kNoMachine : h.machine;
      cells[SourceColumn] = h.source;
      for (int i = 0; i < std::min<int>(4, static_cast<int>(h.weights.size())); ++i)
        cells[WeightColumn0 + i] = fixed(h.weights[i], 3);
      cells[SpeedColumn] = fixed(h.speed_rpm, 0);
      cells[DepthColumn] = units.number(Quantity::Length, h.depth_mm);
      cells[FeedColumn] = units.number(Quantity::ChipLoad, h.feed_mm_per_tooth);
      cells[MrrColumn] = MonitoringPanel::formatNumber(shownMrr(h.mrr_cm3_s));
      cells[TolColumn] = MonitoringPanel::formatNumber(h.tol);
      cells[SurfColumn] = MonitoringPanel::formatNumber(h.surf);
      cells[RosColumn] = MonitoringPanel::formatNumber(h.ros);
      for (int c = 0; c < ColumnCount; ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
        if (c >= WeightColumn0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (c == 0) item->setData(Qt::UserRole, h.id);
        table_->setItem(r, c, item);
      }
    }
    if (had_selection) {
      const auto it = std::find_if(rows_.cbegin(), rows_.cend(),
                                   [selected_id](const HistoryRow& h) { return h.id == selected_id; });
      if (it != rows_.cend()) selectRow(static_cast<int>(it - rows_.cbegin()));
    }
  }
  updateButtons();
}

int HistoryView::selectedRow() const {
  const QModelIndexList rows = table_->selectionModel()->selectedRows();
  if (rows.isEmpty()) return -1;
  const int row = rows.first().row();
  return row < rows_.size() ? row : -1;
}

void HistoryView::selectRow(int row) {
  if (row < 0 || row >= table_->rowCount()) {
    table_->clearSelection();
  } else {
    table_->selectionModel()->select(table_->model()->index(row, 0),
                                     QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  }
  updateButtons();
}

void HistoryView::setStatus(const QString& text) {
  status_->setText(text);
}

void HistoryView::requestApply(int row) {
  if (row < 0 || row >= rows_.size() || rows_[row].weights.size() != 4) return;
  emit applyWeightsRequested(rows_[row].weights);
}

void HistoryView::updateButtons() {
  const int row = selectedRow();
  apply_->setEnabled(row >= 0 && rows_[row].weights.size() == 4);
}

}  // namespace mx::widgets
