#include <QFileInfo>
#include <QJsonArray>
#include <map>

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/tool_formats/carried_payload.h"
#include "services/tool_formats/flute_phrase.h"
#include "services/tool_formats/linuxcnc_tool_table.h"
#include "services/tool_formats/linuxcnc_words.h"

namespace mx::app {

namespace {

[[noreturn]] void refuse(const QString& file, const QString& tool, const QString& field, const QString& what) {
  throw ToolLibraryError(toolLibraryError(file, tool, field, what));
}

struct TableLine {
  int number = 0;  // 1-based
  QString text;    // without the line break
};

// The lines, without their breaks ("\n" or "\r\n").
std::vector<TableLine> tableLines(const QString& text) {
  std::vector<TableLine> lines;
  qsizetype start = 0;
  for (int number = 1; start <= text.size(); ++number) {
    qsizetype end = text.indexOf('\n', start);
    if (end < 0) end = text.size();
    QString line = text.mid(start, end - start);
    while (line.endsWith(u'\r')) line.chop(1);
    lines.push_back({number, line});
    start = end + 1;
  }
  return lines;
}

bool isRemark(const QString& line) {
  return line.trimmed().startsWith(';');
}

// The units the table's remark lines declare; mm when none does.
TableUnits tableUnits(const std::vector<TableLine>& lines, const QString& file) {
  std::optional<TableUnits> units;
  for (const TableLine& line : lines) {
    if (!isRemark(line.text)) continue;
    const std::optional<QString> declared = declaredUnits(line.text);
    if (!declared) continue;
    const QString field = QString("line %1").arg(line.number);
    const std::optional<TableUnits> named = unitsNamed(*declared);
    if (!named) refuse(file, {}, field, QString("units %1: must be mm or inch").arg(quoted(*declared)));
    if (units && *units != *named) refuse(file, {}, field, "declares other units than an earlier line");
    units = named;
  }
  return units.value_or(TableUnits::Millimetre);
}

// One tool line, split and checked word by word.
struct ParsedLine {
  QStringList words;
  std::map<QChar, double> values;  // by upper-case letter
  std::optional<QString> comment;  // the text after ';', as written
};

ParsedLine parseLine(const TableLine& line, const QString& file) {
  ParsedLine parsed;
  const qsizetype semicolon = line.text.indexOf(';');
  if (semicolon >= 0) parsed.comment = line.text.mid(semicolon + 1);
  parsed.words = lineWords(semicolon >= 0 ? line.text.left(semicolon) : line.text);
  const QString where = QString("line %1").arg(line.number);
  for (const QString& word : parsed.words) {
    const QChar letter = word.at(0).toUpper();
    const QString field = QString("%1, %2").arg(where, quoted(word));
    if (!isTableLetter(letter))
      refuse(file, {}, field, "not a tool table word (T, P, X, Y, Z, A, B, C, U, V, W, D, I, J, Q, then a number)");
    const std::optional<double> value = wordValue(word);
    if (!value)
      refuse(file, {}, field,
             isIntegerLetter(letter) ? "must be the letter and an integer" : "must be the letter and a number");
    if (!parsed.values.emplace(letter, *value).second)
      refuse(file, {}, field, QString("repeats the %1 word").arg(letter));
  }
  return parsed;
}

int toolNumber(const ParsedLine& parsed, const TableLine& line, const QString& file) {
  const auto t = parsed.values.find('T');
  const QString field = QString("line %1").arg(line.number);
  if (t == parsed.values.end()) refuse(file, {}, field, "no tool number (a T word)");
  if (t->second < 0 || t->second > 2147483647.0)
    refuse(file, {}, field + ", T", QString("%1: must be an integer >= 0").arg(formatNumber(t->second)));
  if (const auto p = parsed.values.find('P'); p != parsed.values.end() && (p->second < 0 || p->second > 2147483647.0))
    refuse(file, {}, field + ", P", QString("%1: must be an integer >= 0").arg(formatNumber(p->second)));
  return static_cast<int>(t->second);
}

double diameterMm(const ParsedLine& parsed, const TableLine& line, TableUnits units, const QString& file,
                  const QString& id) {
  const auto d = parsed.values.find('D');
  const QString field = QString("line %1, D").arg(line.number);
  if (d == parsed.values.end()) refuse(file, id, field, "missing: the cutter's diameter (D word)");
  const double mm = d->second * millimetresPer(units);
  if (!rules::kDiameterMm.accepts(mm)) {
    const QString given = QString("%1 %2").arg(formatNumber(d->second), unitsName(units));
    const QString in_mm = units == TableUnits::Inch ? QString(" (%1 mm)").arg(formatNumber(mm)) : QString();
    refuse(file, id, field, QString("%1%2: %3").arg(given, in_mm, rules::kDiameterMm.mustBe(mm)));
  }
  return mm;
}

QJsonObject originData(const ParsedLine& parsed, TableUnits units) {
  QJsonObject data{
      {"T", parsed.values.at('T')}, {"words", QJsonArray::fromStringList(parsed.words)}, {"units", unitsName(units)}};
  if (const auto p = parsed.values.find('P'); p != parsed.values.end()) data.insert("P", p->second);
  if (parsed.comment) data.insert("comment", *parsed.comment);
  return data;
}

struct TableContext {
  QString file;
  TableUnits units = TableUnits::Millimetre;
  QString side_file;
  std::map<QString, QJsonObject> payloads;
  ToolImportOptions options;
};

ToolSpec toolOfLine(const TableLine& line, const TableContext& table) {
  const ParsedLine parsed = parseLine(line, table.file);
  ToolSpec tool;
  tool.id = QString("T%1").arg(toolNumber(parsed, line, table.file));
  tool.diameter_mm = diameterMm(parsed, line, table.units, table.file, tool.id);
  tool.origin = ToolOriginSpec{QStringLiteral("linuxcnc"), originData(parsed, table.units)};
  const QString where = QString("line %1, comment").arg(line.number);
  const FlutePhrase phrase = flutePhrase(parsed.comment.value_or(QString()));
  if (!phrase.problem.isEmpty()) refuse(table.file, tool.id, where, phrase.problem);
  const auto found = table.payloads.find(tool.id);
  const QJsonObject payload = found == table.payloads.end() ? QJsonObject{} : found->second;
  const std::optional<int> teeth =
      importedTeeth(phrase.count, carriedTeeth(payload, table.side_file, tool.id, {}), table.options);
  if (!teeth)
    refuse(table.file, tool.id, where,
           "no flute count: state it in the comment (\"3FL\", \"3 flutes\") or give --teeth N");
  if (!rules::kTeeth.accepts(*teeth)) refuse(table.file, tool.id, "--teeth", rules::kTeeth.mustBe(*teeth));
  tool.teeth = *teeth;
  return withCarriedPayload(tool, payload, linuxCncCarriedKeys(), table.side_file, {});
}

}  // namespace

ImportedLibrary readLinuxCncToolTable(const QByteArray& table, const QString& fileName,
                                      const ToolImportOptions& options, const std::optional<QByteArray>& sideFile) {
  const std::vector<TableLine> lines = tableLines(QString::fromUtf8(table));
  TableContext context{
      fileName, tableUnits(lines, fileName), QFileInfo(sideFilePath(fileName)).fileName(), {}, options};
  if (sideFile) context.payloads = readSideFile(*sideFile, context.side_file);
  ImportedLibrary library;
  for (const TableLine& line : lines) {
    if (line.text.trimmed().isEmpty() || isRemark(line.text)) continue;
    if (library.tools.size() == kMaxLinuxCncTools)
      refuse(fileName, {}, QString("line %1").arg(line.number),
             QString("more than %1 tools: LinuxCNC reads at most %1").arg(kMaxLinuxCncTools));
    library.tools.push_back(toolOfLine(line, context));
  }
  return library;
}

}  // namespace mx::app
