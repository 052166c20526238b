#pragma once
// The words of a LinuxCNC tool line and the table's units, shared by the reader and the writer.
#include <QChar>
#include <QString>
#include <QStringList>
#include <optional>

namespace mx::app {

// LinuxCNC reads at most 1000 entries (LinuxCNC manual, "Tool Table").
inline constexpr int kMaxLinuxCncTools = 1000;

enum class TableUnits { Millimetre, Inch };

double millimetresPer(TableUnits units);  // 1 or 25.4
QString unitsName(TableUnits units);      // "mm" or "inch", as the units remark and ToolSpec::origin write it
// "mm", "millimeter(s)", "millimetre(s)", "metric" / "in", "inch", "inches", "imperial" (any case).
std::optional<TableUnits> unitsNamed(const QString& name);
// The units a remark line declares ("; units: inch", ";UNITS=mm"); nullopt when it declares none.
// `declared` is the word after "units:" when there is one, known or not.
std::optional<QString> declaredUnits(const QString& remark);

// The words of a line: T P X Y Z A B C U V W D I J Q (LinuxCNC manual, "Tool Table Format").
bool isTableLetter(QChar letter);
bool isIntegerLetter(QChar letter);  // T, P, Q
bool isLengthLetter(QChar letter);   // X Y Z U V W D: in the machine's units
// The number of a word ("D6.35" -> 6.35, "z+1e-3" -> 0.001), nullopt when the text after the letter is
// not a decimal number (an integer for T, P and Q).
std::optional<double> wordValue(const QString& word);

// The project keys a table has no place for, carried in its side file besides the dynamics.
const QStringList& linuxCncCarriedKeys();

// The words before the comment, split at spaces and tabs.
QStringList lineWords(const QString& words_part);

}  // namespace mx::app
