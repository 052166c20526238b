#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>

#include "document/project_rules.h"
#include "services/tool_formats/carried_payload.h"
#include "services/tool_formats/flute_phrase.h"
#include "services/tool_formats/linuxcnc_tool_table.h"
#include "services/tool_formats/linuxcnc_words.h"
#include "services/tool_formats/tool_numbers.h"

namespace mx::app {

namespace {

bool fromLinuxCnc(const ToolSpec& tool) {
  return tool.origin && tool.origin->format == "linuxcnc" && tool.origin->data.value("words").isArray();
}

TableUnits originUnits(const ToolSpec& tool) {
  return tool.origin->data.value("units").toString() == "inch" ? TableUnits::Inch : TableUnits::Millimetre;
}

// The units of the tables the tools came from when they agree; mm otherwise.
TableUnits exportUnits(const std::vector<ToolSpec>& tools) {
  std::optional<TableUnits> units;
  for (const ToolSpec& tool : tools) {
    if (!fromLinuxCnc(tool)) continue;
    if (units && *units != originUnits(tool)) return TableUnits::Millimetre;
    units = originUnits(tool);
  }
  return units.value_or(TableUnits::Millimetre);
}

std::optional<int> importedNumber(const ToolSpec& tool) {
  if (!fromLinuxCnc(tool)) return std::nullopt;
  const double t = tool.origin->data.value("T").toDouble(-1.0);
  if (t < 0.0 || t > 2147483647.0 || t != std::floor(t)) return std::nullopt;
  return static_cast<int>(t);
}

// The text of `mm` in the table's units that the reader turns back into exactly `mm`, when one of the
// doubles nearest mm/25.4 does; else the nearest.
QString lengthText(double mm, TableUnits units) {
  const double factor = millimetresPer(units);
  const double nearest = mm / factor;
  double below = nearest;
  double above = nearest;
  for (int step = 0; step < 4; ++step) {
    for (const double candidate : {below, above}) {
      QString text = formatNumber(candidate);
      if (text.toDouble() * factor == mm) return text;
    }
    below = std::nextafter(below, -INFINITY);
    above = std::nextafter(above, INFINITY);
  }
  return formatNumber(nearest);
}

// An offset in the other units, to 15 significant digits: 1.5 in is "38.1" mm, not "38.099999999999994".
QString convertedWord(const QString& word, double value, TableUnits from, TableUnits to) {
  return word.at(0) + QString::number(value * millimetresPer(from) / millimetresPer(to), 'g', 15);
}

// A D word that still reads as the tool's diameter is kept as written.
QString diameterWord(const QString& word, double value, const ToolSpec& tool, TableUnits from, TableUnits to) {
  if (from == to && value * millimetresPer(from) == tool.diameter_mm) return word;
  return word.at(0) + lengthText(tool.diameter_mm, to);
}

QStringList importedWords(const ToolSpec& tool, int number, TableUnits units) {
  const TableUnits from = originUnits(tool);
  QStringList words;
  bool has_t = false;
  bool has_d = false;
  for (const QJsonValue entry : tool.origin->data.value("words").toArray()) {
    const QString word = entry.toString();
    const std::optional<double> value = word.isEmpty() || !isTableLetter(word.at(0)) ? std::nullopt : wordValue(word);
    if (!value || word.contains(';')) continue;  // not a word the reader gave: left out
    const QChar letter = word.at(0).toUpper();
    if (letter == 'T') {
      has_t = true;
      words << (*value == number ? word : QString("T%1").arg(number));
    } else if (letter == 'D') {
      has_d = true;
      words << diameterWord(word, *value, tool, from, units);
    } else {
      words << (isLengthLetter(letter) && from != units ? convertedWord(word, *value, from, units) : word);
    }
  }
  if (!has_t) words.prepend(QString("T%1").arg(number));
  if (!has_d) words << "D" + lengthText(tool.diameter_mm, units);
  return words;
}

// A comment stays on its line: a line break becomes a space, and so does a carriage return at the end
// (the reader drops those with the line break).
QString oneLine(QString text) {
  for (QChar& c : text)
    if (c == '\n') c = u' ';
  for (qsizetype i = text.size() - 1; i >= 0 && text.at(i) == '\r'; --i) text[i] = u' ';
  return text;
}

// The imported comment with its flute phrase made the tool's count; a comment for a new tool: its id,
// type and flute count.
std::optional<QString> comment(const ToolSpec& tool) {
  if (fromLinuxCnc(tool)) {
    if (!tool.origin->data.value("comment").isString()) return std::nullopt;
    const QString text = oneLine(tool.origin->data.value("comment").toString());
    const FlutePhrase phrase = flutePhrase(text);
    return phrase.count == tool.teeth && phrase.problem.isEmpty() ? text : withFluteCount(text, tool.teeth);
  }
  QStringList parts{oneLine(tool.id)};
  if (tool.type) parts << oneLine(*tool.type);
  QString text = withFluteCount(parts.join(", "), tool.teeth);
  if (flutePhrase(text).count != tool.teeth) text += QString(", %1 flutes").arg(tool.teeth);
  return text;
}

QString toolLine(const ToolSpec& tool, int number, TableUnits units) {
  const QStringList words = fromLinuxCnc(tool) ? importedWords(tool, number, units)
                                               : QStringList{QString("T%1").arg(number), QString("P%1").arg(number),
                                                             "D" + lengthText(tool.diameter_mm, units)};
  const std::optional<QString> remark = comment(tool);
  return words.join(' ') + (remark ? " ;" + *remark : QString());
}

// writeSideFile's entries with the keys the table has no place for.
QByteArray sideFileOf(const std::vector<ToolSpec>& tools) {
  QJsonObject root = QJsonDocument::fromJson(writeSideFile(tools)).object();
  QJsonArray entries = root.value("tools").toArray();
  for (qsizetype i = 0; i < entries.size(); ++i) {
    QJsonObject entry = entries.at(i).toObject();
    const QJsonObject carried = carriedPayload(tools[static_cast<std::size_t>(i)], linuxCncCarriedKeys());
    for (auto it = carried.begin(); it != carried.end(); ++it)
      if (!entry.contains(it.key())) entry.insert(it.key(), it.value());
    entries[i] = entry;
  }
  root.insert("tools", entries);
  return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

}  // namespace

LinuxCncExport writeLinuxCncToolTable(const std::vector<ToolSpec>& tools) {
  const TableUnits units = exportUnits(tools);
  const std::vector<int> numbers = exportToolNumbers(tools, importedNumber);
  QString table = QString("; LinuxCNC tool table written by MillExpert (docs/tool-libraries.md)\n; units: %1\n")
                      .arg(unitsName(units));
  std::vector<ToolSpec> numbered = tools;
  for (std::size_t i = 0; i < tools.size(); ++i) {
    table += toolLine(tools[i], numbers[i], units) + '\n';
    numbered[i].id = QString("T%1").arg(numbers[i]);
  }
  return {table.toUtf8(), sideFileOf(numbered)};
}

}  // namespace mx::app
