#pragma once
// The open project as the GUI edits it: the Project snapshot, its file, the dirty flag, undo/redo
// (every edit is a whole-snapshot QUndoCommand, so undo restores exactly), the picked operating point,
// and autosave with crash recovery. Views never modify the Project directly: they call applyEdit().
// Every change of the snapshot emits changed() with the sections it touched.
#include <QObject>
#include <QString>
#include <QTimer>
#include <QUndoStack>

#include "document/project.h"
#include "document/project_changes.h"

namespace mx::app {

// The operating point picked on the lobe chart, in shop units.
struct PickedPoint {
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
  bool operator==(const PickedPoint&) const = default;
};

class ProjectDocument : public QObject {
  Q_OBJECT
 public:
  explicit ProjectDocument(QObject* parent = nullptr);

  const Project& project() const { return project_; }
  QString filePath() const { return path_; }
  bool isDirty() const { return !undo_.isClean(); }
  QUndoStack* undoStack() { return &undo_; }
  const PickedPoint& point() const { return point_; }

  // Validates `edited` (validateProject); on success pushes an undoable edit and returns "".
  // On failure nothing changes and the returned message names the field, value and range.
  // An edit that changes no section pushes nothing. Consecutive edits with the same `gesture_id` > 0
  // (one slider drag, press to release) merge into one undo step.
  QString applyEdit(const Project& edited, const QString& description, int gesture_id = 0);
  // A fresh gesture id for applyEdit (one per slider press).
  int newGesture() { return ++gestures_; }
  // Undoable move of the operating point (consecutive moves within one drag merge: `drag_id` > 0).
  void setPoint(const PickedPoint& point, int drag_id = 0);
  // One undo step: applyEdit(edited), then setPoint(point). Nothing happens when the edit is refused
  // (the message is returned, as by applyEdit).
  QString applyEditAndMovePoint(const Project& edited, const PickedPoint& point, const QString& description);
  // Sets the point without an undo entry (the initial point after loading).
  void initPoint(const PickedPoint& point) { setPointSilently(point); }
  // The tool the point is picked for (the GUI's active tool); "" until one is set. A view choice: no
  // undo entry; emits pointToolChanged when it changes.
  const QString& pointTool() const { return point_tool_; }
  void setPointTool(const QString& tool);
  // The project as save and autosave write it: operating_point holds the point and its tool when both
  // are valid for the project (a point picked, the tool one of its tools); else the project's own stays.
  Project projectToSave() const;
  // Loads `path` and applies its newer autosave on top as one undoable, unsaved edit.
  void recover(const QString& path);

  void newProject();
  // Throws ProjectError; clears undo history. A stored operating_point becomes the point and its tool;
  // without one, there is no point until a view picks one.
  void load(const QString& path);
  // projectToSave(), atomically (QSaveFile); throws ProjectError. The written operating_point becomes
  // the project's without an undo entry or a signal, as the rewritten FRF paths do.
  void save(const QString& path = {});
  void setAutosaveInterval(int ms);  // 0 disables; default 30 s
  QString autosavePath() const;      // "<file>.autosave" or per-untitled file in AppDataLocation
  // Atomic; no-op when clean. On failure the previous autosave stays, autosaveFailed is emitted and
  // the message (naming the file and the cause) returned; "" otherwise. The next interval retries.
  QString writeAutosave();
  static QString recoveryCandidate(const QString& path);  // autosave newer than `path`, else ""

 signals:
  // Any change of the snapshot: the sections an edit, its undo or redo touched; all on load and new.
  void changed(mx::app::ProjectChanges sections);
  void pointChanged(const mx::app::PickedPoint& point);
  void pointToolChanged(const QString& tool);
  void dirtyChanged(bool dirty);
  void filePathChanged(const QString& path);
  void autosaveFailed(const QString& message);

 private:
  friend class SnapshotCommand;
  friend class PointCommand;
  void setSnapshot(const Project& project, ProjectChanges sections);
  void setPointSilently(const PickedPoint& point);
  void adoptOperatingPoint(const Project& project);

  Project project_;
  PickedPoint point_;
  QString point_tool_;
  QString path_;
  QUndoStack undo_;
  QTimer autosave_;
  int gestures_ = 0;
};

}  // namespace mx::app
