#include "tool_import_dialog.h"

#include <QAbstractTableModel>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTableView>
#include <QVBoxLayout>

#include "count_text.h"
#include "document/project_rules.h"

namespace mx::widgets {

namespace {

enum Column { kId, kType, kDiameter, kTeeth, kFluteLength, kStickout, kPresets, kDynamics, kColumns };

// Whether the tool brings MillExpert data (modes or a tap test) or imports rigid.
QString dynamicsText(const app::ToolSpec& t) {
  if (t.hasFrf()) return QObject::tr("tap test");
  const std::size_t modes = t.modes_x.size() + t.modes_y.size();
  return modes == 0 ? QObject::tr("none (rigid)") : countText(qsizetype(modes), "mode", "modes");
}

}  // namespace

// The file's tools, one row each, the first column checkable; rows are made only when shown, so a
// library of thousands opens at once.
class ToolImportDialog::Model : public QAbstractTableModel {
 public:
  Model(const std::vector<app::ToolSpec>& tools, const DisplayUnits* units, QObject* parent)
      : QAbstractTableModel(parent), tools_(tools), checked_(tools.size(), true), units_(units) {}

  int rowCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : int(tools_.size()); }
  int columnCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : kColumns; }

  QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    const QString unit = units_ ? units_->lengthSuffix() : QStringLiteral("mm");
    switch (section) {
      case kId:
        return tr("Tool");
      case kType:
        return tr("Type");
      case kDiameter:
        return tr("D [%1]").arg(unit);
      case kTeeth:
        return tr("Teeth");
      case kFluteLength:
        return tr("Flute length [%1]").arg(unit);
      case kStickout:
        return tr("Stickout [%1]").arg(unit);
      case kPresets:
        return tr("Presets");
      case kDynamics:
        return tr("Dynamics");
      default:
        return {};
    }
  }

  QVariant data(const QModelIndex& index, int role) const override {
    const app::ToolSpec& t = tools_[std::size_t(index.row())];
    if (role == Qt::CheckStateRole && index.column() == kId)
      return checked_[std::size_t(index.row())] ? Qt::Checked : Qt::Unchecked;
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
      case kId:
        return t.id;
      case kType:
        return t.type.value_or(QStringLiteral("–"));
      case kDiameter:
        return length(t.diameter_mm);
      case kTeeth:
        return t.teeth;
      case kFluteLength:
        return length(t.flute_length_mm);
      case kStickout:
        return length(t.stickout_mm);
      case kPresets:
        return qlonglong(t.cutting_data.size());
      case kDynamics:
        return dynamicsText(t);
      default:
        return {};
    }
  }

  Qt::ItemFlags flags(const QModelIndex& index) const override {
    const Qt::ItemFlags base = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    return index.column() == kId ? base | Qt::ItemIsUserCheckable : base;
  }

  bool setData(const QModelIndex& index, const QVariant& value, int role) override {
    if (role != Qt::CheckStateRole || index.column() != kId) return false;
    checked_[std::size_t(index.row())] = value.toInt() == Qt::Checked;
    emit dataChanged(index, index, {Qt::CheckStateRole});
    return true;
  }

  void setAll(bool checked) {
    std::fill(checked_.begin(), checked_.end(), checked);
    if (!tools_.empty()) emit dataChanged(index(0, kId), index(rowCount() - 1, kId), {Qt::CheckStateRole});
  }

  QStringList selectedIds() const {
    QStringList ids;
    for (std::size_t i = 0; i < tools_.size(); ++i)
      if (checked_[i]) ids << tools_[i].id;
    return ids;
  }

  int rowOf(const QString& id) const {
    for (std::size_t i = 0; i < tools_.size(); ++i)
      if (tools_[i].id == id) return int(i);
    return -1;
  }

 private:
  QString length(const std::optional<double>& mm) const {
    if (!mm) return QStringLiteral("–");
    return units_ ? QString::number(units_->fromMm(*mm), 'f', units_->lengthDecimals() - 1) : QString::number(*mm);
  }

  const std::vector<app::ToolSpec> tools_;
  std::vector<bool> checked_;
  const DisplayUnits* units_;
};

ToolImportDialog::ToolImportDialog(const QString& fileName, const std::vector<app::ToolSpec>& tools,
                                   const QStringList& skipped, int projectTools, const DisplayUnits* units,
                                   QWidget* parent)
    : QDialog(parent),
      model_(new Model(tools, units, this)),
      table_(new QTableView(this)),
      summary_(new QLabel(this)),
      append_(new QRadioButton(tr("Add to the project's tools (an id it already has gets a suffix: T7-2)"), this)),
      replace_(new QRadioButton(tr("Replace the project's tools"), this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)),
      project_tools_(projectTools) {
  setObjectName("toolImportDialog");
  setWindowTitle(tr("Import tools from %1").arg(fileName));
  table_->setModel(model_);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setMinimumSize(1100, 360);
  auto* all = new QPushButton(tr("Select all"), this);
  auto* none = new QPushButton(tr("Select none"), this);
  connect(all, &QPushButton::clicked, this, [this] { setAllChecked(true); });
  connect(none, &QPushButton::clicked, this, [this] { setAllChecked(false); });
  (projectTools > 0 ? append_ : replace_)->setChecked(true);
  append_->setEnabled(projectTools > 0);
  connect(append_, &QRadioButton::toggled, this, &ToolImportDialog::updateSummary);
  connect(model_, &QAbstractItemModel::dataChanged, this, &ToolImportDialog::updateSummary);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(table_, 1);
  auto* selection = new QHBoxLayout;
  selection->addWidget(all);
  selection->addWidget(none);
  selection->addWidget(summary_, 1);
  layout->addLayout(selection);
  if (!skipped.isEmpty()) {
    layout->addWidget(new QLabel(
        tr("Left out: %1 that are not milling cutters").arg(countText(skipped.size(), "tool", "tools")), this));
    auto* list = new QPlainTextEdit(skipped.join('\n'), this);
    list->setReadOnly(true);
    list->setMaximumHeight(90);
    layout->addWidget(list);
  }
  layout->addWidget(append_);
  layout->addWidget(replace_);
  layout->addWidget(buttons_);
  if (int(tools.size()) + (projectTools > 0 ? projectTools : 0) > app::rules::kMaxTools) setAllChecked(false);
  updateSummary();
}

QStringList ToolImportDialog::selectedIds() const {
  return model_->selectedIds();
}

bool ToolImportDialog::replace() const {
  return replace_->isChecked();
}

void ToolImportDialog::setAllChecked(bool checked) {
  model_->setAll(checked);
}

void ToolImportDialog::setChecked(const QString& id, bool checked) {
  const int row = model_->rowOf(id);
  if (row >= 0) model_->setData(model_->index(row, kId), checked ? Qt::Checked : Qt::Unchecked, Qt::CheckStateRole);
}

void ToolImportDialog::updateSummary() {
  const qsizetype selected = selectedIds().size();
  const qsizetype total = selected + (replace() ? 0 : project_tools_);
  const bool fits = total <= app::rules::kMaxTools;
  const QString count = tr("%1 of %2 tools selected").arg(selected).arg(model_->rowCount());
  summary_->setText(fits ? count
                         : tr("%1: the project would hold %2 tools, more than its limit of %3")
                               .arg(count)
                               .arg(total)
                               .arg(app::rules::kMaxTools));
  summary_->setStyleSheet(fits ? QString() : QStringLiteral("color: #b00020"));
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(selected > 0 && fits);
}

}  // namespace mx::widgets
