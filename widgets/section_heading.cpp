#include "section_heading.h"

#include <QLabel>

namespace mx::widgets {

QLabel* sectionHeading(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  QFont f = label->font();
  f.setBold(true);
  label->setFont(f);
  label->setWordWrap(true);
  return label;
}

}  // namespace mx::widgets
