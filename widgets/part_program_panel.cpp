#include "part_program_panel.h"

#include <QAbstractTableModel>
#include <QCheckBox>
#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

#include "monitoring_panel.h"

namespace mx::widgets {

namespace {
constexpr int kSpacing = 8;
const QString kSame = QStringLiteral("=");
const QColor kFeedHighlight(255, 244, 168);   // light yellow
const QColor kSpeedHighlight(200, 236, 255);  // light blue
const QColor kReasonHighlight(255, 250, 214);

QString number(std::optional<double> v) {
  return v ? MonitoringPanel::formatNumber(v) : QString();
}

// The proposal column: "" with neither value, "=" when it keeps the programmed value (at the shown
// precision), else the new value. `changed` tells whether the cell is highlighted.
QString proposal(std::optional<double> original, std::optional<double> proposed, bool* changed) {
  *changed = false;
  if (!proposed) return original ? kSame : QString();
  QString text = number(proposed);
  if (original && number(original) == text) return kSame;
  *changed = true;
  return text;
}

struct ColumnSpec {
  const char* title;  // %1: the shop unit of feed, %2 of length, %3 of force
  const char* tip;
};
constexpr ColumnSpec kColumns[PartProgramPanel::kColumnCount] = {
    {"Line", "Line number in the program file (1-based)"},
    {"Block", "The block as written in the program"},
    {"F [%1]", "Programmed feed F of the block [%1] (converted from the program's unit)"},
    {"F new [%1]",
     "Proposed feed F [%1] in effect at the block; \"=\" keeps the programmed value; highlighted when changed; "
     "italic where a block without its own F inherits the F proposed on an earlier line (modal)"},
    {"S [rpm]", "Programmed spindle speed S [rpm]"},
    {"S new [rpm]",
     "Proposed spindle speed S [rpm] in effect at the block; \"=\" keeps the programmed value; highlighted when "
     "changed; italic where inherited from an earlier line (modal)"},
    {"Depth [%2]", "Axial depth of cut of the block [%2]"},
    {"Predicted force [%3]", "Predicted peak cutting force of the block with the proposed F and S [%3]"},
    {"Reason", "Why F or S was changed; empty when unchanged"},
};

// The shown values: feeds from the program's unit, depth and force from mm and N, into shop units.
struct CellUnits {
  ShopUnits units;
  double program_feed_to_mm_min = 1.0;
  std::optional<double> feed(std::optional<double> v) const {
    return v ? std::optional<double>(units.fromBase(Quantity::Feed, *v * program_feed_to_mm_min)) : std::nullopt;
  }
  std::optional<double> shown(Quantity q, std::optional<double> v) const {
    return v ? std::optional<double>(units.fromBase(q, *v)) : std::nullopt;
  }
};

// The line whose proposal a modal cell inherits (PartProgramRow::new_feed_from_line); 0 for any other cell.
int inheritedFrom(const PartProgramRow& r, int column) {
  if (column == PartProgramPanel::kNewFeed) return r.new_feed_from_line;
  return column == PartProgramPanel::kNewSpeed ? r.new_speed_from_line : 0;
}

QFont italicFont() {
  QFont f;
  f.setItalic(true);
  return f;
}

QString cellText(const PartProgramRow& r, int column, const CellUnits& u, bool* changed) {
  *changed = false;
  if (column == PartProgramPanel::kLine) return QString::number(r.line);
  if (column == PartProgramPanel::kBlock) return r.text;
  if (column == PartProgramPanel::kNewFeed) return proposal(u.feed(r.original_feed), u.feed(r.new_feed), changed);
  if (column == PartProgramPanel::kNewSpeed) return proposal(r.speed_rpm, r.new_speed_rpm, changed);
  *changed = column == PartProgramPanel::kReason && r.changed && !r.reason.isEmpty();
  if (column == PartProgramPanel::kReason) return r.reason;
  const std::optional<double> plain[] = {{},
                                         {},
                                         u.feed(r.original_feed),
                                         {},
                                         r.speed_rpm,
                                         {},
                                         u.shown(Quantity::Length, r.depth_mm),
                                         u.shown(Quantity::Force, r.predicted_force_n)};
  return column >= 0 && column < PartProgramPanel::kReason ? number(plain[column]) : QString();
}

QFont boldFont() {
  QFont f;
  f.setBold(true);
  return f;
}
}  // namespace

// Serves the rows on demand; with the changed-only filter, `visible_` maps view rows to rows.
class PartProgramTableModel : public QAbstractTableModel {
 public:
  using QAbstractTableModel::QAbstractTableModel;

