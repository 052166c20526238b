#include "gcode/gcode_reader.h"

#include <algorithm>

#include "core/invalid_input.h"
#include "gcode/dialect_lexers.h"

namespace mx {

GcodeProgram GcodeReader::parse(std::string_view text, std::optional<GcodeDialect> dialect) {
  GcodeProgram prog;
  prog.dialect = dialect ? DialectDetection{*dialect, 0, {}} : detectDialect(text);
  const GcodeDialect d = prog.dialect.dialect;
  prog.blocks.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  std::size_t start = 0;
  int line = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    GcodeBlock b;
    b.line = ++line;
    if (nl == std::string_view::npos) {
      b.text = std::string(text.substr(start));
      b.eol.clear();
      start = text.size();
    } else {
      std::size_t end = nl;
      if (end > start && text[end - 1] == '\r') {
        --end;
        b.eol = "\r\n";
      } else {
        b.eol = "\n";
      }
      b.text = std::string(text.substr(start, end - start));
      start = nl + 1;
    }
    if (b.text.size() > kMaxGcodeLineLength)
      throw InvalidInput("line " + std::to_string(b.line) + ": " + std::to_string(b.text.size()) +
                         " characters: a block has at most " + std::to_string(kMaxGcodeLineLength));
    if (d == GcodeDialect::Heidenhain)
      gcode_lex::lexHeidenhainLine(b, prog.warnings);
    else
      gcode_lex::lexIsoFamilyLine(b, d, prog.warnings);
    if (b.eol.empty())
      prog.warnings.push_back({b.line, 0, b.text, "last line has no line end (truncated?): kept as is"});
    prog.blocks.push_back(std::move(b));
  }
  return prog;
}

GcodeProgram GcodeReader::readFile(const std::string& path, std::optional<GcodeDialect> dialect) {
  std::string text;
  try {
    text = readInputFile(path, kPartProgramFileLimit);
  } catch (const InvalidInput& e) {
    throw InvalidInput("gcode file = " + path + ": " + e.what());
  }
  return parse(text, dialect);
}

}  // namespace mx
