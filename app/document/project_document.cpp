#include "document/project_document.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUndoCommand>

#include "document/frf_paths.h"
#include "document/project_validation.h"

namespace mx::app {

// Swaps whole Project snapshots: undo restores the previous project exactly. The changed sections
// are computed once; undo and redo emit the same ones.
class SnapshotCommand : public QUndoCommand {
 public:
  SnapshotCommand(ProjectDocument* doc, Project before, Project after, const QString& text, ProjectChanges sections,
                  int gesture_id)
      : QUndoCommand(text),
        doc_(doc),
        before_(std::move(before)),
        after_(std::move(after)),
        sections_(sections),
        gesture_(gesture_id) {}
  void undo() override { doc_->setSnapshot(before_, sections_); }
  void redo() override { doc_->setSnapshot(after_, sections_); }
  int id() const override { return gesture_ > 0 ? kId : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = static_cast<const SnapshotCommand*>(other);
    if (o->gesture_ != gesture_) return false;
    after_ = o->after_;
    sections_ = changedSections(before_, after_);
    setObsolete(!sections_);  // the gesture came back to where it started: no undo step
    return true;
  }

 private:
  static constexpr int kId = 1002;
  ProjectDocument* doc_;
  Project before_, after_;
  ProjectChanges sections_;
  int gesture_;
};

// Moves the operating point; the moves of one drag merge into one undo step.
class PointCommand : public QUndoCommand {
 public:
  PointCommand(ProjectDocument* doc, PickedPoint before, PickedPoint after, int drag_id)
      : QUndoCommand(QObject::tr("Move operating point")), doc_(doc), before_(before), after_(after), drag_(drag_id) {}
  void undo() override { doc_->setPointSilently(before_); }
  void redo() override { doc_->setPointSilently(after_); }
  int id() const override { return drag_ > 0 ? kId : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = static_cast<const PointCommand*>(other);
    if (o->drag_ != drag_) return false;
    after_ = o->after_;
    setObsolete(after_ == before_);  // dragged back to the start: no undo step
    return true;
  }

 private:
  static constexpr int kId = 1001;
  ProjectDocument* doc_;
  PickedPoint before_, after_;
  int drag_;
};

ProjectDocument::ProjectDocument(QObject* parent) : QObject(parent) {
  connect(&undo_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit dirtyChanged(!clean); });
  connect(&autosave_, &QTimer::timeout, this, &ProjectDocument::writeAutosave);
  setAutosaveInterval(30000);
  newProject();
}

void ProjectDocument::setSnapshot(const Project& project, ProjectChanges sections) {
  project_ = project;
  emit changed(sections);
}

void ProjectDocument::setPointSilently(const PickedPoint& point) {
  point_ = point;
  emit pointChanged(point_);
}

namespace {

// A stored operating point goes with its tool: an edit that removes or renames the tool drops it (the
// point itself is written again on save, with the tool it is then picked for).
Project withoutStalePoint(Project p) {
  if (p.operating_point && p.findTool(p.operating_point->tool) == nullptr) p.operating_point.reset();
  return p;
}

}  // namespace

