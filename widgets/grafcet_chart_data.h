#pragma once
// Display structs of a Grafcet (IEC 60848) chart for the supervisor view and the chart editor.
// The main window converts the engine's chart to these; the widgets never see the engine.
#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVector>

namespace mx::widgets {

struct GrafcetStepView {
  int id = 0;
  QString name;
  bool initial = false;
  QStringList actions;  // module letters: "A" level action, "L*" impulse action
  bool operator==(const GrafcetStepView&) const = default;
};

struct GrafcetTransitionView {
  int id = 0;
  QList<int> from, to;  // step ids (several: parallel convergence / divergence)
  QString receptivity;  // e.g. "a", "b and not a", "1"
  int priority = 1;     // the designer's order among transitions leaving the same step (1 first)
  bool operator==(const GrafcetTransitionView&) const = default;
};

struct GrafcetChartData {
  QString name;
  QVector<GrafcetStepView> steps;
  QVector<GrafcetTransitionView> transitions;
  bool operator==(const GrafcetChartData&) const = default;
};

// A validation error naming its element ("step 3", "transition 5"); ids are -1 when not applicable.
struct ChartIssue {
  QString element;
  int step_id = -1, transition_id = -1;
  QString message;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::GrafcetChartData)
Q_DECLARE_METATYPE(mx::widgets::ChartIssue)
