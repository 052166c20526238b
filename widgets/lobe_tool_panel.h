#pragma once
// Beside the lobe chart: its tools (each drawn as the chart draws it, a check box to show or hide it,
// the active tool in bold; a click makes a tool active) with "Active tool only", the stability pockets
// of the active tool, deepest first (a click moves the operating point there), and the limit under
// the mouse cursor. A list beside the plot instead of a legend on it: it never covers a lobe, and it
// scrolls instead of being cut off when a library has many tools.
#include <QIcon>
#include <QString>
#include <QVector>
#include <QWidget>

#include "lobe_pockets.h"

class QCheckBox;
class QLabel;
class QListWidget;
class QListWidgetItem;

namespace mx::widgets {

struct LobeToolEntry {
  QString id;
  QString tooltip;  // what its lobes ran on and their margins
  QIcon swatch;     // its lines and marker shape as the chart draws them
  bool visible = true;
};

class LobeToolPanel : public QWidget {
  Q_OBJECT
 public:
  explicit LobeToolPanel(QWidget* parent = nullptr);

  void setTools(const QVector<LobeToolEntry>& tools);
  void setToolVisible(int index, bool visible);
  void setActiveTool(int index);
  bool activeToolOnly() const;
  // The pockets of `tool`'s margined lobe; depths shown in the display unit (display_per_mm, unit).
  void setPockets(const QString& tool, const QVector<StabilityPocket>& pockets, double display_per_mm,
                  const QString& unit);
  void setCursorText(const QString& text);  // "" restores the hint

  QListWidget* toolList() const { return tools_; }
  QListWidget* pocketList() const { return pockets_; }
  QString cursorText() const;

  static constexpr int kMaxPockets = 12;

 signals:
  void toolVisibilityToggled(int index, bool visible);
  void toolClicked(int index);
  void activeToolOnlyToggled(bool on);
  void pocketChosen(double speed_rpm, double depth_mm);

 private:
  void onToolItemChanged(QListWidgetItem* item);

  QCheckBox* active_only_;
  QListWidget* tools_;
  QLabel* pockets_title_;
  QListWidget* pockets_;
  QLabel* cursor_;
  QVector<StabilityPocket> shown_pockets_;
  bool filling_ = false;
};

}  // namespace mx::widgets