  void setRows(const QVector<PartProgramRow>& rows, const QString& feed_unit) {
    beginResetModel();
    rows_ = rows;
    units_.program_feed_to_mm_min = feed_unit == QLatin1String("in/min") ? 25.4 : 1.0;
    rebuildFilter();
    endResetModel();
    emit headerDataChanged(Qt::Horizontal, 0, PartProgramPanel::kColumnCount - 1);
  }
  void setShopUnits(const ShopUnits& units) {
    units_.units = units;
    emit headerDataChanged(Qt::Horizontal, 0, PartProgramPanel::kColumnCount - 1);
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, PartProgramPanel::kColumnCount - 1));
  }
  void setChangedOnly(bool on) {
    if (on == changed_only_) return;
    beginResetModel();
    changed_only_ = on;
    rebuildFilter();
    endResetModel();
  }
  bool changedOnly() const { return changed_only_; }
  const QVector<PartProgramRow>& rows() const { return rows_; }
  int sourceRow(int view_row) const { return changed_only_ ? visible_.value(view_row, -1) : view_row; }
  int viewRow(int source_row) const {
    if (!changed_only_) return source_row;
    const auto it = std::lower_bound(visible_.begin(), visible_.end(), source_row);
    return it != visible_.end() && *it == source_row ? static_cast<int>(it - visible_.begin()) : -1;
  }
  // Index of the block of `line` in rows(), -1 when none (rows are normally in line order).
  int findLine(int line) const {
    const auto it =
        std::lower_bound(rows_.begin(), rows_.end(), line, [](const PartProgramRow& r, int l) { return r.line < l; });
    if (it != rows_.end() && it->line == line) return static_cast<int>(it - rows_.begin());
    for (int i = 0; i < rows_.size(); ++i)
      if (rows_[i].line == line) return i;
    return -1;
  }

  int rowCount(const QModelIndex& parent = {}) const override {
    if (parent.isValid()) return 0;
    return static_cast<int>(changed_only_ ? visible_.size() : rows_.size());
  }
  int columnCount(const QModelIndex& parent = {}) const override {
    return parent.isValid() ? 0 : PartProgramPanel::kColumnCount;
  }
  Qt::ItemFlags flags(const QModelIndex& index) const override {
    return index.isValid() ? Qt::ItemIsSelectable | Qt::ItemIsEnabled : Qt::NoItemFlags;
  }

  QVariant data(const QModelIndex& index, int role) const override {
    const int source = index.isValid() ? sourceRow(index.row()) : -1;
    if (source < 0 || source >= rows_.size()) return {};
    const PartProgramRow& r = rows_[source];
    const int column = index.column();
    const bool text_column = column == PartProgramPanel::kBlock || column == PartProgramPanel::kReason;
    bool changed = false;
    const QString text = cellText(r, column, units_, &changed);
    switch (role) {
      case Qt::DisplayRole:
        return text;
      case Qt::ToolTipRole:
        if (const int from = inheritedFrom(r, column); from > 0)
          return PartProgramPanel::tr("Modal: the value proposed at line %1 stays in effect here").arg(from);
        return text_column && !text.isEmpty() ? QVariant(text) : QVariant();
      case Qt::BackgroundRole:
        if (!changed) return {};
        if (column == PartProgramPanel::kNewFeed) return kFeedHighlight;
        return column == PartProgramPanel::kNewSpeed ? kSpeedHighlight : kReasonHighlight;
      case Qt::FontRole:
        if (column == PartProgramPanel::kBlock) return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        if (inheritedFrom(r, column) > 0) return italicFont();
        return changed && column != PartProgramPanel::kReason ? QVariant(boldFont()) : QVariant();
      case Qt::TextAlignmentRole:
        return QVariant(text_column ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
      default:
        return {};
    }
  }

  QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
    if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
    if (section < 0 || section >= PartProgramPanel::kColumnCount) return {};
    const char* source = role == Qt::DisplayRole   ? kColumns[section].title
                         : role == Qt::ToolTipRole ? kColumns[section].tip
                                                   : nullptr;
    if (!source) return {};
    const QString text = PartProgramPanel::tr(source);
    const ShopUnits& u = units_.units;
    if (text.contains(QLatin1String("%1"))) return text.arg(u.symbol(Quantity::Feed));
    if (text.contains(QLatin1String("%2"))) return text.arg(u.symbol(Quantity::Length));
    return text.contains(QLatin1String("%3")) ? text.arg(u.symbol(Quantity::Force)) : text;
  }

 private:
  void rebuildFilter() {
    visible_.clear();
    if (!changed_only_) return;
    for (int i = 0; i < rows_.size(); ++i)
      if (rows_[i].changed) visible_.push_back(i);
  }

  QVector<PartProgramRow> rows_;
  QVector<int> visible_;
  CellUnits units_;
  bool changed_only_ = false;
};

