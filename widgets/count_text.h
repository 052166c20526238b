#pragma once
// "1 tool", "3 tools": a count with its noun in the right number (the GUI has no translation files, so
// Qt's "%n tool(s)" would show its parentheses).
#include <QString>

namespace mx::widgets {

inline QString countText(qsizetype count, const QString& singular, const QString& plural) {
  return QStringLiteral("%1 %2").arg(count).arg(count == 1 ? singular : plural);
}

}  // namespace mx::widgets
