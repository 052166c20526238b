#pragma once
// One block (line) of a part program as read by GcodeReader, in any dialect: the original bytes of the
// line (without its line end), the line end itself, and the words and comments found in it with their
// byte positions, so a writer can replace or insert F and S words and reproduce everything else
// byte-for-byte. Columns are 1-based byte offsets (UTF-8 bytes are kept as they are).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mx {

// An address-value word ("G1", "F250.5", "x-1.2", "S1=2000", Heidenhain "IX+5", "FMAX", "DR-").
// Addresses are stored upper-case; the text keeps the case.
struct GcodeWord {
  char letter = 0;           // first letter of the address, upper-case: 'G', 'F', ...
  std::string address;       // the whole address upper-case ("G", "IX", "FMAX", "DR", "S1"); ISO: one letter
  double value = 0.0;        // the number as written (program units); 0 when has_value is false
  std::size_t column = 0;    // 1-based byte column of the address
  std::size_t length = 0;    // bytes of address + value (spaces, '=' between them included)
  std::size_t value_at = 1;  // bytes from the column to the value ("F 250": 2, "S1=2000": 3)
  bool has_value = true;     // false for a bare address ("FMAX", "RL", "DR+" keeps its sign in value)
  bool known = false;        // a word of the dialect's supported subset
};

struct GcodeComment {
  std::size_t column = 0;  // 1-based byte column of '(' or ';'
  std::size_t length = 0;  // bytes including the delimiters
  std::string text;        // inner text, UTF-8 bytes preserved
};

struct GcodeWarning {
  int line = 0;            // 1-based line number
  std::size_t column = 0;  // 1-based byte column (0: the whole line)
  std::string text;        // the offending text, verbatim
  std::string message;     // what is wrong
};

struct GcodeBlock {
  int line = 0;                        // 1-based line number in the file
  std::string text;                    // the line's bytes without the line end
  std::string eol;                     // "\n", "\r\n" or "" (last line without line end)
  std::string keyword;                 // Heidenhain: the block's keyword ("L", "CC", "TOOL CALL", ...); ISO: empty
  std::vector<GcodeWord> words;        // in order of appearance (known and unknown letter words)
  std::vector<GcodeComment> comments;  // in order of appearance
  std::size_t words_end = 0;           // byte offset just after the last word (insertion point)
  // The F and S words a writer edits (indices into words, -1: none), and where it may insert one
  // (byte offset; npos: this block takes no such word in its dialect, e.g. S outside a Heidenhain
  // TOOL CALL).
  int feed_word = -1;
  int speed_word = -1;
  std::size_t feed_insert_at = 0;
  std::size_t speed_insert_at = 0;

  // The first one-letter word with this letter (upper-case) and a number, or nullptr.
  const GcodeWord* find(char letter) const;
  // The first word with this address (upper-case) and a number, or nullptr.
  const GcodeWord* findAddress(std::string_view address) const;
  // True when the block has a G word with this number (e.g. hasG(1), hasG(17)).
  bool hasG(int number) const;
  // The block's editable F / S word, or nullptr.
  const GcodeWord* feedWord() const { return feed_word < 0 ? nullptr : &words[static_cast<std::size_t>(feed_word)]; }
  const GcodeWord* speedWord() const { return speed_word < 0 ? nullptr : &words[static_cast<std::size_t>(speed_word)]; }
};

}  // namespace mx