QColor PartProgramPanel::highlightColor() {
  return kFeedHighlight;
}

PartProgramPanel::PartProgramPanel(QWidget* parent)
    : QWidget(parent),
      model_(new PartProgramTableModel(this)),
      table_(new QTableView(this)),
      warnings_(new QListWidget(this)),
      header_label_(new QLabel(this)),
      warnings_label_(new QLabel(this)),
      status_label_(new QLabel(this)),
      changed_only_box_(new QCheckBox(tr("Show changed blocks only"), this)),
      open_button_(new QPushButton(tr("Open program..."), this)),
      export_program_button_(new QPushButton(tr("Export program..."), this)),
      export_csv_button_(new QPushButton(tr("Export CSV..."), this)),
      export_afc_button_(new QPushButton(tr("Export AFC table..."), this)),
      dialect_box_(new QComboBox(this)) {
  setToolTip(
      tr("Part-program override: the programmed feed F and speed S of each block beside the proposed "
         "ones, the reason and the predicted cutting force."));
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(kSpacing, kSpacing, kSpacing, kSpacing);
  outer->setSpacing(kSpacing);

  auto* buttons = new QHBoxLayout;
  open_button_->setObjectName(QStringLiteral("partProgramOpen"));
  open_button_->setToolTip(tr("Open an NC part program (G-code) and compute the proposed F and S per block."));
  export_program_button_->setObjectName(QStringLiteral("partProgramExportProgram"));
  export_program_button_->setToolTip(tr("Write the program with the proposed F and S."));
  export_csv_button_->setObjectName(QStringLiteral("partProgramExportCsv"));
  export_csv_button_->setToolTip(tr("Write the table (one row per block, units in the header) as CSV."));
  export_afc_button_->setObjectName(QStringLiteral("partProgramExportAfc"));
  export_afc_button_->setToolTip(
      tr("Heidenhain programs: write the AFC.TAB row (adaptive feed control) for the tool, taught at the project's "
         "operating point; its reference power AFC-LOAD is shown below."));
  dialect_box_->setObjectName(QStringLiteral("partProgramDialect"));
  dialect_box_->addItem(tr("Detect"), QString());
  dialect_box_->addItem(tr("ISO / Fanuc"), QStringLiteral("iso"));
  dialect_box_->addItem(tr("Heidenhain Klartext"), QStringLiteral("heidenhain"));
  dialect_box_->addItem(tr("Siemens Sinumerik"), QStringLiteral("sinumerik"));
  dialect_box_->addItem(tr("LinuxCNC"), QStringLiteral("linuxcnc"));
  dialect_box_->setToolTip(
      tr("The controller dialect the program is written in; the optimised program is written in the same one. "
         "Detect: from the program's own syntax (BEGIN PGM, CYCLE...(), #<name>, ...)."));
  auto* dialect_label = new QLabel(tr("Dialect:"), this);
  dialect_label->setBuddy(dialect_box_);
  changed_only_box_->setObjectName(QStringLiteral("partProgramChangedOnly"));
  changed_only_box_->setToolTip(tr("Hide the blocks whose F and S are kept."));
  buttons->addWidget(open_button_);
  buttons->addWidget(export_program_button_);
  buttons->addWidget(export_csv_button_);
  buttons->addWidget(export_afc_button_);
  buttons->addSpacing(2 * kSpacing);
  buttons->addWidget(dialect_label);
  buttons->addWidget(dialect_box_);
  buttons->addSpacing(2 * kSpacing);
  buttons->addWidget(changed_only_box_);
  buttons->addStretch(1);
  outer->addLayout(buttons);

  header_label_->setObjectName(QStringLiteral("partProgramHeader"));
  header_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  header_label_->setWordWrap(true);
  header_label_->setToolTip(tr("The program file, the controller dialect and how many blocks get a new F or S."));
  outer->addWidget(header_label_);

  table_->setObjectName(QStringLiteral("partProgramTable"));
  table_->setModel(model_);
  table_->setToolTip(
      tr("Blocks of the program; highlighted: the proposed changes. Double-click a block to go to "
         "its line."));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setAlternatingRowColors(true);
  table_->setWordWrap(false);
  table_->verticalHeader()->hide();
  // Fixed row heights and no ResizeToContents: both would visit every row of a large program.
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
  QHeaderView* h = table_->horizontalHeader();
  h->setSectionResizeMode(QHeaderView::Interactive);
  h->setStretchLastSection(true);
  resizeColumns();
  connect(table_, &QTableView::doubleClicked, this, [this](const QModelIndex& index) {
    const int source = model_->sourceRow(index.row());
    if (source >= 0) emit lineActivated(model_->rows()[source].line);
  });

  warnings_label_->setObjectName(QStringLiteral("partProgramWarningsLabel"));
  warnings_->setObjectName(QStringLiteral("partProgramWarnings"));
  warnings_->setToolTip(tr("Parser warnings; double-click one to go to its block."));
  connect(warnings_, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
    const int line = item->data(Qt::UserRole).toInt();
    selectLine(line);
    emit lineActivated(line);
  });
  auto* warning_box = new QWidget(this);
  auto* warning_layout = new QVBoxLayout(warning_box);
  warning_layout->setContentsMargins(0, 0, 0, 0);
  warning_layout->addWidget(warnings_label_);
  warning_layout->addWidget(warnings_);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(table_);
  splitter->addWidget(warning_box);
  splitter->setStretchFactor(0, 4);
  splitter->setStretchFactor(1, 1);
  outer->addWidget(splitter, 1);

  status_label_->setObjectName(QStringLiteral("partProgramStatus"));
  status_label_->setWordWrap(true);
  outer->addWidget(status_label_);

  connect(open_button_, &QPushButton::clicked, this, &PartProgramPanel::openRequested);
  connect(export_program_button_, &QPushButton::clicked, this, &PartProgramPanel::exportProgramRequested);
  connect(export_csv_button_, &QPushButton::clicked, this, &PartProgramPanel::exportCsvRequested);
  connect(export_afc_button_, &QPushButton::clicked, this, &PartProgramPanel::exportAfcRequested);
  connect(dialect_box_, &QComboBox::currentIndexChanged, this, [this] { emit dialectChanged(dialectChoice()); });
  connect(changed_only_box_, &QCheckBox::toggled, this, [this](bool on) { model_->setChangedOnly(on); });
  clear();
}

