#pragma once
// Line-by-line reading of in-memory bytes that may hold binary blocks (58b): lines end with "\n" or
// "\r\n" (a last line without line end counts), trailing blanks are dropped, and the caller may jump
// over a block of raw bytes while the line count stays that of the bytes (an editor's line numbers).
#include <cstddef>
#include <string_view>

namespace mx {

// `s` without a leading UTF-8 byte order mark, which spreadsheet programs put before a CSV's header.
inline std::string_view withoutBom(std::string_view s) {
  constexpr std::string_view kBom = "\xef\xbb\xbf";
  return s.substr(0, kBom.size()) == kBom ? s.substr(kBom.size()) : s;
}

struct TextLine {
  std::string_view text;  // without the line end and trailing blanks
  int number = 0;         // 1-based
};

class TextLines {
 public:
  explicit TextLines(std::string_view bytes) : bytes_(bytes) {}

  // The next line; false at the end of the bytes.
  bool next(TextLine& line);
  // The next line that is not blank; false at the end of the bytes.
  bool nextNonBlank(TextLine& line);
  // Byte position of the next line's first character.
  std::size_t position() const { return pos_; }
  // Bytes left from position().
  std::size_t remaining() const { return bytes_.size() - pos_; }
  // Moves position() forward by n bytes (at most remaining()), counting the line ends skipped.
  void skip(std::size_t n);
  // Number of the last line returned (0 before the first).
  int lineNumber() const { return line_; }
  // Undoes the last next(), so that the same line is returned again.
  void putBack() { pos_ = previous_pos_, line_ = previous_line_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::size_t previous_pos_ = 0;
  int previous_line_ = 0;
};

// True for the "    -1" record that opens and closes every universal-file dataset.
bool isUffDelimiter(std::string_view line);

}  // namespace mx
