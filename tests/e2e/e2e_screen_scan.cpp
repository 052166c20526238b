#include "e2e_screen_scan.h"

#include <QAbstractItemModel>
#include <QAbstractItemView>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <algorithm>

#include "e2e_monkey_targets.h"

namespace mx::e2e {

namespace {

constexpr int kMaxRows = 200, kMaxColumns = 40;

bool nonFinite(const QString& text) {
  static const QRegularExpression pattern(R"((?<![\w.])[-+]?(nan|inf|infinity)(?!\w))",
                                          QRegularExpression::CaseInsensitiveOption);
  return pattern.match(text).hasMatch();
}

// A refusal quotes the value the user typed: "damping = -inf: not a number", "teeth = 'nan': must be",
// and an editor's note under its field: ... must be between 0 and 10; "inf" is above the maximum.
bool nonFinite(QString text, const QStringList& user_strings) {
  static const QRegularExpression refused(
      R"(['"]?[-+]?(nan|inf|infinity)['"]?(?=\s*(:\s*(not a number|must\b)|is (above|below|not)\b)))",
      QRegularExpression::CaseInsensitiveOption);
  for (const QString& user : user_strings) text.remove(user);
  text.remove(refused);
  return nonFinite(text);
}

void collect(const QJsonValue& value, QStringList& out) {
  if (value.isString() && nonFinite(value.toString()) && !out.contains(value.toString())) out << value.toString();
  if (value.isArray())
    for (const auto& v : value.toArray()) collect(v, out);
  if (value.isObject())
    for (const auto& v : value.toObject()) collect(v, out);
}

bool shows(const QWidget* w) {
  return w->isVisible() && !w->visibleRegion().isEmpty();
}

void scanView(const QAbstractItemView& view, const QStringList& user_strings, QStringList& found) {
  const QAbstractItemModel* model = view.model();
  if (!model) return;
  const int rows = std::min(model->rowCount(), kMaxRows), columns = std::min(model->columnCount(), kMaxColumns);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const QString text = model->data(model->index(r, c)).toString();
      if (nonFinite(text, user_strings))
        found << QString("%1 cell (%2, %3): %4").arg(describe(&view)).arg(r).arg(c).arg(text);
    }
}

}  // namespace

QStringList nonFiniteUserStrings(const QJsonObject& project) {
  QStringList strings;
  collect(project, strings);
  // The longest first: a name that contains another is taken out whole.
  std::sort(strings.begin(), strings.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
  return strings;
}

QStringList nonFiniteTexts(const QWidget& window, const QStringList& user_strings) {
  QStringList found;
  for (const QLabel* label : window.findChildren<QLabel*>())
    if (shows(label) && nonFinite(label->text(), user_strings))
      found << describe(label) + ": " + label->text().left(200);
  for (const QLineEdit* line : window.findChildren<QLineEdit*>())
    if (shows(line) && line->isReadOnly() && nonFinite(line->text(), user_strings))
      found << describe(line) + ": " + line->text();
  for (const QAbstractItemView* view : window.findChildren<QAbstractItemView*>())
    if (shows(view)) scanView(*view, user_strings, found);
  return found;
}

QStringList cutWrappedLabels(const QWidget& window) {
  QStringList found;
  for (const QLabel* label : window.findChildren<QLabel*>()) {
    if (!shows(label) || !label->wordWrap() || label->text().isEmpty()) continue;
    const int needed = label->heightForWidth(label->width());
    if (label->height() < needed)
      found << QString("%1 (%2 px of %3): %4")
                   .arg(describe(label))
                   .arg(label->height())
                   .arg(needed)
                   .arg(label->text().left(120));
  }
  return found;
}

}  // namespace mx::e2e
