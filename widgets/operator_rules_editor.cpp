#include "operator_rules_editor.h"

#include <QFontDatabase>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QTextBlock>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <string>
#include <vector>

#include "rules/rule_parser.h"

namespace mx::widgets {

namespace {

// RuleError columns count Unicode code points; QTextBlock positions count UTF-16 units.
int utf16Offset(const QString& line, int column) {
  int offset = 0;
  for (int cp = 1; cp < column && offset < line.size(); ++cp)
    offset += (line.at(offset).isHighSurrogate() && offset + 1 < line.size()) ? 2 : 1;
  return offset;
}

}  // namespace

OperatorRulesEditor::OperatorRulesEditor(QWidget* parent) : QWidget(parent) {
  edit_ = new QPlainTextEdit(this);
  edit_->setObjectName("operator_rules_text");
  edit_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  edit_->setLineWrapMode(QPlainTextEdit::NoWrap);
  edit_->setPlaceholderText(tr("if tool.diameter_mm < 10 then speed_rpm <= 8000"));
  edit_->setToolTip(
      tr("Operator rules, one per line: if <condition> then <bound> [because \"...\"]. "
         "Blank lines and # comments are ignored. Lines with errors are red; rules that "
         "fired for the current point are green."));
  errors_ = new QListWidget(this);
  errors_->setObjectName("operator_rules_errors");
  errors_->setMaximumHeight(110);
  errors_->setToolTip(tr("Errors of the rules as \"line L, column C: message\"; click one to go to it."));
  status_ = new QLabel(this);
  status_->setObjectName("operator_rules_status");
  status_->setToolTip(tr("Result of the last check of the rules"));
  timer_ = new QTimer(this);
  timer_->setSingleShot(true);
  timer_->setInterval(kCheckDelayMs);
  connect(timer_, &QTimer::timeout, this, [this] { check(); });
  connect(edit_, &QPlainTextEdit::textChanged, this, &OperatorRulesEditor::onTextEdited);
  connect(errors_, &QListWidget::itemActivated, this, &OperatorRulesEditor::onErrorClicked);
  connect(errors_, &QListWidget::itemClicked, this, &OperatorRulesEditor::onErrorClicked);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(edit_, 1);
  layout->addWidget(status_);
  notes_ = new QLabel(this);
  notes_->setObjectName("operator_rules_notes");
  notes_->setWordWrap(true);
  notes_->setTextFormat(Qt::PlainText);
  notes_->setToolTip(
      tr("The rules evaluated at the current operating point: contradictions, violated constraints and advice"));
  notes_->setVisible(false);
  layout->addWidget(notes_);
  layout->addWidget(errors_);
  check();
}

QStringList OperatorRulesEditor::rules() const {
  QStringList lines = edit_->toPlainText().split(QLatin1Char('\n'));
  while (!lines.isEmpty() && lines.last().trimmed().isEmpty()) lines.removeLast();
  return lines;
}

void OperatorRulesEditor::setRules(const QStringList& rules) {
  setting_ = true;
  edit_->setPlainText(rules.join(QLatin1Char('\n')));
  setting_ = false;
  user_edited_ = false;
  last_emitted_ = this->rules();
  check();
}

void OperatorRulesEditor::setFiredRules(const QList<int>& lines) {
  fired_ = lines;
  updateSelections();
}

void OperatorRulesEditor::onTextEdited() {
  if (setting_) return;
  user_edited_ = true;
  timer_->start();
}

bool OperatorRulesEditor::check() {
  timer_->stop();
  const QStringList lines = rules();
  std::vector<std::string> text;
  text.reserve(static_cast<std::size_t>(lines.size()));
  for (const QString& l : lines) text.push_back(l.toStdString());
  const RuleParseResult result = parseRules(text);

  error_lines_.clear();
  error_columns_.clear();
  errors_->clear();
  for (const RuleError& e : result.errors) {
    error_lines_.push_back(e.line);
    error_columns_.push_back(e.column);
    auto* item = new QListWidgetItem(QString::fromStdString(e.toString()), errors_);
    item->setData(Qt::UserRole, e.line);
    item->setData(Qt::UserRole + 1, e.column);
    item->setForeground(QColor(170, 0, 0));
    item->setToolTip(tr("Click to go to line %1, column %2").arg(e.line).arg(e.column));
  }
  const bool ok = result.ok();
  errors_->setVisible(!ok);
  status_->setText(ok ? tr("%n rule(s), no errors", nullptr, static_cast<int>(result.rules.size()))
                      : tr("%n error(s)", nullptr, static_cast<int>(result.errors.size())));
  updateSelections();
  if (ok && user_edited_ && lines != last_emitted_) {
    last_emitted_ = lines;
    user_edited_ = false;
    emit rulesChanged(lines);
  }
  return ok;
}

void OperatorRulesEditor::setNotes(const QStringList& notes) {
  notes_list_ = notes;
  notes_->setText(notes.join('\n'));
  notes_->setVisible(!notes.isEmpty());
}

QStringList OperatorRulesEditor::errorMessages() const {
  QStringList out;
  for (int i = 0; i < errors_->count(); ++i) out << errors_->item(i)->text();
  return out;
}

void OperatorRulesEditor::onErrorClicked(QListWidgetItem* item) {
  if (!item) return;
  const QTextBlock block = edit_->document()->findBlockByNumber(item->data(Qt::UserRole).toInt() - 1);
  if (!block.isValid()) return;
  QTextCursor cursor(block);
  cursor.setPosition(block.position() + utf16Offset(block.text(), item->data(Qt::UserRole + 1).toInt()));
  edit_->setTextCursor(cursor);
  edit_->setFocus(Qt::OtherFocusReason);
}

void OperatorRulesEditor::updateSelections() {
  QList<QTextEdit::ExtraSelection> selections;
  QTextDocument* doc = edit_->document();
  auto lineSelection = [&](int line, const QColor& colour) {
    const QTextBlock block = doc->findBlockByNumber(line - 1);
    if (!block.isValid()) return;
    QTextEdit::ExtraSelection s;
    s.format.setBackground(colour);
    s.format.setProperty(QTextFormat::FullWidthSelection, true);
    s.cursor = QTextCursor(block);
    selections.push_back(s);
  };
  for (int line : fired_)
    if (!error_lines_.contains(line)) lineSelection(line, QColor(200, 240, 200));
  for (int i = 0; i < error_lines_.size(); ++i) {
    lineSelection(error_lines_[i], QColor(255, 205, 205));
    // A wavy underline from the error's column to the end of the line.
    const QTextBlock block = doc->findBlockByNumber(error_lines_[i] - 1);
    if (!block.isValid() || block.length() <= 1) continue;
    QTextEdit::ExtraSelection mark;
    mark.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
    mark.format.setUnderlineColor(Qt::red);
    mark.cursor = QTextCursor(block);
    const int start = std::min(utf16Offset(block.text(), error_columns_[i]), std::max(0, int(block.length()) - 2));
    mark.cursor.setPosition(block.position() + start);
    mark.cursor.setPosition(block.position() + std::max(start + 1, int(block.length()) - 1), QTextCursor::KeepAnchor);
    selections.push_back(mark);
  }
  edit_->setExtraSelections(selections);
}

}  // namespace mx::widgets
