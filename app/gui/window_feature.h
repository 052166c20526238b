#pragma once
// A feature hosted by the main window (force control, supervisor, machining, ...): it owns its docks,
// runner, cached request and generation counters. It reads the project from the document, never
// writes it: edits go out as editRequested, which the window applies (and undoes) through the
// ProjectDocument, and messages go to the window's status bar.
#include <QObject>
#include <QString>

#include "document/project.h"
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
  // Stop the feature's engine-thread work (the window closes).
  virtual void stop() {}

 signals:
  // `gesture` > 0 names one slider drag: its edits become one undo step.
  void editRequested(const mx::app::Project& edited, const QString& description, int gesture);
  void statusMessage(const QString& text, int timeout_ms);
  void errorRaised(const QString& title, const QString& message);  // a dialog unless the window is quiet
};

}  // namespace mx::gui
