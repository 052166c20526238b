// The lexer of Heidenhain conversational (Klartext) blocks (gcode_dialect.h, docs/part-programs.md):
//   [block number] KEYWORD word word ... [; comment]     or     [block number] * - structure comment
// Words are an address of letters and an optional signed number ("X+10", "IX-5", "F200", "S3000",
// "R0", "RL", "DR-", "FMAX", "M3"); "F AUTO" is one word. Other tokens (program and tool names, cycle
// numbers, Q-parameter formulas) are kept as they are.
#include <algorithm>
#include <array>
#include <string>

#include "core/invalid_input.h"
#include "gcode/dialect_lexers.h"
#include "gcode/word_scan.h"

namespace mx::gcode_lex {
namespace {

using namespace gcode_scan;

// Bytes a token may hold outside quoted names; anything else cannot be part of a Klartext block.
bool tokenChar(char c) {
  static constexpr std::string_view kSigns = "+-._:=/*<>[](),^%?'#$&";
  return isLetter(c) || isDigit(c) || kSigns.find(c) != std::string_view::npos;
}

enum class BlockKind { Motion, CircleCentre, Corner, ToolCall, Frame, Silent, NotModelled, Unknown };

constexpr std::array<std::string_view, 5> kMotionKeywords{"L", "C", "CR", "CT", "CC"};

BlockKind kindOf(std::string_view keyword, std::string_view second) {
  if (keyword == "CC") return BlockKind::CircleCentre;
  if (std::find(kMotionKeywords.begin(), kMotionKeywords.end(), keyword) != kMotionKeywords.end())
    return BlockKind::Motion;
  if (keyword == "RND" || keyword == "CHF") return BlockKind::Corner;
  if (keyword == "TOOL" && second == "CALL") return BlockKind::ToolCall;
  if ((keyword == "BEGIN" || keyword == "END") && second == "PGM") return BlockKind::Frame;
  if (keyword == "M" || keyword == "STOP" || keyword == "LBL" || keyword == "BLK" || keyword == "FN" ||
      keyword == "Q" || keyword == "TOOL" || keyword == "*" || keyword.empty())
    return BlockKind::Silent;
  if (keyword == "CYCL" && second == "DEF") return BlockKind::Silent;
  if (keyword == "CYCL" || keyword == "CALL" || keyword == "APPR" || keyword == "DEP" || keyword == "LP" ||
      keyword == "CP" || keyword == "PLANE" || keyword == "FUNCTION" || keyword == "TCH")
    return BlockKind::NotModelled;
  return BlockKind::Unknown;
}

// The addresses a motion block knows: axes absolute and incremental, radius compensation, arc radius
// and direction, feeds and M words.
bool knownMotionAddress(std::string_view a) {
  static constexpr std::array<std::string_view, 14> kKnown{"X",  "Y",  "Z",  "IX", "IY",   "IZ",    "R",
                                                           "RL", "RR", "DR", "F",  "FMAX", "FAUTO", "M"};
  return std::find(kKnown.begin(), kKnown.end(), a) != kKnown.end();
}

bool knownToolCallAddress(std::string_view a) {
  static constexpr std::array<std::string_view, 9> kKnown{"CALL", "X", "Y", "Z", "S", "F", "DL", "DR", "DR2"};
  return std::find(kKnown.begin(), kKnown.end(), a) != kKnown.end();
}

class HeidenhainLexer {
 public:
  HeidenhainLexer(GcodeBlock& block, std::vector<GcodeWarning>& warnings)
      : b_(block), s_(block.text), warnings_(warnings) {}

  void run() {
    skipBlanks();
    while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;  // the block number
    if (pos_ > 0 && pos_ < s_.size() && !isSpace(s_[pos_]) && s_[pos_] != ';') refuse(0, skipToken(0));
    b_.words_end = pos_;
    skipBlanks();
    if (pos_ < s_.size() && s_[pos_] == '/') endToken(pos_ + 1), skipBlanks();  // block skip
    if (pos_ < s_.size() && s_[pos_] == '*') {                                  // structure comment "* - text"
      b_.comments.push_back({pos_ + 1, s_.size() - pos_, std::string(s_.substr(pos_ + 1))});
      keyword_.assign(1, '*');
      return finish();
    }
    while (pos_ < s_.size()) {
      if (isSpace(s_[pos_])) {
        ++pos_;
      } else if (s_[pos_] == ';') {
        b_.comments.push_back({pos_ + 1, s_.size() - pos_, std::string(s_.substr(pos_ + 1))});
        break;
      } else {
        lexToken();
      }
    }
    finish();
  }

