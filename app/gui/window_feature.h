#pragma once
// A feature hosted by the main window (lobes, simulation, expert ranking, Pareto, force control,
// machining, supervisor, ...): it owns its docks, actions, runner, cached request and generation
// counters. It reads the project from the document, never writes it: edits and point moves go out as
// signals, which the window applies (and undoes) through the ProjectDocument, and messages go to the
// window's status bar. What features share goes through the FeatureContext (feature_context.h).
#include <QMenu>
#include <QObject>
#include <QString>
#include <QToolBar>

#include "document/project.h"
#include "document/project_document.h"
#include "feature_recompute.h"

namespace mx::gui {

class WindowFeature : public QObject {
  Q_OBJECT
 public:
  using QObject::QObject;

  // The project changed (edit, undo, redo, load); `recompute` names what its sections invalidate
  // (featuresToRecompute), and a feature ignores what is not its own.
  virtual void projectChanged(const app::Project& project, Features recompute) = 0;
  // Another project is about to be loaded: forget what was shown of the previous one.
  virtual void projectReplaced() {}
  // Stop the feature's engine-thread work (the window closes, or Cancel was pressed).
  virtual void stop() {}
  // Its actions in the File, View, Settings and Help menus and on the toolbar, in the order the window asks.
  virtual void addFileActions(QMenu* /*file*/, QToolBar* /*toolbar*/) {}
  virtual void addViewActions(QMenu* /*view*/, QToolBar* /*toolbar*/) {}
  virtual void addSettingsActions(QMenu* /*settings*/) {}
  virtual void addHelpActions(QMenu* /*help*/) {}

 signals:
  // `gesture` > 0 names one slider drag: its edits become one undo step.
  void editRequested(const mx::app::Project& edited, const QString& description, int gesture);
  // An undoable move of the operating point (moves with the same `gesture` > 0 merge: one drag).
  void pointRequested(const mx::app::PickedPoint& point, int gesture);
  // The first point of a project, without an undo entry.
  void initialPointRequested(const mx::app::PickedPoint& point);
  // One undo step: the edit, then the move of the operating point.
  void editWithPointRequested(const mx::app::Project& edited, const mx::app::PickedPoint& point,
                              const QString& description);
  void statusMessage(const QString& text, int timeout_ms);
  void errorRaised(const QString& title, const QString& message);  // a dialog unless the window is quiet
};

}  // namespace mx::gui
