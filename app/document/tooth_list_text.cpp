#include "document/tooth_list_text.h"

#include <QLocale>
#include <QStringList>

#include "document/project_rules.h"

namespace mx::app {

QString toothListText(const std::vector<double>& values, const QString& separator) {
  QStringList items;
  for (double v : values) items << app::formatNumber(v);
  return items.join(separator);
}

ToothListParse parseToothList(const QString& text) {
  ToothListParse out;
  if (text.trimmed().isEmpty()) return out;
  QLocale c = QLocale::c();
  c.setNumberOptions(QLocale::RejectGroupSeparator);  // "70,110" is a mistyped list, never 70110
  const QStringList items = text.split(kToothListSeparator);
  for (qsizetype i = 0; i < items.size(); ++i) {
    bool ok = false;
    const QString item = items[i].trimmed();
    const double value = c.toDouble(item, &ok);
    if (!ok) {
      out.bad_item = static_cast<int>(i);
      out.bad_text = item;
      out.values.clear();
      return out;
    }
    out.values.push_back(value);
  }
  return out;
}

}  // namespace mx::app
