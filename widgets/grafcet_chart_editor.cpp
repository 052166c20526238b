#include "grafcet_chart_editor.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "grafcet_chart_view.h"

namespace mx::widgets {

namespace {
constexpr int kStepRole = Qt::UserRole + 1, kTransitionRole = Qt::UserRole + 2;

QString idList(const QList<int>& ids) {
  QStringList parts;
  for (int id : ids) parts << QString::number(id);
  return parts.join(QStringLiteral(", "));
}

QStringList tokens(const QString& text) {
  return text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
}

QTableWidget* makeTable(const QStringList& headers, QWidget* parent) {
  auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
  table->setHorizontalHeaderLabels(headers);
  table->verticalHeader()->setVisible(false);
  table->setSelectionBehavior(QAbstractItemView::SelectRows);
  table->setSelectionMode(QAbstractItemView::SingleSelection);
  table->horizontalHeader()->setStretchLastSection(true);
  table->setMinimumHeight(80);
  return table;
}

QPushButton* button(const QString& text, const QString& tip, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setToolTip(tip);
  return b;
}

QWidget* tableGroup(const QString& title, QTableWidget* table, QPushButton* add, QPushButton* remove, QWidget* parent) {
  auto* box = new QGroupBox(title, parent);
  auto* layout = new QVBoxLayout(box);
  layout->addWidget(table);
  auto* row = new QHBoxLayout;
  row->addWidget(add);
  row->addWidget(remove);
  row->addStretch(1);
  layout->addLayout(row);
  return box;
}
}  // namespace

GrafcetChartEditor::GrafcetChartEditor(QWidget* parent)
    : QWidget(parent),
      name_(new QLineEdit(this)),
      steps_(makeTable({tr("Step"), tr("Name"), tr("Initial"), tr("Actions (A = level, L* = impulse)")}, this)),
      transitions_(
          makeTable({tr("Transition"), tr("From steps"), tr("To steps"), tr("Receptivity"), tr("Priority")}, this)),
      add_step_(button(tr("Add step"), tr("Append a step with the next free number"), this)),
      remove_step_(button(tr("Remove step"), tr("Remove the selected step and its arcs"), this)),
      add_transition_(button(tr("Add transition"), tr("Append a transition leaving the selected step"), this)),
      remove_transition_(button(tr("Remove transition"), tr("Remove the selected transition"), this)),
      verdict_(new QLabel(this)),
      issue_list_(new QListWidget(this)),
      view_(new GrafcetChartView(this)) {
  setObjectName(QStringLiteral("grafcetChartEditor"));
  name_->setPlaceholderText(tr("Chart name"));
  transitions_->setToolTip(
      tr("Receptivity: signals with and, or, not, parentheses and comparisons, e.g. "
         "\"b and not a\"; \"1\" is always true. Priority 1 is checked first."));
  issue_list_->setObjectName(QStringLiteral("grafcetIssueList"));
  issue_list_->setMaximumHeight(130);
  issue_list_->setToolTip(tr("Click an issue to select its element"));

  auto* left = new QWidget(this);
  auto* left_layout = new QVBoxLayout(left);
  left_layout->setContentsMargins(0, 0, 0, 0);
  auto* name_row = new QHBoxLayout;
  name_row->addWidget(new QLabel(tr("Chart:"), left));
  name_row->addWidget(name_, 1);
  left_layout->addLayout(name_row);
  left_layout->addWidget(tableGroup(tr("Steps"), steps_, add_step_, remove_step_, left), 1);
  left_layout->addWidget(tableGroup(tr("Transitions"), transitions_, add_transition_, remove_transition_, left), 1);
  auto* issues_box = new QGroupBox(tr("Validation"), left);
  auto* issues_layout = new QVBoxLayout(issues_box);
  issues_layout->addWidget(verdict_);
  issues_layout->addWidget(issue_list_);
  left_layout->addWidget(issues_box);

  auto* scroll = new QScrollArea(this);
  scroll->setWidget(view_);
  scroll->setWidgetResizable(true);
  scroll->setBackgroundRole(QPalette::Base);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(left);
  split->addWidget(scroll);
  split->setStretchFactor(0, 2);
  split->setStretchFactor(1, 3);
  split->setChildrenCollapsible(false);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(split);

  connect(steps_, &QTableWidget::itemChanged, this, [this] { edited(); });
  connect(transitions_, &QTableWidget::itemChanged, this, [this] { edited(); });
  connect(name_, &QLineEdit::editingFinished, this, [this] {
    if (name_->text() != chart_.name) edited();
  });
  connect(add_step_, &QPushButton::clicked, this, &GrafcetChartEditor::addStep);
  connect(remove_step_, &QPushButton::clicked, this, &GrafcetChartEditor::removeStep);
  connect(add_transition_, &QPushButton::clicked, this, &GrafcetChartEditor::addTransition);
  connect(remove_transition_, &QPushButton::clicked, this, &GrafcetChartEditor::removeTransition);
  connect(issue_list_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
    selectElement(item->data(kStepRole).toInt(), item->data(kTransitionRole).toInt());
  });
  connect(view_, &GrafcetChartView::stepClicked, this, [this](int id) { selectElement(id, -1); });
  connect(view_, &GrafcetChartView::transitionClicked, this, [this](int id) { selectElement(-1, id); });
  connect(steps_, &QTableWidget::currentCellChanged, this, [this](int row) {
    if (!populating_ && row >= 0 && steps_->item(row, StepId))
      view_->setSelected(steps_->item(row, StepId)->text().toInt(), -1);
  });
  connect(transitions_, &QTableWidget::currentCellChanged, this, [this](int row) {
    if (!populating_ && row >= 0 && transitions_->item(row, TransitionId))
      view_->setSelected(-1, transitions_->item(row, TransitionId)->text().toInt());
  });
  setChart({});
}

