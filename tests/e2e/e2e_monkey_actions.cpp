#include "e2e_monkey_actions.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QHash>
#include <QLineEdit>
#include <QMainWindow>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QTextEdit>

namespace mx::e2e {

namespace {

// Share of each kind, in the order of ActionKind.
const std::vector<double> kKindWeights = {24, 5, 3, 14, 10, 16, 18, 10};
const char* const kKindNames[] = {"click", "double-click", "right-click", "drag", "wheel", "key", "edit", "combo"};

const std::vector<QString> kKeys = {"0",          "1",          "2",
                                    "3",          "4",          "5",
                                    "6",          "7",          "8",
                                    "9",          "a",          "e",
                                    "k",          "n",          "q",
                                    "s",          "x",          "z",
                                    "Tab",        "shift+Tab",  "Return",
                                    "Escape",     "Up",         "Down",
                                    "Left",       "Right",      "shift+Up",
                                    "shift+Down", "shift+Left", "shift+Right",
                                    "ctrl+z",     "ctrl+y",     "ctrl+shift+z",
                                    "space",      "BackSpace",  "Delete",
                                    "Home",       "End",        "Prior",
                                    "Next",       "minus",      "period",
                                    "plus"};

// Values typed into line edits, spin boxes and table cells: good ones, out-of-range ones and garbage.
const std::vector<QString> kValues = {
    "-1", "0",   "1e308", "-1e308", "1e-308", "nan",    "NaN",        "inf",      "-inf",
    "",   "abc", "1,5",   "3",      "12.5",   "100000", "2147483648", "0.000001", "99999999999999999999",
    "-0", "1e",  "--5",   ".",      "e",      "7",      "250"};

// Fragments typed into text editors (operator rules, G-code, receptivities).
const std::vector<QString> kFragments = {"if ",   "then ", "and ", "or ",    "not ",   "(",      ")",      "speed",
                                         " > ",   " < ",   " = ",  "1e308",  "nan",    "-1",     "\n",     "depth",
                                         "power", "G1 ",   "X10 ", "F1e10 ", "S1e10 ", "M3",     "\n",     "chatter",
                                         "X",     "#",     ";",    "0.5",    "1e-300", "((((((", "))))))", "true"};

QString keysym(QChar c) {
  static const QHash<QChar, QString> names = {
      {'-', "minus"},      {'.', "period"},     {'+', "plus"},    {',', "comma"},      {' ', "space"},
      {'(', "parenleft"},  {')', "parenright"}, {'<', "less"},    {'>', "greater"},    {'=', "equal"},
      {'_', "underscore"}, {'*', "asterisk"},   {'/', "slash"},   {'#', "numbersign"}, {';', "semicolon"},
      {':', "colon"},      {'\n', "Return"},    {'%', "percent"}, {'!', "exclam"},     {'&', "ampersand"}};
  if (c.isLetterOrNumber() && c.unicode() < 128) return QString(c);
  return names.value(c, "space");
}

QStringList keysFor(const QString& text) {
  QStringList keys;
  for (QChar c : text) keys << keysym(c);
  return keys;
}

QString longText(Dice& dice) {
  const QString alphabet = "0123456789abcdefxyz.-e";
  QString text;
  const int n = dice.between(120, 300);
  for (int i = 0; i < n; ++i) text += alphabet[dice.below(int(alphabet.size()))];
  return text;
}

QString value(Dice& dice) {
  return dice.chance(0.1) ? longText(dice) : dice.pick(kValues);
}

QString fragments(Dice& dice) {
  if (dice.chance(0.1)) return longText(dice);
  QString text;
  const int n = dice.between(1, 8);
  for (int i = 0; i < n; ++i) text += dice.pick(kFragments);
  return text;
}

QStringList move(QPoint p) {
  return {"mousemove", QString::number(p.x()), QString::number(p.y())};
}

// Presses and releases (xdotool's own "click" waits 100 ms after each one).
QStringList click(int button, int repeat = 1) {
  const QString b = QString::number(button);
  QStringList args;
  for (int i = 0; i < repeat; ++i) {
    if (i > 0)
      args << "sleep"
           << "0.04";
    args << "mousedown" << b << "mouseup" << b;
  }
  return args;
}

QStringList keys(const QStringList& names) {
  return QStringList{"key", "--delay", "3"} + names;
}

QStringList sleep(int ms) {
  return {"sleep", QString::number(ms / 1000.0, 'f', 3)};
}

// How an edit ends: committed with Return or Tab, cancelled with Escape, or left for a later click.
QStringList finish(Dice& dice, QString* detail) {
  const std::vector<QString> endings = {"Return", "Return", "Tab", "Escape", ""};
  const QString ending = dice.pick(endings);
  *detail += ending.isEmpty() ? " (left open)" : " then " + ending;
  return ending.isEmpty() ? QStringList{} : keys({ending});
}

QString quoted(const QString& text) {
  QString shown = text.left(40);
  shown.replace('\n', "\\n");
  return "\"" + shown + (text.size() > 40 ? QString("...\" (%1 characters)").arg(text.size()) : "\"");
}

PlannedAction planned(const char* kind, const Region& region, QWidget* target, QPoint at) {
  PlannedAction p;
  p.action = {kind, region.name, describe(target), at, {}};
  return p;
}

std::optional<PlannedAction> planPointer(ActionKind kind, const Region& region, Dice& dice) {
  const std::vector<QWidget*> widgets = visibleWidgets(region);
  if (widgets.empty()) return std::nullopt;
  QWidget* target = dice.pick(widgets);
  const std::optional<QPoint> at = randomPointOn(target, region, dice);
  if (!at || (kind == ActionKind::Drag && dragsTextAt(*at))) return std::nullopt;
  PlannedAction p = planned(kKindNames[int(kind)], region, target, *at);
  p.xdotool = move(*at);
  switch (kind) {
    case ActionKind::DoubleClick:
      p.xdotool += click(1, 2);
      break;
    case ActionKind::RightClick: {  // a context menu: leave it, Escape, or pick an entry below the point
      p.xdotool += click(3) + sleep(200);
      const int choice = dice.below(3);
      if (choice == 1) {
        p.xdotool += keys({"Escape"});
        p.action.detail = "then Escape";
      } else if (choice == 2) {
        const QPoint entry(dice.between(10, 60), dice.between(8, 120));
        p.xdotool +=
            QStringList{"mousemove_relative", QString::number(entry.x()), QString::number(entry.y())} + click(1);
        p.action.detail = QString("then a click %1,%2 further").arg(entry.x()).arg(entry.y());
      }
      break;
    }
    case ActionKind::Wheel: {
      const bool up = dice.chance(0.5);
      const int notches = dice.between(1, 6);
      const QString modifier = dice.chance(0.2) ? "ctrl" : dice.chance(0.15) ? "shift" : QString();
      if (!modifier.isEmpty()) p.xdotool += QStringList{"keydown", modifier};
      p.xdotool += click(up ? 4 : 5, notches);
      if (!modifier.isEmpty()) p.xdotool += QStringList{"keyup", modifier};
      p.action.detail = QString("%1 %2 notches%3")
                            .arg(up ? "up" : "down")
                            .arg(notches)
                            .arg(modifier.isEmpty() ? QString() : " with " + modifier);
      p.needs_focus = !modifier.isEmpty();
      break;
    }
    case ActionKind::Drag: {
      QWidget* end_widget = dice.chance(0.6) ? target : dice.pick(widgets);
      const QPoint to = randomPointOn(end_widget, region, dice).value_or(*at);
      const int steps = dice.between(2, 8);
      p.xdotool += QStringList{"mousedown", "1"};
      for (int i = 1; i <= steps; ++i) {
        const QPoint step(at->x() + (to.x() - at->x()) * i / steps, at->y() + (to.y() - at->y()) * i / steps);
        p.xdotool += sleep(dice.between(5, 40)) + move(step);
      }
      p.xdotool += QStringList{"mouseup", "1"};
      p.action.detail =
          QString("to (%1,%2) on %3 in %4 steps").arg(to.x()).arg(to.y()).arg(describe(end_widget)).arg(steps);
      break;
    }
    default:
      p.xdotool += click(1);
  }
  return p;
}

std::optional<PlannedAction> planKey(const Region& region, Dice& dice) {
  std::optional<PlannedAction> p;
  if (dice.chance(0.5)) p = planPointer(ActionKind::Click, region, dice);  // focus something first
  if (!p) {
    p = PlannedAction{};
    p->action = {"key", region.name, "focused widget", {}, {}};
  }
  p->action.kind = "key";
  QStringList names;
  const int n = dice.between(1, 6);
  for (int i = 0; i < n; ++i) names << dice.pick(kKeys);
  p->xdotool += keys(names);
  p->action.detail = names.join(' ');
  p->needs_focus = true;
  return p;
}

bool editable(QWidget* w) {
  if (auto* line = qobject_cast<QLineEdit*>(w)) return !line->isReadOnly();
  if (auto* spin = qobject_cast<QAbstractSpinBox*>(w)) return !spin->isReadOnly();
  if (auto* text = qobject_cast<QPlainTextEdit*>(w)) return !text->isReadOnly();
  if (auto* text = qobject_cast<QTextEdit*>(w)) return !text->isReadOnly();
  return false;
}

std::optional<PlannedAction> planCellEdit(const Region& region, Dice& dice) {
  const std::vector<QWidget*> views =
      visibleWidgets(region, [](QWidget* w) { return qobject_cast<QAbstractItemView*>(w) != nullptr; });
  if (views.empty()) return std::nullopt;
  auto* view = static_cast<QAbstractItemView*>(dice.pick(views));
  const std::optional<QPoint> at = randomPointOn(view->viewport(), region, dice);
  if (!at) return std::nullopt;
  PlannedAction p = planned("edit", region, view, *at);
  const QString text = value(dice);
  p.xdotool = move(*at) + click(1, 2) + sleep(150) + keys({"ctrl+a", "BackSpace"});
  if (!text.isEmpty()) p.xdotool += keys(keysFor(text));
  p.action.detail = "cell " + quoted(text);
  p.xdotool += finish(dice, &p.action.detail);
  p.needs_focus = true;
  return p;
}

std::optional<PlannedAction> planEdit(const Region& region, Dice& dice) {
  const std::vector<QWidget*> fields = visibleWidgets(region, editable);
  if (fields.empty() || dice.chance(0.25)) {
    if (std::optional<PlannedAction> cell = planCellEdit(region, dice)) return cell;
  }
  if (fields.empty()) return planKey(region, dice);
  QWidget* field = dice.pick(fields);
  const bool text_editor = qobject_cast<QPlainTextEdit*>(field) || qobject_cast<QTextEdit*>(field);
  // A spin box's text is its left part, away from the arrows.
  const std::optional<QPoint> at = text_editor ? randomPointOn(field, region, dice)
                                               : pointAt(field, qobject_cast<QAbstractSpinBox*>(field) ? 0.3 : 0.5);
  if (!at) return std::nullopt;
  PlannedAction p = planned("edit", region, field, *at);
  const QString text = text_editor ? fragments(dice) : value(dice);
  p.xdotool = move(*at) + click(1);
  if (!text_editor || dice.chance(0.3)) p.xdotool += keys({"ctrl+a", "BackSpace"});
  if (!text.isEmpty()) p.xdotool += keys(keysFor(text));
  p.action.detail = quoted(text);
  if (!text_editor) p.xdotool += finish(dice, &p.action.detail);
  p.needs_focus = true;
  return p;
}

std::optional<PlannedAction> planCombo(const Region& region, Dice& dice) {
  const std::vector<QWidget*> combos =
      visibleWidgets(region, [](QWidget* w) { return qobject_cast<QComboBox*>(w) != nullptr; });
  if (combos.empty()) return planPointer(ActionKind::Click, region, dice);
  auto* combo = static_cast<QComboBox*>(dice.pick(combos));
  const std::optional<QPoint> at = pointAt(combo, 0.9);  // the arrow, also of an editable combo
  if (!at) return std::nullopt;
  PlannedAction p = planned("combo", region, combo, *at);
  const int steps = dice.between(1, 4);
  const QString direction = dice.chance(0.7) ? "Down" : "Up";
  QStringList names;
  for (int i = 0; i < steps; ++i) names << direction;
  const QString ending = dice.chance(0.85) ? "Return" : "Escape";
  names << ending;
  p.xdotool = move(*at) + click(1) + sleep(150) + keys(names);
  p.action.detail = QString("%1 x%2 then %3 (of %4 entries)").arg(direction).arg(steps).arg(ending).arg(combo->count());
  p.needs_focus = true;
  return p;
}

}  // namespace

ActionKind drawKind(Dice& dice) {
  return static_cast<ActionKind>(dice.weighted(kKindWeights));
}

const char* kindName(ActionKind kind) {
  return kKindNames[int(kind)];
}

std::optional<PlannedAction> planAction(ActionKind kind, const Region& region, Dice& dice) {
  switch (kind) {
    case ActionKind::Key:
      return planKey(region, dice);
    case ActionKind::Edit:
      return planEdit(region, dice);
    case ActionKind::Combo:
      return planCombo(region, dice);
    default:
      return planPointer(kind, region, dice);
  }
}

std::optional<PlannedAction> planRaise(QMainWindow& window, const Region& region) {
  if (!region.dock) return std::nullopt;
  int index = -1;
  QTabBar* bar = tabOf(window, region.dock, &index);
  if (!bar) return std::nullopt;
  const QPoint at = bar->mapToGlobal(bar->tabRect(index).center());
  PlannedAction p;
  p.action = {"tab", region.name, describe(bar), at, QString("\"%1\"").arg(bar->tabText(index))};
  p.xdotool = move(at) + click(1);
  return p;
}

}  // namespace mx::e2e
