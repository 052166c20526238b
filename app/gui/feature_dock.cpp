#include "feature_dock.h"

#include <QScrollArea>

namespace mx::gui {

QDockWidget* makeFeatureDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                             DockContent mode) {
  auto* dock = new QDockWidget(title, window);
  dock->setObjectName(name);
  if (mode == DockContent::Scrolling) {
    auto* area = new QScrollArea;
    area->setWidget(content);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    dock->setWidget(area);
  } else {
    dock->setWidget(content);
  }
  return dock;
}

}  // namespace mx::gui
