#include "lobe_tool_panel.h"

#include <QCheckBox>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

#include "section_heading.h"

namespace mx::widgets {

namespace {
const QString kCursorHint = QObject::tr("Move the mouse over the chart to read the limit b_lim there.");
}  // namespace

LobeToolPanel::LobeToolPanel(QWidget* parent)
    : QWidget(parent),
      active_only_(new QCheckBox(tr("Active tool only"), this)),
      tools_(new QListWidget(this)),
      pockets_title_(sectionHeading(tr("Stability pockets"), this)),
      pockets_(new QListWidget(this)),
      cursor_(new QLabel(kCursorHint, this)) {
  setObjectName("lobeToolPanel");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(sectionHeading(tr("Tools on the chart"), this));
  active_only_->setObjectName("activeToolOnly");
  active_only_->setToolTip(tr("Show the lobes of the active tool alone"));
  layout->addWidget(active_only_);
  tools_->setObjectName("lobeToolList");
  tools_->setIconSize(QSize(44, 14));
  tools_->setToolTip(
      tr("Solid: nominal lobe (\u03b4 = 0, \u03b1 = 1); dashed: margined lobe (Rule 1); dotted: measured FRF. "
         "Tick to show a tool, click to make it the active tool."));
  layout->addWidget(tools_, 3);
  layout->addWidget(pockets_title_);
  pockets_->setObjectName("pocketList");
  pockets_->setToolTip(
      tr("Peaks of the active tool's margined lobe, deepest first; click one to move the point there"));
  layout->addWidget(pockets_, 2);
  cursor_->setObjectName("cursorLimit");
  cursor_->setWordWrap(true);
  cursor_->setMinimumHeight(3 * fontMetrics().height());
  cursor_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  layout->addWidget(cursor_);
  setMinimumWidth(200);
  setMaximumWidth(260);
  connect(active_only_, &QCheckBox::toggled, this, &LobeToolPanel::activeToolOnlyToggled);
  connect(tools_, &QListWidget::itemChanged, this, &LobeToolPanel::onToolItemChanged);
  connect(tools_, &QListWidget::itemClicked, this,
          [this](QListWidgetItem* item) { emit toolClicked(tools_->row(item)); });
  connect(pockets_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
    const int row = pockets_->row(item);
    if (row >= 0 && row < shown_pockets_.size())
      emit pocketChosen(shown_pockets_[row].speed_rpm, shown_pockets_[row].depth_mm);
  });
}

void LobeToolPanel::setTools(const QVector<LobeToolEntry>& tools) {
  filling_ = true;
  tools_->clear();
  for (const LobeToolEntry& t : tools) {
    auto* item = new QListWidgetItem(t.swatch, t.id, tools_);
    item->setToolTip(t.tooltip);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
    item->setCheckState(t.visible ? Qt::Checked : Qt::Unchecked);
  }
  filling_ = false;
}

void LobeToolPanel::setToolVisible(int index, bool visible) {
  QListWidgetItem* item = tools_->item(index);
  if (!item) return;
  filling_ = true;
  item->setCheckState(visible ? Qt::Checked : Qt::Unchecked);
  filling_ = false;
}

void LobeToolPanel::setActiveTool(int index) {
  for (int i = 0; i < tools_->count(); ++i) {
    QFont f = tools_->item(i)->font();
    f.setBold(i == index);
    tools_->item(i)->setFont(f);
  }
  if (QListWidgetItem* item = tools_->item(index)) {
    tools_->setCurrentItem(item, QItemSelectionModel::ClearAndSelect);
    tools_->scrollToItem(item);
  }
}

bool LobeToolPanel::activeToolOnly() const {
  return active_only_->isChecked();
}

void LobeToolPanel::onToolItemChanged(QListWidgetItem* item) {
  if (!filling_) emit toolVisibilityToggled(tools_->row(item), item->checkState() == Qt::Checked);
}

void LobeToolPanel::setPockets(const QString& tool, const QVector<StabilityPocket>& pockets, double display_per_mm,
                               const QString& unit) {
  shown_pockets_ = pockets.mid(0, kMaxPockets);
  pockets_title_->setText(tool.isEmpty() ? tr("Stability pockets") : tr("Stability pockets of %1").arg(tool));
  pockets_->clear();
  const int decimals = display_per_mm == 1.0 ? 2 : 4;
  for (int i = 0; i < shown_pockets_.size(); ++i) {
    const StabilityPocket& p = shown_pockets_[i];
    const QString where =
        tr("%1 rpm, %2 %3").arg(p.speed_rpm, 0, 'f', 0).arg(p.depth_mm * display_per_mm, 0, 'f', decimals).arg(unit);
    pockets_->addItem(i == 0 ? tr("best: %1").arg(where) : where);
  }
  if (shown_pockets_.isEmpty()) {
    auto* none = new QListWidgetItem(tr("none in the computed speed range"), pockets_);
    none->setFlags(Qt::NoItemFlags);
  }
}

void LobeToolPanel::setCursorText(const QString& text) {
  cursor_->setText(text.isEmpty() ? kCursorHint : text);
}

QString LobeToolPanel::cursorText() const {
  return cursor_->text();
}

}  // namespace mx::widgets
