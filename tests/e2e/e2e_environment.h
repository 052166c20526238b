#pragma once
// Where the driver runs: a private HOME, XDG folders and TMPDIR (the window's recent files, learning
// database and autosaves never touch the user's), and the preconditions of real input: an X display
// of at least 1920x1080 reached through the xcb platform, and xdotool.
#include <QString>
#include <QTemporaryDir>

namespace mx::e2e {

class IsolatedEnvironment {
 public:
  IsolatedEnvironment();
  bool valid() const { return root_.isValid(); }

 private:
  void setFolder(const char* variable, const QString& relative, bool private_folder);
  QTemporaryDir root_;
};

// Before the application exists: why there is no X display to run on ("" when DISPLAY is set).
QString displayProblem();
// Once the application exists: why its screen cannot take the 1920x1080 window ("" when it can).
QString screenProblem();
// The xdotool executable ("" when it is not on PATH).
QString findXdotool();

}  // namespace mx::e2e