void GrafcetChartEditor::setValidator(Validator v) {
  validator_ = std::move(v);
  validate();
  showIssues();
}

void GrafcetChartEditor::setChart(const GrafcetChartData& chart) {
  chart_ = chart;
  format_issues_.clear();
  populate();
  view_->setChart(chart_);
  validate();
  showIssues();
}

GrafcetChartData GrafcetChartEditor::chart() const {
  return chart_;
}

QList<ChartIssue> GrafcetChartEditor::issues() const {
  return issues_;
}

void GrafcetChartEditor::populate() {
  populating_ = true;
  name_->setText(chart_.name);
  steps_->setRowCount(static_cast<int>(chart_.steps.size()));
  for (int r = 0; r < chart_.steps.size(); ++r) {
    const GrafcetStepView& s = chart_.steps[r];
    steps_->setItem(r, StepId, new QTableWidgetItem(QString::number(s.id)));
    steps_->setItem(r, StepName, new QTableWidgetItem(s.name));
    auto* initial = new QTableWidgetItem;
    initial->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    initial->setCheckState(s.initial ? Qt::Checked : Qt::Unchecked);
    steps_->setItem(r, StepInitial, initial);
    steps_->setItem(r, StepActions, new QTableWidgetItem(s.actions.join(QStringLiteral(", "))));
  }
  transitions_->setRowCount(static_cast<int>(chart_.transitions.size()));
  for (int r = 0; r < chart_.transitions.size(); ++r) {
    const GrafcetTransitionView& t = chart_.transitions[r];
    transitions_->setItem(r, TransitionId, new QTableWidgetItem(QString::number(t.id)));
    transitions_->setItem(r, TransitionFrom, new QTableWidgetItem(idList(t.from)));
    transitions_->setItem(r, TransitionTo, new QTableWidgetItem(idList(t.to)));
    transitions_->setItem(r, TransitionReceptivity, new QTableWidgetItem(t.receptivity));
    transitions_->setItem(r, TransitionPriority, new QTableWidgetItem(QString::number(t.priority)));
  }
  steps_->resizeColumnsToContents();
  transitions_->resizeColumnsToContents();
  populating_ = false;
}

