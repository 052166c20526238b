#include "e2e_environment.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QScreen>
#include <QStandardPaths>

namespace mx::e2e {

IsolatedEnvironment::IsolatedEnvironment() : root_(QDir::tempPath() + "/mx-e2e-XXXXXX") {
  if (!root_.isValid()) return;
  setFolder("HOME", "home", false);
  setFolder("XDG_CONFIG_HOME", "home/.config", false);
  setFolder("XDG_DATA_HOME", "home/.local/share", false);
  setFolder("XDG_STATE_HOME", "home/.local/state", false);
  setFolder("XDG_CACHE_HOME", "home/.cache", false);
  setFolder("XDG_RUNTIME_DIR", "runtime", true);  // Qt wants it private (0700)
  setFolder("TMPDIR", "tmp", false);
}

void IsolatedEnvironment::setFolder(const char* variable, const QString& relative, bool private_folder) {
  const QString path = root_.filePath(relative);
  QDir().mkpath(path);
  QFile::Permissions permissions = QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner;
  if (!private_folder) permissions |= QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther;
  QFile::setPermissions(path, permissions);
  qputenv(variable, QFile::encodeName(path));
}

QString displayProblem() {
  if (qEnvironmentVariableIsEmpty("DISPLAY"))
    return "no X display: DISPLAY is not set (run it under xvfb-run -a -s \"-screen 0 1920x1080x24\")";
  return {};
}

QString screenProblem() {
  if (QGuiApplication::platformName() != "xcb")
    return QString("the Qt platform is '%1', not xcb: real input needs a real X server")
        .arg(QGuiApplication::platformName());
  const QScreen* screen = QGuiApplication::primaryScreen();
  if (!screen) return "the X display has no screen";
  const QRect geometry = screen->geometry();
  if (geometry.width() < 1920 || geometry.height() < 1080 || screen->devicePixelRatio() != 1.0)
    return QString(
               "the X screen is %1x%2 at device pixel ratio %3; the window needs 1920x1080 at 1 "
               "(xvfb-run -s \"-screen 0 1920x1080x24\", no QT_SCALE_FACTOR)")
        .arg(geometry.width())
        .arg(geometry.height())
        .arg(screen->devicePixelRatio());
  return {};
}

QString findXdotool() {
  return QStandardPaths::findExecutable("xdotool");
}

}  // namespace mx::e2e
