#pragma once
// A per-tooth list (pitch_deg, runout_um) as one text cell: numbers separated by ';', e.g.
// "70;110;70;110" in the tool-library CSV (whose delimiter is ',') and "70; 110; 70; 110" in the editor.
#include <QString>
#include <vector>

namespace mx::app {

inline constexpr QChar kToothListSeparator = u';';

// The shortest text of each number that reads back exactly, joined by `separator`.
QString toothListText(const std::vector<double>& values, const QString& separator = QString(kToothListSeparator));

struct ToothListParse {
  std::vector<double> values;
  int bad_item = -1;  // 0-based index of the first item that is not a number; -1 when all are
  QString bad_text;   // that item, trimmed
  bool ok() const { return bad_item < 0; }
};

// Items are trimmed; numbers use a decimal point. An empty text gives an empty list.
ToothListParse parseToothList(const QString& text);

}  // namespace mx::app