QString ProjectDocument::applyEdit(const Project& edit, const QString& description, int gesture_id) {
  const Project edited = withoutStalePoint(edit);
  const ProjectChanges sections = changedSections(project_, edited);
  if (!sections) return {};
  try {
    validateProject(edited);
  } catch (const ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  undo_.push(new SnapshotCommand(this, project_, edited, description, sections, gesture_id));
  return {};
}

QString ProjectDocument::applyEditAndMovePoint(const Project& edit, const PickedPoint& point,
                                               const QString& description) {
  const Project edited = withoutStalePoint(edit);
  const ProjectChanges sections = changedSections(project_, edited);
  if (!sections && point == point_) return {};
  // Validated first: a refused edit leaves no empty macro on the stack and does not move the point.
  if (sections) {
    try {
      validateProject(edited);
    } catch (const ProjectError& e) {
      return QString::fromStdString(e.what());
    }
  }
  undo_.beginMacro(description);
  applyEdit(edited, description);
  setPoint(point);
  undo_.endMacro();
  return {};
}

void ProjectDocument::setPoint(const PickedPoint& point, int drag_id) {
  if (point == point_) return;
  undo_.push(new PointCommand(this, point_, point, drag_id));
}

void ProjectDocument::setPointTool(const QString& tool) {
  if (tool == point_tool_) return;
  point_tool_ = tool;
  emit pointToolChanged(point_tool_);
}

Project ProjectDocument::projectToSave() const {
  if (point_tool_.isEmpty() || !(point_.speed_rpm > 0.0)) return project_;
  Project p = project_;
  p.operating_point = OperatingPointSpec{point_tool_, point_.speed_rpm, point_.depth_mm, point_.feed_mm_per_tooth};
  return projectValidationError(p).isEmpty() ? p : project_;
}

void ProjectDocument::adoptOperatingPoint(const Project& project) {
  if (!project.operating_point) return;
  const OperatingPointSpec& op = *project.operating_point;
  setPointTool(op.tool);
  setPointSilently({op.speed_rpm, op.depth_mm, op.feed_mm_per_tooth});
}

void ProjectDocument::newProject() {
  Project p;
  p.name = tr("Untitled");
  undo_.clear();
  path_.clear();
  setSnapshot(p, kAllSections);
  emit filePathChanged(path_);
}

void ProjectDocument::load(const QString& path) {
  Project p = loadProject(path);
  undo_.clear();
  path_ = path;
  setSnapshot(p, kAllSections);
  emit filePathChanged(path_);
  if (project_.operating_point)
    adoptOperatingPoint(project_);
  else if (!(point_ == PickedPoint{}))
    setPointSilently({});  // the previous project's point is none of this one's
}

void ProjectDocument::recover(const QString& path) {
  const Project recovered = loadProject(path + ".autosave");
  if (QFileInfo::exists(path)) {
    load(path);
  } else {
    newProject();
    path_ = path;
    emit filePathChanged(path_);
  }
  // Pushed even when equal to the file, so that the recovery stays one unsaved, undoable step.
  undo_.push(
      new SnapshotCommand(this, project_, recovered, tr("Recover autosave"), changedSections(project_, recovered), 0));
  adoptOperatingPoint(recovered);  // the point moves since the last save are in the autosave's
}

void ProjectDocument::save(const QString& path) {
  const QString target = path.isEmpty() ? path_ : path;
  if (target.isEmpty()) throw ProjectError(tr("no file name to save to"));
  const Project saved = projectToSave();
  saveProject(saved, target);
  QFile::remove(autosavePath());
  // What the file now holds: the same FRF files, named from the new folder, and the point it opens at.
  // Neither changes what the views show, so no undo step or signal.
  project_ = withFrfPathsRelativeTo(saved, QFileInfo(target).absolutePath());
  if (target != path_) {
    path_ = target;
    emit filePathChanged(path_);
  }
  undo_.setClean();
}

void ProjectDocument::setAutosaveInterval(int ms) {
  autosave_.stop();
  if (ms > 0) autosave_.start(ms);
}

QString ProjectDocument::autosavePath() const {
  if (!path_.isEmpty()) return path_ + ".autosave";
  const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
  QDir().mkpath(dir);
  return dir + "/untitled.mxproj.autosave";
}

QString ProjectDocument::writeAutosave() {
  if (!isDirty()) return {};
  try {
    saveProject(projectToSave(), autosavePath());
  } catch (const ProjectError& e) {
    QString message = QString::fromStdString(e.what());
    emit autosaveFailed(message);
    return message;
  }
  return {};
}

QString ProjectDocument::recoveryCandidate(const QString& path) {
  QString autosave = path + ".autosave";
  const QFileInfo a(autosave), f(path);
  if (!a.exists()) return {};
  if (f.exists() && a.lastModified() < f.lastModified()) return {};
  return autosave;
}

}  // namespace mx::app