 private:
  GcodeBlock& b_;
  std::string_view s_;
  std::vector<GcodeWarning>& warnings_;
  std::size_t pos_ = 0;
  std::string keyword_, second_;
  int tokens_ = 0;
  struct Span {
    std::size_t from, to;
  };
  std::vector<Span> others_;  // tokens that are not words, after the keyword

  void other(std::size_t from, std::size_t to) {
    if (tokens_ > 0) others_.push_back({from, to});
  }

  void skipBlanks() {
    while (pos_ < s_.size() && isSpace(s_[pos_])) ++pos_;
  }
  std::size_t skipToken(std::size_t p) const {
    while (p < s_.size() && !isSpace(s_[p]) && s_[p] != ';') ++p;
    return p;
  }
  void endToken(std::size_t end) {
    pos_ = end;
    b_.words_end = end;
  }
  void warn(std::size_t at, std::size_t len, const std::string& message) {
    warnings_.push_back({b_.line, at + 1, std::string(s_.substr(at, len)), message});
  }
  [[noreturn]] void refuse(std::size_t at, std::size_t len) {
    throw InvalidInput(where(b_.line, at + 1) + excerpt(s_.substr(at, std::max<std::size_t>(len, 1))) +
                       ": cannot be split into Heidenhain Klartext words");
  }

  void lexToken() {
    const std::size_t start = pos_;
    if (s_[pos_] == '"') {  // a quoted tool or program name
      const std::size_t close = s_.find('"', pos_ + 1);
      if (close == std::string_view::npos) refuse(pos_, s_.size() - pos_);
      other(pos_, close + 1);
      return note(std::string(s_.substr(pos_, close + 1 - pos_))), endToken(close + 1);
    }
    const std::size_t end = skipToken(pos_);
    for (std::size_t i = start; i < end; ++i)
      if (!tokenChar(s_[i])) refuse(i, end - i);
    std::size_t p = start;
    while (p < end && isLetter(s_[p])) ++p;
    const std::size_t letters_end = p;
    double value = 0.0;
    bool has_value = false;
    if (p < end) {
      const std::size_t number_end = scanNumber(s_, p, value);
      if (number_end == end && number_end > p) {
        has_value = true;
      } else if (p + 1 == end && (s_[p] == '+' || s_[p] == '-')) {  // "DR+", "DR-"
        has_value = true;
        value = s_[p] == '+' ? 1.0 : -1.0;
      } else {
        other(start, end);
        return note(upperCopy(s_.substr(start, end - start))), endToken(end);  // "Q1=+5", "0:", a name: kept as it is
      }
    }
    if (letters_end == start) {  // a number ("TOOL CALL 1", "CHF 2")
      other(start, end);
      return note(upperCopy(s_.substr(start, end - start))), endToken(end);
    }
    GcodeWord w;
    w.address = upperCopy(s_.substr(start, letters_end - start));
    w.letter = w.address[0];
    w.column = start + 1;
    w.length = end - start;
    w.value_at = letters_end - start;
    w.has_value = has_value;
    w.value = has_value ? value : 0.0;
    if (w.address == "F" && !has_value) joinAuto(w);
    note(w.address);
    b_.words.push_back(std::move(w));
    endToken(b_.words.back().column - 1 + b_.words.back().length);
  }

  // "F AUTO": the feed of the TOOL CALL, one word.
  void joinAuto(GcodeWord& w) {
    std::size_t p = w.column - 1 + w.length;
    while (p < s_.size() && (s_[p] == ' ' || s_[p] == '\t')) ++p;
    if (upperCopy(s_.substr(p, 4)) == "AUTO" && (p + 4 == s_.size() || isSpace(s_[p + 4]) || s_[p + 4] == ';')) {
      w.address = "FAUTO";
      w.length = p + 4 - (w.column - 1);
    }
  }

  void note(const std::string& token) {
    if (tokens_ == 0) keyword_ = token.rfind('Q', 0) == 0 && token.size() > 1 ? "Q" : token;
    if (tokens_ == 1) second_ = token;
    ++tokens_;
  }

