#pragma once
// The monkey's actions on one region, planned without touching the window: what to log and the
// xdotool command line that does it with real input. Clicks, double and right clicks, drags and the
// wheel land at random points of visible widgets; keys go to the focused widget; edits type good and
// bad values (-1, 1e308, nan, empty, very long text) into line edits, spin boxes, table cells and text
// editors; combo changes open a combo box and pick another entry.
#include <QStringList>
#include <optional>
#include <vector>

#include "e2e_monkey_dice.h"
#include "e2e_monkey_log.h"
#include "e2e_monkey_targets.h"

class QMainWindow;

namespace mx::e2e {

enum class ActionKind { Click, DoubleClick, RightClick, Drag, Wheel, Key, Edit, Combo };

struct PlannedAction {
  MonkeyAction action;
  QStringList xdotool;
  bool needs_focus = false;  // key events: the window must have the X input focus
};

// A kind drawn by the monkey's weights.
ActionKind drawKind(Dice& dice);
const char* kindName(ActionKind kind);

// The action of `kind` on `region`; a click when the region has nothing of that kind, none when
// nothing in it shows.
std::optional<PlannedAction> planAction(ActionKind kind, const Region& region, Dice& dice);

// A click on the tab that raises `region`'s dock; none when the dock is not behind a tab.
std::optional<PlannedAction> planRaise(QMainWindow& window, const Region& region);

}  // namespace mx::e2e
