#pragma once
// The operator-rules editor (Pareto paper, Module VII, Rule 18): the rules, one per line, in a plain
// text editor with inline errors. After each edit (debounced by kCheckDelayMs) or on check(), the
// text is parsed with mx::parseRules; every line with an error gets a red background and the errors
// are listed under the editor as "line L, column C: message" (the parser's own text). Clicking an
// error moves the cursor to it. Lines of rules that fired for the current point (setFiredRules) get a
// green background.
//
// rulesChanged() is emitted by a check after a user edit when the rules parse without errors and
// differ from the last emitted (or set) rules. setRules() emits nothing.
#include <QList>
#include <QStringList>
#include <QWidget>

class QLabel;
class QListWidget;
class QListWidgetItem;
class QPlainTextEdit;
class QTimer;

namespace mx::widgets {

class OperatorRulesEditor : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kCheckDelayMs = 300;

  explicit OperatorRulesEditor(QWidget* parent = nullptr);

  // The editor's lines (line i + 1 is element i; trailing empty lines dropped).
  QStringList rules() const;
  void setRules(const QStringList& rules);  // checks, no signal

  // 1-based line numbers of the rules that fired for the current point.
  void setFiredRules(const QList<int>& lines);
  QList<int> firedRules() const { return fired_; }

  // Parses now (cancels a pending debounced check). Returns true when there is no error.
  bool check();

  // Evaluation notes for the current point, under the status line: contradictions, violated fired
  // constraints, advice (plain text, one per line; empty hides the label).
  void setNotes(const QStringList& notes);
  QStringList notes() const { return notes_list_; }

  QList<int> errorLines() const { return error_lines_; }  // 1-based, ascending
  QStringList errorMessages() const;                      // as listed
  QPlainTextEdit* textEdit() const { return edit_; }
  QListWidget* errorList() const { return errors_; }

 signals:
  void rulesChanged(const QStringList& rules);

 private:
  void onTextEdited();
  void onErrorClicked(QListWidgetItem* item);
  void updateSelections();

  QPlainTextEdit* edit_ = nullptr;
  QListWidget* errors_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* notes_ = nullptr;
  QStringList notes_list_;
  QTimer* timer_ = nullptr;
  QList<int> error_lines_;
  QList<int> error_columns_;
  QList<int> fired_;
  QStringList last_emitted_;
  bool user_edited_ = false;
  bool setting_ = false;
};

}  // namespace mx::widgets