  void finish() {
    b_.feed_insert_at = std::string::npos;
    b_.speed_insert_at = std::string::npos;
    const BlockKind kind = kindOf(keyword_, second_);
    const bool two_words = kind == BlockKind::ToolCall || kind == BlockKind::Frame || keyword_ == "CYCL";
    b_.keyword = keyword_;
    if (two_words) b_.keyword.append(" ").append(second_);
    const std::size_t words_from = b_.words.empty() ? 0 : 1;  // the keyword itself is a word
    switch (kind) {
      case BlockKind::Motion:
      case BlockKind::CircleCentre:
      case BlockKind::Corner:
        markMotionWords(kind, words_from);
        break;
      case BlockKind::ToolCall:
        markToolCallWords();
        break;
      case BlockKind::NotModelled:
        warn(firstTokenAt(), b_.words_end - firstTokenAt(),
             "block not interpreted (its motion is not modelled): kept verbatim");
        break;
      case BlockKind::Unknown:
        warn(firstTokenAt(), b_.words_end - firstTokenAt(), "unknown block: kept verbatim");
        break;
      case BlockKind::Frame:
      case BlockKind::Silent:
        break;
    }
    if (!b_.words.empty() &&
        (kind == BlockKind::Motion || kind == BlockKind::CircleCentre || kind == BlockKind::Corner))
      b_.words.front().known = true;
  }

  // The end of the text before a word, blanks excluded: where a word inserted before it goes.
  std::size_t endBefore(const GcodeWord& w) const {
    std::size_t p = w.column - 1;
    while (p > 0 && isSpace(s_[p - 1])) --p;
    return p;
  }

  std::size_t firstTokenAt() const {
    std::size_t p = 0;
    while (p < s_.size() && (isSpace(s_[p]) || isDigit(s_[p]))) ++p;
    return std::min(p, b_.words_end);
  }

  // Words of L, C, CR, CT, CC, RND, CHF. The feed word is the first F before any M word (an F after an
  // M word belongs to it: "M103 F20").
  void markMotionWords(BlockKind kind, std::size_t from) {
    // Only RND and CHF take a bare number (the chamfer's length); any other token is not understood.
    for (std::size_t i = 0; i < others_.size(); ++i)
      if (!(kind == BlockKind::Corner && i == 0 && isDigit(s_[others_[i].from])))
        warn(others_[i].from, others_[i].to - others_[i].from, "unknown word: kept verbatim");
    bool after_m = false, rapid = false;
    std::size_t before_m = b_.words_end;
    for (std::size_t i = from; i < b_.words.size(); ++i) {
      GcodeWord& w = b_.words[i];
      if (after_m) {
        w.known = false;  // an M word's own parameter (M103 F20): not an axis or feed of the block
        continue;
      }
      w.known = knownMotionAddress(w.address);
      if (w.address == "M") {
        after_m = true;
        before_m = endBefore(w);
      }
      if (!w.known) {
        warn(w.column - 1, w.length, "unknown word: kept verbatim");
        continue;
      }
      checkWordRange(b_, w);
      if (w.address == "FMAX") rapid = true;
      if ((w.address == "F" || w.address == "FAUTO") && b_.feed_word < 0) b_.feed_word = static_cast<int>(i);
    }
    if (kind == BlockKind::Motion && !rapid && keyword_ != "CC") b_.feed_insert_at = before_m;
  }

  // TOOL CALL 1 Z S3000 F500 DL+0.1: S is the spindle speed; an S is inserted after the tool axis.
  void markToolCallWords() {
    std::size_t insert = b_.words_end;
    for (std::size_t i = 1; i < b_.words.size(); ++i) {
      GcodeWord& w = b_.words[i];
      w.known = knownToolCallAddress(w.address);
      if (!w.known) {
        warn(w.column - 1, w.length, "unknown word: kept verbatim");
        continue;
      }
      checkWordRange(b_, w);
      const bool technology =
          w.address == "S" || w.address == "F" || w.address == "DL" || w.address.rfind("DR", 0) == 0;
      if (technology && insert == b_.words_end) insert = endBefore(w);
      if (w.address == "S" && w.has_value && b_.speed_word < 0) b_.speed_word = static_cast<int>(i);
    }
    if (!b_.words.empty()) b_.words.front().known = true;
    b_.speed_insert_at = insert;
  }
};

}  // namespace

void lexHeidenhainLine(GcodeBlock& block, std::vector<GcodeWarning>& warnings) {
  HeidenhainLexer(block, warnings).run();
}

}  // namespace mx::gcode_lex
