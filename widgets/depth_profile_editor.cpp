#include "depth_profile_editor.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <set>

#include "indicator_gauge.h"

namespace mx::widgets {

namespace {
QString number(double v) {
  return QLocale::c().toString(v, 'g', 6);
}
}  // namespace

QString DepthProfileEditor::columnTitle(Column column) {
  return column == kLength ? tr("Length [mm]") : tr("Depth [mm]");
}

std::optional<double> DepthProfileEditor::parseCell(Column column, const QString& text, QString* reason) {
  const QString trimmed = text.trimmed();
  auto refuse = [&](const QString& why) -> std::optional<double> {
    if (reason) *reason = tr("%1 = %2: %3").arg(columnTitle(column), trimmed.isEmpty() ? tr("(empty)") : trimmed, why);
    return std::nullopt;
  };
  bool ok = false;
  double v = QLocale::c().toDouble(trimmed, &ok);
  if (!ok) v = QLocale().toDouble(trimmed, &ok);
  if (!ok || !std::isfinite(v)) return refuse(tr("not a number"));
  if (column == kLength && !(v > 0.0)) return refuse(tr("must be > 0"));
  if (column == kDepth && v < 0.0) return refuse(tr("must be >= 0"));
  return v;
}

DepthProfileEditor::DepthProfileEditor(QWidget* parent)
    : QWidget(parent),
      table_(new QTableWidget(0, 2, this)),
      add_(new QPushButton(tr("Add step"), this)),
      remove_(new QPushButton(tr("Remove step"), this)),
      summary_(new QLabel(this)),
      error_(new QLabel(this)) {
  table_->setObjectName(QStringLiteral("depthProfileTable"));
  table_->setHorizontalHeaderLabels({columnTitle(kLength), columnTitle(kDepth)});
  table_->horizontalHeaderItem(kLength)->setToolTip(tr("Length of tool path cut at this depth"));
  table_->horizontalHeaderItem(kDepth)->setToolTip(tr("Axial depth of cut b over this length (0: air cut)"));
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 8);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setMinimumHeight(5 * (table_->fontMetrics().height() + 8));
  table_->setToolTip(
      tr("Workpiece depth profile along the tool path; the tool position (the integral of the feed) "
         "decides the depth it sees."));
  add_->setObjectName(QStringLiteral("depthProfileAdd"));
  add_->setToolTip(tr("Insert a copy of the current step after it"));
  remove_->setObjectName(QStringLiteral("depthProfileRemove"));
  remove_->setToolTip(tr("Remove the selected steps (at least one step stays)"));
  error_->setObjectName(QStringLiteral("depthProfileError"));
  error_->setWordWrap(true);
  error_->setStyleSheet(QString("QLabel { color: %1; }").arg(IndicatorGauge::alarmColor().name()));
  error_->setVisible(false);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add_);
  buttons->addWidget(remove_);
  buttons->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(table_, 1);
  layout->addLayout(buttons);
  layout->addWidget(summary_);
  layout->addWidget(error_);

  connect(table_, &QTableWidget::itemChanged, this, &DepthProfileEditor::onItemChanged);
  connect(add_, &QPushButton::clicked, this, &DepthProfileEditor::addStep);
  connect(remove_, &QPushButton::clicked, this, &DepthProfileEditor::removeSteps);
  fillTable();
}

void DepthProfileEditor::setSteps(const QVector<DepthStepView>& steps) {
  steps_ = steps;
  setError({});
  fillTable();
}

void DepthProfileEditor::fillTable() {
  filling_ = true;
  table_->setRowCount(static_cast<int>(steps_.size()));
  for (int row = 0; row < table_->rowCount(); ++row) {
    const double values[] = {steps_[row].length_mm, steps_[row].depth_mm};
    for (int col = 0; col < 2; ++col) {
      auto* item = new QTableWidgetItem(number(values[col]));
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(row, col, item);
    }
  }
  filling_ = false;
  updateSummary();
}

void DepthProfileEditor::updateSummary() {
  double total = 0.0;
  int changes = 0;
  for (qsizetype i = 0; i < steps_.size(); ++i) {
    total += steps_[i].length_mm;
    if (i > 0 && steps_[i].depth_mm != steps_[i - 1].depth_mm) ++changes;
  }
  summary_->setText(steps_.isEmpty() ? tr("No depth profile: add a step.")
                                     : tr("Total length: %1 mm, %2 depth changes").arg(number(total)).arg(changes));
  remove_->setEnabled(steps_.size() > 1);
}

void DepthProfileEditor::onItemChanged(QTableWidgetItem* item) {
  if (filling_ || !item) return;
  const int row = item->row();
  if (row < 0 || row >= steps_.size()) return;
  const auto column = static_cast<Column>(item->column());
  double& target = column == kLength ? steps_[row].length_mm : steps_[row].depth_mm;
  QString reason;
  const std::optional<double> value = parseCell(column, item->text(), &reason);
  const bool changed = value && *value != target;
  if (value) target = *value;
  setError(value ? QString() : tr("Row %1: %2").arg(row + 1).arg(reason));
  // The cell shows the value kept: the new one, or the previous one when refused.
  filling_ = true;
  item->setText(number(target));
  filling_ = false;
  updateSummary();
  if (changed) emit stepsEdited(steps_);
}

void DepthProfileEditor::addStep() {
  const int current = table_->currentRow();
  const int at = current >= 0 && current < steps_.size() ? current : static_cast<int>(steps_.size()) - 1;
  const DepthStepView step = at >= 0 ? steps_[at] : DepthStepView{kDefaultLengthMm, kDefaultDepthMm};
  steps_.insert(at + 1, step);
  setError({});
  fillTable();
  table_->setCurrentCell(at + 1, kDepth);
  emit stepsEdited(steps_);
}

void DepthProfileEditor::removeSteps() {
  std::set<int> rows;
  for (const QModelIndex& index : table_->selectionModel()->selectedRows()) rows.insert(index.row());
  if (rows.empty() && table_->currentRow() >= 0) rows.insert(table_->currentRow());
  if (rows.empty() && !steps_.isEmpty()) rows.insert(static_cast<int>(steps_.size()) - 1);
  if (rows.empty()) return;
  if (static_cast<qsizetype>(rows.size()) >= steps_.size()) {
    setError(tr("Not removed: the profile needs at least one step."));
    return;
  }
  // From the last row up, so that the rows still to remove keep their index.
  std::for_each(rows.rbegin(), rows.rend(), [this](int row) { steps_.remove(row); });
  setError({});
  fillTable();
  emit stepsEdited(steps_);
}

void DepthProfileEditor::setError(const QString& text) {
  error_->setText(text);
  error_->setVisible(!text.isEmpty());
}

QString DepthProfileEditor::errorText() const {
  return error_->text();
}

QString DepthProfileEditor::summaryText() const {
  return summary_->text();
}

}  // namespace mx::widgets
