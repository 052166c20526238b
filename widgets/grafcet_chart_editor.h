#pragma once
// The Grafcet chart editor: a table of steps (id, name, initial, actions such as "A, B, L*")
// and a table of transitions (id, source steps, target steps, receptivity, priority), add/remove
// buttons, the live drawing, and the validation errors inline. After each edit the chart is read
// back from the tables, checked for format errors (ids, action names) and then by the validator the
// main window provides; the issues are listed under the tables, the offending cells are tinted, and
// clicking an issue selects its element in the table and the drawing. chartEdited is emitted only for
// an edit that validates with no issue.
#include <QList>
#include <QWidget>
#include <functional>

#include "grafcet_chart_data.h"

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace mx::widgets {

class GrafcetChartView;

class GrafcetChartEditor : public QWidget {
  Q_OBJECT
 public:
  using Validator = std::function<QList<ChartIssue>(const GrafcetChartData&)>;
  explicit GrafcetChartEditor(QWidget* parent = nullptr);

  void setValidator(Validator v);
  void setChart(const GrafcetChartData& chart);  // no signal
  GrafcetChartData chart() const;
  QList<ChartIssue> issues() const;  // from the last validation (after each edit)

  QPushButton* addStepButton() const { return add_step_; }
  QPushButton* removeStepButton() const { return remove_step_; }
  QPushButton* addTransitionButton() const { return add_transition_; }
  QPushButton* removeTransitionButton() const { return remove_transition_; }
  QTableWidget* stepTable() const { return steps_; }
  QTableWidget* transitionTable() const { return transitions_; }
  QListWidget* issueList() const { return issue_list_; }
  QLineEdit* nameEdit() const { return name_; }
  GrafcetChartView* chartView() const { return view_; }

  enum StepColumn { StepId, StepName, StepInitial, StepActions };
  enum TransitionColumn { TransitionId, TransitionFrom, TransitionTo, TransitionReceptivity, TransitionPriority };

 signals:
  void chartEdited(const mx::widgets::GrafcetChartData& chart);

 private:
  void populate();
  void edited();    // tables -> chart, validate, show, maybe emit
  void validate();  // issues_ from format_issues_ + validator
  void showIssues();
  void selectElement(int step_id, int transition_id);
  void addStep();
  void removeStep();
  void addTransition();
  void removeTransition();

  QLineEdit* name_;
  QTableWidget* steps_;
  QTableWidget* transitions_;
  QPushButton* add_step_;
  QPushButton* remove_step_;
  QPushButton* add_transition_;
  QPushButton* remove_transition_;
  QLabel* verdict_;
  QListWidget* issue_list_;
  GrafcetChartView* view_;
  Validator validator_;
  GrafcetChartData chart_;
  QList<ChartIssue> format_issues_, issues_;
  bool populating_ = false;
};

}  // namespace mx::widgets
