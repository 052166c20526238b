#pragma once
// The real main window as the driver uses it: 1920x1080 at the top left of the X screen, quiet (errors
// go to the status bar, no modal dialog waits for a click), an autosave found next to a project is
// discarded.
#include <QString>
#include <memory>

#include "e2e_report.h"
#include "main_window.h"

namespace mx::e2e {

// Shown and exposed; Aborted when the X server never shows it.
std::unique_ptr<gui::MainWindow> showWindow();

// A child of the window by class and object name (any name when empty); Aborted naming it when missing.
template <class T>
T* part(const QObject& window, const QString& name = {}) {
  T* found = window.findChild<T*>(name);
  if (!found)
    throw Aborted(QString("the main window has no %1 %2").arg(T::staticMetaObject.className(), name).trimmed());
  return found;
}

}  // namespace mx::e2e