PartProgramPanel::~PartProgramPanel() = default;

void PartProgramPanel::setUnits(DisplayUnits* units) {
  const auto apply = [this] {
    model_->setShopUnits(DisplayUnits::of(units_));
    resizeColumns();
  };
  followUnits(this, units_, units, apply);
}

void PartProgramPanel::setProgram(const QString& path, const QVector<PartProgramRow>& rows,
                                  const QVector<PartProgramWarningView>& warnings, const QString& feed_unit,
                                  const QString& controller) {
  setUpdatesEnabled(false);
  path_ = path;
  controller_ = controller;
  feed_unit_ = feed_unit.isEmpty() ? QStringLiteral("mm/min") : feed_unit;
  changed_count_ =
      static_cast<int>(std::count_if(rows.begin(), rows.end(), [](const PartProgramRow& r) { return r.changed; }));
  has_program_ = true;
  model_->setRows(rows, feed_unit_);
  resizeColumns();

  warnings_->clear();
  for (const PartProgramWarningView& w : warnings) {
    auto* item = new QListWidgetItem(
        tr("line %1, column %2: %3 \u2014 %4").arg(w.line).arg(w.column).arg(w.text, w.message), warnings_);
    item->setData(Qt::UserRole, w.line);
    item->setToolTip(w.message);
  }
  warnings_label_->setText(tr("Warnings: %1").arg(warnings.size()));
  export_program_button_->setEnabled(true);
  export_csv_button_->setEnabled(true);
  updateHeader();
  setUpdatesEnabled(true);
}

