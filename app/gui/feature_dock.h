#pragma once
// The docks of the window's features: a QDockWidget with the object name that tests, saved window
// states and `millexpert --docks` use.
#include <QDockWidget>
#include <QMainWindow>
#include <QString>

namespace mx::gui {

enum class DockContent {
  Fixed,     // the content fills the dock
  Scrolling  // the content scrolls, so the dock never forces the window taller than the screen (1080p)
};

// A dock of `window` holding `content`; the caller adds it to a dock area.
QDockWidget* makeFeatureDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                             DockContent mode = DockContent::Fixed);

}  // namespace mx::gui