void GrafcetChartEditor::edited() {
  if (populating_) return;
  GrafcetChartData c;
  c.name = name_->text().trimmed();
  format_issues_.clear();
  auto text = [](QTableWidget* t, int r, int col) {
    return t->item(r, col) ? t->item(r, col)->text().trimmed() : QString();
  };
  auto number = [&](const QString& s, const QString& element, int sid, int tid, const QString& what) {
    bool ok = false;
    const int v = s.toInt(&ok);
    if (!ok) format_issues_ << ChartIssue{element, sid, tid, tr("%1 \u201c%2\u201d is not an integer").arg(what, s)};
    return v;
  };
  static const QRegularExpression action_re(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*\\*?$"));
  for (int r = 0; r < steps_->rowCount(); ++r) {
    GrafcetStepView s;
    s.id = number(text(steps_, r, StepId), tr("step row %1").arg(r + 1), -1, -1, tr("step number"));
    const QString element = tr("step %1").arg(s.id);
    s.name = text(steps_, r, StepName);
    s.initial = steps_->item(r, StepInitial) && steps_->item(r, StepInitial)->checkState() == Qt::Checked;
    s.actions = tokens(text(steps_, r, StepActions));
    for (const QString& a : std::as_const(s.actions))
      if (!action_re.match(a).hasMatch())
        format_issues_ << ChartIssue{element, s.id, -1,
                                     tr("action \u201c%1\u201d is not a module name (A, L*)").arg(a)};
    if (std::any_of(c.steps.begin(), c.steps.end(), [&](const auto& o) { return o.id == s.id; }))
      format_issues_ << ChartIssue{element, s.id, -1, tr("duplicate step number %1").arg(s.id)};
    c.steps << s;
  }
  for (int r = 0; r < transitions_->rowCount(); ++r) {
    GrafcetTransitionView t;
    t.id = number(text(transitions_, r, TransitionId), tr("transition row %1").arg(r + 1), -1, -1,
                  tr("transition number"));
    const QString element = tr("transition %1").arg(t.id);
    for (const QString& f : tokens(text(transitions_, r, TransitionFrom)))
      t.from << number(f, element, -1, t.id, tr("source step"));
    for (const QString& s : tokens(text(transitions_, r, TransitionTo)))
      t.to << number(s, element, -1, t.id, tr("target step"));
    t.receptivity = text(transitions_, r, TransitionReceptivity);
    t.priority = number(text(transitions_, r, TransitionPriority), element, -1, t.id, tr("priority"));
    if (std::any_of(c.transitions.begin(), c.transitions.end(), [&](const auto& o) { return o.id == t.id; }))
      format_issues_ << ChartIssue{element, -1, t.id, tr("duplicate transition number %1").arg(t.id)};
    c.transitions << t;
  }
  chart_ = c;
  view_->setChart(chart_);
  validate();
  showIssues();
  if (issues_.isEmpty()) emit chartEdited(chart_);
}

void GrafcetChartEditor::validate() {
  issues_ = format_issues_;
  if (validator_) issues_ << validator_(chart_);
}

void GrafcetChartEditor::showIssues() {
  issue_list_->clear();
  const bool blocked_s = steps_->blockSignals(true), blocked_t = transitions_->blockSignals(true);
  for (QTableWidget* t : {steps_, transitions_})
    for (int r = 0; r < t->rowCount(); ++r)
      for (int c = 0; c < t->columnCount(); ++c)
        if (QTableWidgetItem* item = t->item(r, c)) item->setBackground(QBrush());
  for (const ChartIssue& issue : std::as_const(issues_)) {
    auto* item = new QListWidgetItem(
        issue.element.isEmpty() ? issue.message : issue.element + QStringLiteral(": ") + issue.message, issue_list_);
    item->setForeground(QColor(180, 20, 20));
    item->setData(kStepRole, issue.step_id);
    item->setData(kTransitionRole, issue.transition_id);
    item->setToolTip(item->text());
    QTableWidget* table = issue.step_id >= 0 ? steps_ : issue.transition_id >= 0 ? transitions_ : nullptr;
    const int id = issue.step_id >= 0 ? issue.step_id : issue.transition_id;
    for (int r = 0; table && r < table->rowCount(); ++r)
      if (table->item(r, 0) && table->item(r, 0)->text().toInt() == id)
        for (int c = 0; c < table->columnCount(); ++c)
          if (QTableWidgetItem* cell = table->item(r, c)) cell->setBackground(QColor(255, 220, 220));
  }
  steps_->blockSignals(blocked_s);
  transitions_->blockSignals(blocked_t);
  verdict_->setText(issues_.isEmpty() ? tr("\u2714 The chart is valid.")
                                      : tr("\u2716 %n issue(s): the chart is not applied until fixed.", "",
                                           static_cast<int>(issues_.size())));
  verdict_->setStyleSheet(issues_.isEmpty() ? QStringLiteral("color: #207020;")
                                            : QStringLiteral("color: #b41414; font-weight: bold;"));
}

void GrafcetChartEditor::selectElement(int step_id, int transition_id) {
  view_->setSelected(step_id, transition_id);
  QTableWidget* table = step_id >= 0 ? steps_ : transition_id >= 0 ? transitions_ : nullptr;
  const int id = step_id >= 0 ? step_id : transition_id;
  for (int r = 0; table && r < table->rowCount(); ++r)
    if (table->item(r, 0) && table->item(r, 0)->text().toInt() == id) {
      table->selectRow(r);
      table->scrollToItem(table->item(r, 0));
      table->setFocus();
    }
}

void GrafcetChartEditor::addStep() {
  int id = 0;
  for (const GrafcetStepView& s : std::as_const(chart_.steps)) id = std::max(id, s.id);
  GrafcetStepView s;
  s.id = id + 1;
  s.name = tr("Step %1").arg(s.id);
  s.initial = chart_.steps.isEmpty();
  chart_.steps << s;
  populate();
  edited();
  selectElement(s.id, -1);
}

void GrafcetChartEditor::removeStep() {
  const int row = steps_->currentRow();
  if (row < 0 || row >= chart_.steps.size()) return;
  const int id = chart_.steps[row].id;
  chart_.steps.removeAt(row);
  for (GrafcetTransitionView& t : chart_.transitions) {  // its arcs go with it
    t.from.removeAll(id);
    t.to.removeAll(id);
  }
  populate();
  edited();
}

void GrafcetChartEditor::addTransition() {
  int id = 0;
  for (const GrafcetTransitionView& t : std::as_const(chart_.transitions)) id = std::max(id, t.id);
  GrafcetTransitionView t;
  t.id = id + 1;
  const int row = steps_->currentRow();
  if (row >= 0 && row < chart_.steps.size()) t.from << chart_.steps[row].id;
  t.receptivity = QStringLiteral("1");
  chart_.transitions << t;
  populate();
  edited();
  selectElement(-1, t.id);
}

void GrafcetChartEditor::removeTransition() {
  const int row = transitions_->currentRow();
  if (row < 0 || row >= chart_.transitions.size()) return;
  chart_.transitions.removeAt(row);
  populate();
  edited();
}

}  // namespace mx::widgets
