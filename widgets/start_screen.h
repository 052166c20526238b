#pragma once
// The start page of an empty project (File > New, or a window opened without a project): open one of
// the bundled example projects (listed by name, the selected one's description below), import a tap
// test, import a tool library, open a project file, or one of the recent projects. It only asks: each
// choice is a signal, which the window carries out with its own actions. It scrolls when the space it
// is given is small.
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>

class QLabel;
class QListWidget;
class QPushButton;

namespace mx::widgets {

struct StartEntry {
  QString path;  // absolute
  QString title;
  QString description;
};

class StartScreen : public QWidget {
  Q_OBJECT
 public:
  explicit StartScreen(QWidget* parent = nullptr);

  void setExamples(const QVector<StartEntry>& examples);  // the first one selected
  void setRecentFiles(const QStringList& paths);          // newest first; missing files are left out
  QListWidget* exampleList() const { return examples_; }
  QListWidget* recentList() const { return recent_; }
  QPushButton* button(const QString& object_name) const;  // "startOpenExample", "startImportTapTest", ...

 signals:
  void projectChosen(const QString& path);  // an example or a recent project
  void openProjectRequested();              // a file dialog
  void tapTestImportRequested();
  void toolLibraryImportRequested();
  void addToolRequested();  // a tool typed in by hand, in the tool library

 private:
  QWidget* buildActions();
  QWidget* buildExamples();
  void openSelectedExample();
  void showDescription();

  QListWidget* examples_;
  QLabel* description_;
  QListWidget* recent_;
  QLabel* no_recent_;
  QPushButton* open_example_ = nullptr;
};

}  // namespace mx::widgets
