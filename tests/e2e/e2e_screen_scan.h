#pragma once
// Numbers the window shows that are not numbers: "nan" or "inf" in a visible label, a read-only field
// or a cell of a visible table. What the user typed is theirs: editable fields are not scanned, and the
// project's own strings (a tool named "-inf", a rule line) and a refused value quoted in its refusal
// ("= -inf: not a number") are taken out of a text before it is.
#include <QJsonObject>
#include <QStringList>

class QWidget;

namespace mx::e2e {

// The strings of `project` (ids, names, rule lines) that read as nan or inf.
QStringList nonFiniteUserStrings(const QJsonObject& project);

// "Class#name: text" of each offending text under `window`, `user_strings` taken out.
QStringList nonFiniteTexts(const QWidget& window, const QStringList& user_strings);

// "Class#name: text" of each visible word-wrapped label under `window` that is lower than its text
// needs at its width: its last lines are cut off.
QStringList cutWrappedLabels(const QWidget& window);

}  // namespace mx::e2e
