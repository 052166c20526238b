#pragma once
// Immediate feedback on input a field cannot take: a small red note right under the field (or under a
// cell of a table) saying why, in plain words. The note belongs to the field's window, so it outlives
// a table's cell editor; it stays kInputNoteMs or until hideInputNote() (the next accepted keystroke).
// One note per window: a new one replaces the last.
#include <QModelIndex>
#include <QRect>
#include <QString>

class QAbstractItemView;
class QLabel;
class QWidget;

namespace mx::widgets {

inline constexpr int kInputNoteMs = 6000;

// Shows `text` under `area` of `field` (field coordinates; an empty area is the whole field), or
// above it when the window has no room below. Nothing while the field or its window is hidden.
void showInputNote(QWidget* field, const QString& text, const QRect& area = {});
// The same under the cell `index` of `view`; under the view's top when the index is not shown.
void showInputNote(QAbstractItemView* view, const QModelIndex& index, const QString& text);
void hideInputNote(const QWidget* field);
// The note of `field`'s window, nullptr before the first; for tests.
QLabel* inputNote(const QWidget* field);

}  // namespace mx::widgets
