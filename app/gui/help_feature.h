#pragma once
// Help: the Help menu (User guide on F1, What's This on Shift+F1, the example projects, About) and the
// start page of an empty project.
// - The guide, docs/user-guide.md with its pictures, is compiled into the program (help.qrc) and
//   shown in a GuideWindow beside the main window, not modal.
// - The start page (widgets::StartScreen) is laid over the central widget while the project has no
//   tool: a child of the main window kept on the central widget's geometry, outside every layout. The
//   lobe chart stays the central widget, untouched, and no other feature knows of the page; the first
//   tool (an example opened, a library imported, a tool added) hides it and the lobes show.
// - What the page and the Examples menu ask for goes out as signals that the window carries out:
//   opening a project needs the window's save prompt, and the imports are the tap-test and editors
//   features' own File actions.
#include <QMainWindow>
#include <QPointer>
#include <QUrl>
#include <QVector>

#include "start_screen.h"
#include "window_feature.h"

namespace mx::widgets {
class GuideWindow;
}

namespace mx::gui {

class HelpFeature : public WindowFeature {
  Q_OBJECT
 public:
  explicit HelpFeature(QMainWindow* window);

  void projectChanged(const app::Project& project, Features recompute) override;
  void addHelpActions(QMenu* help) override;

  widgets::GuideWindow* showGuide();  // opens the guide window (once) and raises it
  widgets::StartScreen* startScreen() const { return start_; }
  bool startScreenShown() const { return !start_->isHidden(); }
  static QUrl guideUrl();  // the guide compiled into the program
  static QString aboutText();

 signals:
  void projectOpenRequested(const QString& path);  // an example or a recent project
  void openProjectRequested();                     // File > Open's dialog
  void tapTestImportRequested();
  void toolLibraryImportRequested();
  void addToolRequested();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;  // the central widget moved or resized

 private:
  void showStartScreen(bool shown);

  QMainWindow* window_;
  widgets::StartScreen* start_;
  QVector<widgets::StartEntry> examples_;  // found once: the installed examples do not change while running
  QPointer<widgets::GuideWindow> guide_;
};

}  // namespace mx::gui
