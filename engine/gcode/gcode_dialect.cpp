#include "gcode/gcode_dialect.h"

#include <array>
#include <cctype>

#include "core/invalid_input.h"
#include "gcode/word_scan.h"

namespace mx {
namespace {

struct DialectInfo {
  GcodeDialect dialect;
  std::string_view name;
  std::string_view title;
};

constexpr std::array<DialectInfo, 4> kDialects{{
    {GcodeDialect::Iso, "iso", "ISO / Fanuc"},
    {GcodeDialect::Heidenhain, "heidenhain", "Heidenhain Klartext"},
    {GcodeDialect::Sinumerik, "sinumerik", "Siemens Sinumerik"},
    {GcodeDialect::LinuxCnc, "linuxcnc", "LinuxCNC"},
}};

const DialectInfo& infoOf(GcodeDialect d) {
  for (const DialectInfo& info : kDialects)
    if (info.dialect == d) return info;
  return kDialects[0];
}

using gcode_scan::isDigit;

bool isAlnum(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// The (upper-cased) line with comments in parentheses and after ';' removed and runs of blanks made
// one space: markers are searched for only in the program's own words.
// keep_parens: for Sinumerik, whose parentheses hold call arguments, not comments.
std::string codeOf(std::string_view upper_line, bool keep_parens = false) {
  std::string out;
  out.reserve(upper_line.size());
  bool in_paren = false;
  for (const char c : upper_line) {
    if (in_paren) {
      in_paren = c != ')';
      continue;
    }
    if (c == '(' && !keep_parens) {
      in_paren = true;
      continue;
    }
    if (c == ';') break;
    if (c == ' ' || c == '\t' || c == '\r') {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    out += c;
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// True when `word` occurs in `code` not preceded or followed by a letter or digit.
bool hasToken(std::string_view code, std::string_view word) {
  for (std::size_t at = code.find(word); at != std::string_view::npos; at = code.find(word, at + 1)) {
    const bool open = at == 0 || !isAlnum(code[at - 1]);
    const std::size_t end = at + word.size();
    const bool close = end >= code.size() || !isAlnum(code[end]);
    if (open && close) return true;
  }
  return false;
}

// "CYCLE832(" or "MSG (": a name followed by '(' (Sinumerik calls).
bool hasCall(std::string_view code, std::string_view prefix, std::string& evidence) {
  for (std::size_t at = code.find(prefix); at != std::string_view::npos; at = code.find(prefix, at + 1)) {
    if (at > 0 && isAlnum(code[at - 1])) continue;
    std::size_t p = at + prefix.size();
    while (p < code.size() && isAlnum(code[p])) ++p;
    const std::size_t name_end = p;
    if (p < code.size() && code[p] == ' ') ++p;
    if (p < code.size() && code[p] == '(') {
      evidence = std::string(code.substr(at, name_end - at)) + "(";
      return true;
    }
  }
  return false;
}

// The Heidenhain block keywords that follow a block number ("7 L X+0", "9 CC X+50").
bool heidenhainMarker(std::string_view code, std::string& evidence) {
  for (const std::string_view k : {"BEGIN PGM", "END PGM", "TOOL CALL", "TOOL DEF", "BLK FORM", "CYCL DEF"})
    if (code.find(k) != std::string_view::npos) return evidence = k, true;
  std::size_t p = 0;
  while (p < code.size() && isDigit(code[p])) ++p;
  if (p == 0 || p >= code.size() || code[p] != ' ') return false;
  const std::string_view rest = code.substr(p + 1);
  for (const std::string_view k : {"L", "CC", "C", "CR", "CT", "LP", "CP", "RND", "CHF", "LBL", "CALL"}) {
    if (rest.substr(0, k.size()) != k) continue;
    if (rest.size() == k.size() || rest[k.size()] == ' ') return evidence = "block number + " + std::string(k), true;
  }
  return false;
}

bool sinumerikMarker(std::string_view code, std::string_view with_parens, std::string& evidence) {
  if (code.substr(0, 4) == "%_N_") return evidence = "%_N_", true;
  if (hasCall(with_parens, "CYCLE", evidence) || hasCall(with_parens, "MSG", evidence) ||
      hasCall(with_parens, "POCKET", evidence))
    return true;
  for (const std::string_view k : {"G641", "G642", "G643", "G644", "G645", "TRANS", "ATRANS", "SUPA", "G500"})
    if (hasToken(code, k)) return evidence = k, true;
  for (const std::string_view k : {"DEF REAL", "DEF INT", "DEF BOOL", "DEF STRING", "DEF CHAR", "DEF AXIS"})
    if (code.find(k) != std::string_view::npos) return evidence = k, true;
  for (std::size_t at = code.find('='); at != std::string_view::npos; at = code.find('=', at + 1)) {
    std::size_t b = at;
    if (b > 0 && code[b - 1] == ' ') --b;
    std::size_t a = b;
    while (a > 0 && isAlnum(code[a - 1])) --a;
    const std::string_view name = code.substr(a, b - a);
    const bool spindle = name.size() >= 2 && name[0] == 'S' && isDigit(name[1]);
    if (spindle || name == "CR" || name == "T" || name == "D") return evidence = std::string(name) + "=", true;
  }
  return false;
}

bool linuxCncMarker(std::string_view raw_upper, std::string_view code, std::string& evidence) {
  for (const std::string_view k : {"(MSG,", "(DEBUG,", "(PRINT,", "(LOGOPEN,", "(PROBEOPEN"})
    if (raw_upper.find(k) != std::string_view::npos) return evidence = k, true;
  if (code.find("#<") != std::string_view::npos) return evidence = "#<", true;
  if (hasToken(code, "M52")) return evidence = "M52", true;
  for (const std::string_view k : {"G64 P", "G64P"})
    if (code.find(k) != std::string_view::npos) return evidence = k, true;
  std::size_t p = code.substr(0, 1) == "N" ? code.find(' ') : 0;  // an o-word after a sequence number
  p = p == std::string_view::npos ? code.size() : (p == 0 ? 0 : p + 1);
  if (p < code.size() && code[p] == 'O' && p + 1 < code.size()) {
    const std::size_t space = code.find(' ', p);
    if (space != std::string_view::npos && (code[p + 1] == '<' || isDigit(code[p + 1])))
      for (const std::string_view k : {"SUB", "ENDSUB", "CALL", "IF", "WHILE", "DO", "REPEAT", "RETURN", "ELSE"})
        if (code.substr(space + 1, k.size()) == k) return evidence = "o-word " + std::string(k), true;
  }
  return false;
}

// The first block of an ISO program starts with a letter word ("G21", "N10", "O1234", "T1"), a tape
// marker, a block delete or '#' (a parameter).
bool startsLikeIso(std::string_view code) {
  std::size_t p = 0;
  if (p < code.size() && code[p] == '/') ++p;
  if (p < code.size() && code[p] == ' ') ++p;
  if (p >= code.size() || code[p] == '%' || code[p] == '#') return true;
  if (!std::isalpha(static_cast<unsigned char>(code[p]))) return false;
  ++p;
  if (p < code.size() && code[p] == ' ') ++p;
  return p < code.size() && (isDigit(code[p]) || code[p] == '-' || code[p] == '+' || code[p] == '.' || code[p] == '[');
}

std::string shortLine(std::string_view line) {
  std::string s(line.substr(0, 60));
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return line.size() > 60 ? s + "..." : s;
}

}  // namespace

std::string_view dialectName(GcodeDialect dialect) {
  return infoOf(dialect).name;
}

std::string_view dialectTitle(GcodeDialect dialect) {
  return infoOf(dialect).title;
}

std::optional<GcodeDialect> dialectFromName(std::string_view name) {
  for (const DialectInfo& info : kDialects)
    if (info.name == name) return info.dialect;
  return std::nullopt;
}

std::string dialectNames() {
  std::string out;
  for (const DialectInfo& info : kDialects) out += (out.empty() ? "" : ", ") + std::string(info.name);
  return out;
}

DialectDetection detectDialect(std::string_view text) {
  std::optional<DialectDetection> found;
  int first_code_line = 0;
  std::string first_code, first_raw;
  int line = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t nl = text.find('\n', start);
    const std::string_view raw = text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
    start = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line;
    const std::string raw_upper = gcode_scan::upperCopy(raw);
    const std::string code = codeOf(raw_upper);
    if (first_code_line == 0 && !code.empty()) first_code_line = line, first_code = code, first_raw = raw;
    std::string evidence;
    GcodeDialect dialect = GcodeDialect::Iso;
    if (code.empty() && raw_upper.find('(') == std::string::npos) continue;
    if (heidenhainMarker(code, evidence))
      dialect = GcodeDialect::Heidenhain;
    else if (sinumerikMarker(code, codeOf(raw_upper, true), evidence))
      dialect = GcodeDialect::Sinumerik;
    else if (linuxCncMarker(raw_upper, code, evidence))
      dialect = GcodeDialect::LinuxCnc;
    else
      continue;
    if (!found) {
      found = DialectDetection{dialect, line, evidence};
    } else if (found->dialect != dialect) {
      throw InvalidInput("line " + std::to_string(line) + ": " + shortLine(raw) + ": " +
                         std::string(dialectTitle(dialect)) + " syntax (" + evidence + ") in a program that line " +
                         std::to_string(found->line) + " marks as " + std::string(dialectTitle(found->dialect)) + " (" +
                         found->evidence + "): the dialect cannot be detected; name it (" + dialectNames() + ")");
    }
  }
  if (found) return *found;
  if (first_code_line > 0 && !startsLikeIso(first_code))
    throw InvalidInput("line " + std::to_string(first_code_line) + ": " + shortLine(first_raw) +
                       ": not a block of a known dialect (" + dialectNames() +
                       "): the dialect cannot be detected; name it if the program is one of them");
  return {};
}

}  // namespace mx
