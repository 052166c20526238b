#pragma once
// One block (line) of a G-code part program as read by GcodeReader: the original bytes of the line
// (without its line end), the line end itself, and the words and comments found in it with their byte
// positions, so a writer can replace or insert F and S words and reproduce everything else
// byte-for-byte. Columns are 1-based byte offsets (UTF-8 bytes are kept as they are).
#include <cstddef>
#include <string>
#include <vector>

namespace mx {

// A letter-number word ("G1", "F250.5", "x-1.2"). Letters are stored upper-case; the text keeps the case.
struct GcodeWord {
  char letter = 0;         // 'G', 'F', ... upper-case
  double value = 0.0;      // the number as written (program units)
  std::size_t column = 0;  // 1-based byte column of the letter
  std::size_t length = 0;  // bytes of letter + number (spaces between them included)
  bool known = false;      // a word of the supported subset
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
  std::vector<GcodeWord> words;        // in order of appearance (known and unknown letter words)
  std::vector<GcodeComment> comments;  // in order of appearance
  std::size_t words_end = 0;           // byte offset just after the last word (insertion point)

  // The first word with this letter (upper-case), or nullptr.
  const GcodeWord* find(char letter) const;
  // True when the block has a G word with this number (e.g. hasG(1), hasG(17)).
  bool hasG(int number) const;
};

}  // namespace mx
