#include "gcode/gcode_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"

namespace mx {

std::string GcodeWriter::formatNumber(double value, int decimals) {
  decimals = std::clamp(decimals, 0, 12);
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  std::string s(buf, res.ptr);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string GcodeWriter::sanitizeComment(const std::string& text) {
  std::string s = text;
  for (char& c : s) {
    if (c == '(')
      c = '[';
    else if (c == ')')
      c = ']';
    else if (c == '\n' || c == '\r')
      c = ' ';
  }
  return s;
}

namespace {

bool semicolonComments(GcodeDialect d) {
  return d == GcodeDialect::Heidenhain || d == GcodeDialect::Sinumerik;
}

struct Change {
  std::size_t pos, len;
  std::string text;
  int order;
};

// The change that gives the block's F or S word the number, or inserts one.
Change wordChange(const GcodeBlock& b, char letter, double value, int decimals, int order, GcodeDialect d) {
  const std::string num = GcodeWriter::formatNumber(value, decimals);
  const GcodeWord* w = letter == 'F' ? b.feedWord() : b.speedWord();
  if (w) {
    const std::size_t at = w->column - 1;
    // A word with a number keeps its address and separator; a symbolic one ("F AUTO") is replaced whole.
    const std::size_t keep = w->has_value ? w->value_at : 0;
    std::string text = w->has_value ? num : std::string(1, letter) + num;
    if (!w->has_value && b.text[at] >= 'a' && b.text[at] <= 'z') text[0] = static_cast<char>(text[0] - 'A' + 'a');
    // The new number must not run into what follows: a digit or '.' would lengthen it, and on Sinumerik
    // a letter would make a name of it ("S1.5e3=8" -> "S88731e3=8", an assignment).
    const std::size_t after = at + w->length;
    if (after < b.text.size()) {
      const char c = b.text[after];
      const bool letter_after = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
      if ((c >= '0' && c <= '9') || c == '.' || (d == GcodeDialect::Sinumerik && letter_after)) text += ' ';
    }
    return {at + keep, w->length - keep, std::move(text), order};
  }
  const std::size_t at = letter == 'F' ? b.feed_insert_at : b.speed_insert_at;
  if (at == std::string::npos || at > b.text.size())
    throw InvalidInput("gcode edit of line " + std::to_string(b.line) + ": a " + std::string(dialectTitle(d)) + " " +
                       (b.keyword.empty() ? std::string("block") : b.keyword + " block") + " takes no " + letter +
                       " word");
  std::string text(at > 0 ? " " : "");
  text += letter;
  text += num;
  // A word inserted before text that is not a blank or a comment's ';' must not run into it.
  if (at < b.text.size() && b.text[at] != ' ' && b.text[at] != '\t' && b.text[at] != ';') text += ' ';
  return {at, 0, std::move(text), order};
}

void appendComment(std::string& out, const GcodeBlock& b, const std::string& comment, GcodeDialect d) {
  if (!semicolonComments(d)) {
    if (!out.empty()) out += ' ';
    out += '(' + GcodeWriter::sanitizeComment(comment) + ')';
    return;
  }
  std::string text = comment;
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  const bool open_to_end = !b.comments.empty() &&
                           b.comments.back().column - 1 + b.comments.back().length == b.text.size() &&
                           (b.text[b.comments.back().column - 1] == ';' || b.text[b.comments.back().column - 1] == '*');
  out += open_to_end ? " " : (out.empty() ? "; " : " ; ");
  out += text;
}

}  // namespace

std::string GcodeWriter::applyEdit(const GcodeBlock& b, const GcodeBlockEdit& e, GcodeDialect d) {
  // NaN means "leave the word alone"; an infinite value is a controller's failure, never written.
  for (const auto& [letter, value] : {std::pair{'F', e.feed}, std::pair{'S', e.speed_rpm}})
    if (std::isinf(value))
      throw InvalidInput("gcode edit of line " + std::to_string(b.line) + ": " + letter + " = " +
                         (value > 0 ? "inf" : "-inf") + ": only a finite value is written");
  std::vector<Change> changes;
  if (e.feed == e.feed) changes.push_back(wordChange(b, 'F', e.feed, e.feed_decimals, 0, d));
  if (e.speed_rpm == e.speed_rpm) changes.push_back(wordChange(b, 'S', e.speed_rpm, e.speed_decimals, 1, d));
  std::sort(changes.begin(), changes.end(),
            [](const Change& a, const Change& c) { return a.pos != c.pos ? a.pos < c.pos : a.order < c.order; });
  std::string out;
  out.reserve(b.text.size() + 32 + e.comment.size());
  std::size_t cursor = 0;
  for (const auto& c : changes) {
    out.append(b.text, cursor, c.pos - cursor);
    out += c.text;
    cursor = c.pos + c.len;
  }
  out.append(b.text, cursor, std::string::npos);
  if (!e.comment.empty()) {
    // Our comment is cut so that the block stays within the reader's line limit.
    const std::size_t room = kMaxGcodeLineLength > out.size() + 4 ? kMaxGcodeLineLength - out.size() - 4 : 0;
    std::string comment = e.comment.substr(0, room);
    while (comment.size() < e.comment.size() && !comment.empty() &&
           (static_cast<unsigned char>(e.comment[comment.size()]) & 0xC0) == 0x80)
      comment.pop_back();  // not inside a UTF-8 sequence
    if (!comment.empty()) appendComment(out, b, comment, d);
  }
  return out;
}

std::string GcodeWriter::headerText(const GcodeHeader& h, const std::string& eol, bool semicolon) {
  const auto line = [&](const std::string& text) {
    std::string out(semicolon ? "; " : "(");
    out += semicolon ? text : sanitizeComment(text);
    if (!semicolon) out += ')';
    out += eol;
    return out;
  };
  std::string s;
  s += line("MillExpert optimised part program");
  s += line("project: " + h.project);
  s += line("controller: " + h.controller);
  s += line("date: " + h.date);
  return s;
}

namespace {

// The leading lines a header goes after: a '%' tape marker line; on Sinumerik also "%_N_..." and
// ";$PATH=..." (the controller reads them first).
std::size_t headerPosition(const GcodeProgram& p) {
  const GcodeDialect d = p.dialect.dialect;
  std::size_t i = 0;
  for (; i < p.blocks.size(); ++i) {
    const GcodeBlock& b = p.blocks[i];
    const std::size_t first = b.text.find_first_not_of(" \t");
    const bool marker = first != std::string::npos && b.text[first] == '%' && b.words.empty() &&
                        (d == GcodeDialect::Sinumerik || b.text.find_first_not_of(" \t%") == std::string::npos);
    const bool path = d == GcodeDialect::Sinumerik && b.text.rfind(";$PATH", 0) == 0;
    if (!marker && !path) break;
  }
  return i;
}

}  // namespace

std::string GcodeWriter::write(const GcodeProgram& p, const std::vector<GcodeBlockEdit>& edits,
                               const GcodeHeader* header) {
  if (!edits.empty() && edits.size() != p.blocks.size())
    throw InvalidInput("gcode edits = " + std::to_string(edits.size()) + " entries: must be 0 or " +
                       std::to_string(p.blocks.size()) + " (one per block)");
  const GcodeDialect d = p.dialect.dialect;
  const bool heidenhain = d == GcodeDialect::Heidenhain;
  const std::size_t header_at = header && !heidenhain ? headerPosition(p) : std::string::npos;
  // Heidenhain: the BEGIN PGM block carries the header, or the first block when there is none.
  std::size_t header_block = std::string::npos;
  if (header && heidenhain && !p.blocks.empty()) {
    header_block = 0;
    for (std::size_t i = 0; i < p.blocks.size(); ++i)
      if (p.blocks[i].keyword == "BEGIN PGM") {
        header_block = i;
        break;
      }
  }
  std::string out;
  out.reserve(p.blocks.size() * 40 + 256);
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    if (i == header_at) out += headerText(*header, p.lineEnd(), semicolonComments(d));
    const auto& b = p.blocks[i];
    GcodeBlockEdit e = edits.empty() ? GcodeBlockEdit{} : edits[i];
    if (i == header_block) {
      const std::string note = "MillExpert optimised part program, project: " + header->project +
                               ", controller: " + header->controller + ", date: " + header->date;
      e.comment = e.comment.empty() ? note : note + "; " + e.comment;
    }
    out += e.empty() ? b.text : applyEdit(b, e, d);
    // A header after a last line without line end must not run into it.
    out += b.eol.empty() && i + 1 == header_at ? p.lineEnd() : b.eol;
  }
  if (header_at != std::string::npos && header_at >= p.blocks.size())
    out += headerText(*header, p.lineEnd(), semicolonComments(d));
  return out;
}

}  // namespace mx
