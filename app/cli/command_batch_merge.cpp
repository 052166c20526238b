// millexpert-cli batch-merge RESULTS.jsonl... --out SUMMARY.json [--csv FILE] [--html FILE]
// One table from the results files of `batch` (services/batch_merge.h): SUMMARY.json holds
// {"computation", "files", "cases", "duplicates", "failed", "torn_lines", "rows": [{"project",
// "machine", "material", "operation", "first_case", "entries": [...]}]}; --csv and --html the same
// rows, one line per row and tool. Each file is written atomically (QSaveFile). Prints {"cases",
// "rows", "duplicates", "failed", "out"}. A torn last line (a job still running or killed) is left out.
// Exit 1: one case (hash) with two different results; exit 2: a missing or malformed results file.
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/shortened_text.h"
#include "services/batch_merge.h"

namespace mx::app {

namespace {

QString csvField(const QString& text) {
  if (!text.contains(',') && !text.contains('"') && !text.contains('\n')) return text;
  return '"' + QString(text).replace("\"", "\"\"") + '"';
}

void writeCsv(QTextStream& out, const QJsonObject& summary) {
  out << batchTableHeader().join(',') << '\n';
  for (QStringList line : batchTableLines(summary)) {
    for (QString& field : line) field = csvField(field);
    out << line.join(',') << '\n';
  }
}

void writeHtml(QTextStream& out, const QJsonObject& summary) {
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>MillExpert batch: "
      << summary.value("computation").toString() << "</title></head><body>\n<table border=\"1\">\n<tr>";
  for (const QString& h : batchTableHeader()) out << "<th>" << h.toHtmlEscaped() << "</th>";
  out << "</tr>\n";
  for (const QStringList& line : batchTableLines(summary)) {
    out << "<tr>";
    for (const QString& field : line) out << "<td>" << field.toHtmlEscaped() << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n</body></html>\n";
}

void checkInputs(const QStringList& paths) {
  for (const QString& path : paths)
    if (!QFileInfo(path).isFile()) throw CliError(QString("RESULTS = %1: not a file").arg(quoted(path)), kExitBadInput);
}

}  // namespace

int runBatchMergeCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Merge batch results files into one table (docs/shop-scale.md).");
  parser.addHelpOption();
  parser.addOptions({{"out", "The summary (JSON).", "SUMMARY.json"},
                     {"csv", "The table as CSV, one line per row and tool.", "FILE"},
                     {"html", "The table as an HTML page.", "FILE"}});
  parser.addPositionalArgument("RESULTS", "The results files of `batch` (JSON Lines).", "RESULTS.jsonl...");
  parseArguments(parser, arguments);
  const QStringList paths = parser.positionalArguments();
  if (paths.isEmpty()) throw CliError("expected at least one RESULTS file", kExitBadInput);
  const QString out = requiredOption(parser, "out");
  OutputPaths checked;
  for (const QString& path : paths) checked.input("RESULTS", path);
  checked.output("--out", out).outputOption(parser, "csv").outputOption(parser, "html").check();

  checkInputs(paths);
  const QJsonObject summary = mergeBatchResults(paths);
  if (const qint64 torn = summary.value("torn_lines").toInteger(); torn > 0)
    QTextStream(stderr) << "note: " << torn
                        << " file(s) end in a torn line, left out (a job still running or killed)\n";
  writeTextFileAtomically("--out", out, [&](QTextStream& s) { s << QJsonDocument(summary).toJson(); });
  if (parser.isSet("csv"))
    writeTextFileAtomically("--csv", parser.value("csv"), [&](QTextStream& s) { writeCsv(s, summary); });
  if (parser.isSet("html"))
    writeTextFileAtomically("--html", parser.value("html"), [&](QTextStream& s) { writeHtml(s, summary); });
  printJson({{"cases", summary.value("cases")},
             {"rows", summary.value("rows").toArray().size()},
             {"duplicates", summary.value("duplicates")},
             {"failed", summary.value("failed")},
             {"out", out}});
  return kExitOk;
}

}  // namespace mx::app
