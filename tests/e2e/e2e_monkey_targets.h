#pragma once
// Where the monkey may act: each dock's content and the central widget (a "region"), the widgets in a
// region that show on screen, a random screen point on one of them, and the tab that raises a dock
// hidden behind another. Never the menu bar, the toolbar or a dock's title bar (close and float), and
// never a button whose text ends in "..." (a file dialog).
#include <QPoint>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

#include "e2e_monkey_dice.h"

class QDockWidget;
class QMainWindow;
class QTabBar;
class QWidget;

namespace mx::e2e {

struct Region {
  QString name;        // the dock's object name, or "central"
  QDockWidget* dock;   // null for the central widget
  QWidget* content;    // what the monkey acts on
  bool shown() const;  // on screen now (not behind another dock's tab)
};

// Every dock of `window` and its central widget.
std::vector<Region> regionsOf(QMainWindow& window);

// The widgets of `region` (its content and its descendants) that show on screen, are enabled and pass
// `accept` (every one when empty).
std::vector<QWidget*> visibleWidgets(const Region& region, const std::function<bool(QWidget*)>& accept = {});

// A random global point on the visible part of `widget` whose topmost widget is in the region and is
// no file-dialog button; none after a few tries.
std::optional<QPoint> randomPointOn(QWidget* widget, const Region& region, Dice& dice);

// A global point at `fraction` of `widget`'s width and half its height, when it shows there.
std::optional<QPoint> pointAt(QWidget* widget, double fraction);

// The tab bar of `window` that holds `dock` and the tab's index (null when the dock is not tabbed).
QTabBar* tabOf(QMainWindow& window, QDockWidget* dock, int* index);

// Whether a press and move at `global` could drag text out of a widget (selectable label text, a text
// editor, a line edit with dragging on): Qt's X11 drag and drop then holds the pointer, and once under
// ASan held xdotool past its 20 s.
bool dragsTextAt(const QPoint& global);

// "Class#objectName" of a widget and, without a name of its own, of its nearest named ancestor.
QString describe(const QWidget* widget);

}  // namespace mx::e2e
