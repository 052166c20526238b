#include "e2e_monkey_targets.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPlainTextEdit>
#include <QRegion>
#include <QTabBar>
#include <QTextEdit>

namespace mx::e2e {

namespace {

constexpr int kTries = 12;

bool opensFileDialog(const QWidget* w) {
  const auto* button = qobject_cast<const QAbstractButton*>(w);
  if (!button) return false;
  const QString text = button->text().trimmed();
  return text.endsWith("...") || text.endsWith(QChar(0x2026));
}

bool inside(const QWidget* w, const QWidget* ancestor) {
  for (; w; w = w->parentWidget())
    if (w == ancestor) return true;
  return false;
}

bool allowedAt(const QPoint& global, const Region& region) {
  const QWidget* top = QApplication::widgetAt(global);
  if (!top || !inside(top, region.content)) return false;
  for (const QWidget* w = top; w && w != region.content; w = w->parentWidget())
    if (opensFileDialog(w)) return false;
  return true;
}

}  // namespace

// A dock behind another's tab may still count as visible, but none of its widgets shows.
bool Region::shown() const {
  return content && content->isVisible() && !visibleWidgets(*this).empty();
}

std::vector<Region> regionsOf(QMainWindow& window) {
  std::vector<Region> regions;
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
    if (dock->widget()) regions.push_back({dock->objectName(), dock, dock->widget()});
  if (window.centralWidget()) regions.push_back({"central", nullptr, window.centralWidget()});
  return regions;
}

std::vector<QWidget*> visibleWidgets(const Region& region, const std::function<bool(QWidget*)>& accept) {
  std::vector<QWidget*> found;
  QList<QWidget*> all = region.content->findChildren<QWidget*>();
  all.prepend(region.content);
  for (QWidget* w : all) {
    if (!w->isVisible() || !w->isEnabled() || w->isWindow() || w->visibleRegion().isEmpty()) continue;
    if (w->width() < 3 || w->height() < 3 || opensFileDialog(w)) continue;
    if (accept && !accept(w)) continue;
    found.push_back(w);
  }
  return found;
}

std::optional<QPoint> randomPointOn(QWidget* widget, const Region& region, Dice& dice) {
  const QRegion visible = widget->visibleRegion();
  std::vector<QRect> rects(visible.begin(), visible.end());
  std::vector<double> areas;
  areas.reserve(rects.size());
  for (const QRect& r : rects) areas.push_back(double(r.width()) * r.height());
  if (rects.empty()) return std::nullopt;
  for (int i = 0; i < kTries; ++i) {
    const QRect& r = rects[dice.weighted(areas)];
    const QPoint local(r.left() + dice.below(r.width()), r.top() + dice.below(r.height()));
    const QPoint global = widget->mapToGlobal(local);
    if (allowedAt(global, region)) return global;
  }
  return std::nullopt;
}

std::optional<QPoint> pointAt(QWidget* widget, double fraction) {
  const QPoint local(int(widget->width() * fraction), widget->height() / 2);
  if (!widget->visibleRegion().contains(local)) return std::nullopt;
  return widget->mapToGlobal(local);
}

QTabBar* tabOf(QMainWindow& window, QDockWidget* dock, int* index) {
  for (QTabBar* bar : window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
    if (!bar->isVisible()) continue;
    for (int i = 0; i < bar->count(); ++i) {
      const bool same = bar->tabData(i).value<quintptr>() == reinterpret_cast<quintptr>(dock) ||
                        bar->tabText(i) == dock->windowTitle();
      if (same) {
        *index = i;
        return bar;
      }
    }
  }
  return nullptr;
}

bool dragsTextAt(const QPoint& global) {
  for (const QWidget* w = QApplication::widgetAt(global); w && !w->isWindow(); w = w->parentWidget()) {
    if (const auto* label = qobject_cast<const QLabel*>(w))
      return label->textInteractionFlags().testFlag(Qt::TextSelectableByMouse);
    if (const auto* line = qobject_cast<const QLineEdit*>(w)) return line->dragEnabled();
    if (qobject_cast<const QPlainTextEdit*>(w) || qobject_cast<const QTextEdit*>(w)) return true;
  }
  return false;
}

QString describe(const QWidget* widget) {
  QString text = widget->metaObject()->className();
  if (!widget->objectName().isEmpty()) return text + "#" + widget->objectName();
  for (const QWidget* w = widget->parentWidget(); w; w = w->parentWidget())
    if (!w->objectName().isEmpty()) return text + " in " + w->metaObject()->className() + "#" + w->objectName();
  return text;
}

}  // namespace mx::e2e