void PartProgramPanel::clear() {
  path_.clear();
  controller_.clear();
  changed_count_ = 0;
  has_program_ = false;
  model_->setRows({}, feed_unit_);
  warnings_->clear();
  warnings_label_->setText(tr("Warnings: 0"));
  export_program_button_->setEnabled(false);
  export_csv_button_->setEnabled(false);
  export_afc_button_->setEnabled(false);
  dialect_.clear();
  status_label_->clear();
  updateHeader();
}

// From the header texts only (visiting the cells of a large program would take seconds).
void PartProgramPanel::resizeColumns() {
  QHeaderView* h = table_->horizontalHeader();
  const int em = table_->fontMetrics().horizontalAdvance(QLatin1Char('M'));
  const int minimum[] = {4 * em, 24 * em, 5 * em, 5 * em, 5 * em, 5 * em, 5 * em, 6 * em};
  for (int c = 0; c < kReason; ++c) h->resizeSection(c, std::max(minimum[c], h->sectionSizeHint(c) + em));
}

void PartProgramPanel::updateHeader() {
  if (!has_program_) {
    header_label_->setText(tr("No program: open one to see the proposed feeds and speeds."));
    return;
  }
  const QString file = dialect_.isEmpty() ? path_ : tr("%1 \u2014 %2").arg(path_, dialect_);
  header_label_->setText(tr("%1 \u2014 controller: %2 \u2014 %3 of %4 blocks changed")
                             .arg(file, controller_.isEmpty() ? tr("\u2013") : controller_)
                             .arg(changed_count_)
                             .arg(model_->rows().size()));
}

QString PartProgramPanel::dialectChoice() const {
  return dialect_box_->currentData().toString();
}

void PartProgramPanel::setDialectChoice(const QString& name) {
  const int index = dialect_box_->findData(name);
  if (index >= 0) dialect_box_->setCurrentIndex(index);
}

void PartProgramPanel::setDialect(const QString& description, bool afc) {
  dialect_ = description;
  export_afc_button_->setEnabled(has_program_ && afc);
  updateHeader();
}

void PartProgramPanel::setStatus(const QString& text) {
  status_label_->setText(text);
}

const QVector<PartProgramRow>& PartProgramPanel::rows() const {
  return model_->rows();
}

void PartProgramPanel::setShowChangedOnly(bool on) {
  changed_only_box_->setChecked(on);  // toggled() filters
}

bool PartProgramPanel::showChangedOnly() const {
  return model_->changedOnly();
}

bool PartProgramPanel::selectLine(int line) {
  const int source = model_->findLine(line);
  if (source < 0) return false;
  if (model_->viewRow(source) < 0) setShowChangedOnly(false);
  const QModelIndex index = model_->index(model_->viewRow(source), 0);
  table_->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  table_->scrollTo(index, QAbstractItemView::PositionAtCenter);
  return true;
}

int PartProgramPanel::selectedLine() const {
  const QModelIndexList selected = table_->selectionModel()->selectedRows();
  if (selected.isEmpty()) return 0;
  const int source = model_->sourceRow(selected.front().row());
  return source >= 0 ? model_->rows()[source].line : 0;
}

int PartProgramPanel::visibleRowCount() const {
  return model_->rowCount();
}

QString PartProgramPanel::headerText() const {
  return header_label_->text();
}

QString PartProgramPanel::statusText() const {
  return status_label_->text();
}

}  // namespace mx::widgets
