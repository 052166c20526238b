#pragma once
// The bold caption over a section of a panel ("Tools on the chart", "Binding at q"), wrapped when the
// dock is narrow.
#include <QString>

class QLabel;
class QWidget;

namespace mx::widgets {

QLabel* sectionHeading(const QString& text, QWidget* parent = nullptr);

}  // namespace mx::widgets
