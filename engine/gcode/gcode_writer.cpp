#include "gcode/gcode_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

#include "core/invalid_input.h"

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

std::string GcodeWriter::applyEdit(const GcodeBlock& b, const GcodeBlockEdit& e) {
  struct Change {
    std::size_t pos, len;
    std::string text;
    int order;
  };
  std::vector<Change> changes;
  auto wordChange = [&](char letter, double value, int decimals, int order) {
    const std::string num = formatNumber(value, decimals);
    for (const auto& w : b.words)
      if (w.known && w.letter == letter) {
        const char written = b.text[w.column - 1];  // keep the letter's case
        std::string text = std::string(1, written) + num;
        // The line may go on with a '.' or a digit the old number did not take ("S30..2" is S30. and a
        // stray ".2"); a space keeps the new number from running into it.
        const std::size_t after = w.column - 1 + w.length;
        if (after < b.text.size() && (b.text[after] == '.' || (b.text[after] >= '0' && b.text[after] <= '9')))
          text += ' ';
        changes.push_back({w.column - 1, w.length, std::move(text), order});
        return;
      }
    const std::size_t at = b.words_end;
    changes.push_back({at, 0, std::string(at > 0 ? " " : "") + letter + num, order});
  };
  // NaN means "leave the word alone"; an infinite value is a controller's failure, never written.
  for (const auto& [letter, value] : {std::pair{'F', e.feed}, std::pair{'S', e.speed_rpm}})
    if (std::isinf(value))
      throw InvalidInput("gcode edit of line " + std::to_string(b.line) + ": " + letter + " = " +
                         (value > 0 ? "inf" : "-inf") + ": only a finite value is written");
  if (e.feed == e.feed) wordChange('F', e.feed, e.feed_decimals, 0);
  if (e.speed_rpm == e.speed_rpm) wordChange('S', e.speed_rpm, e.speed_decimals, 1);
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
    if (!out.empty()) out += ' ';
    out += '(';
    out += sanitizeComment(e.comment);
    out += ')';
  }
  return out;
}

std::string GcodeWriter::headerText(const GcodeHeader& h, const std::string& eol) {
  std::string s;
  s += "(MillExpert optimised part program)" + eol;
  s += "(project: " + sanitizeComment(h.project) + ")" + eol;
  s += "(controller: " + sanitizeComment(h.controller) + ")" + eol;
  s += "(date: " + sanitizeComment(h.date) + ")" + eol;
  return s;
}

std::string GcodeWriter::write(const GcodeProgram& p, const std::vector<GcodeBlockEdit>& edits,
                               const GcodeHeader* header) {
  if (!edits.empty() && edits.size() != p.blocks.size())
    throw InvalidInput("gcode edits = " + std::to_string(edits.size()) + " entries: must be 0 or " +
                       std::to_string(p.blocks.size()) + " (one per block)");
  std::string out;
  out.reserve(p.blocks.size() * 40 + 256);
  std::size_t first = 0;
  if (header) {
    // keep a leading tape marker line first
    if (!p.blocks.empty() && p.blocks[0].text.find('%') != std::string::npos && p.blocks[0].words.empty() &&
        p.blocks[0].text.find_first_not_of(" \t%") == std::string::npos) {
      out += p.blocks[0].text;
      out += p.blocks[0].eol.empty() ? p.lineEnd() : p.blocks[0].eol;
      first = 1;
    }
    out += headerText(*header, p.lineEnd());
  }
  for (std::size_t i = first; i < p.blocks.size(); ++i) {
    const auto& b = p.blocks[i];
    if (edits.empty() || edits[i].empty())
      out += b.text;
    else
      out += applyEdit(b, edits[i]);
    out += b.eol;
  }
  return out;
}

}  // namespace mx
