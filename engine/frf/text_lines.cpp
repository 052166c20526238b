#include "frf/text_lines.h"

#include <algorithm>

#include "frf/fortran_number.h"

namespace mx {

bool TextLines::next(TextLine& line) {
  if (pos_ >= bytes_.size()) return false;
  previous_pos_ = pos_;
  previous_line_ = line_;
  const std::size_t nl = bytes_.find('\n', pos_);
  const std::size_t stop = nl == std::string_view::npos ? bytes_.size() : nl;
  std::size_t end = stop;
  while (end > pos_ && (bytes_[end - 1] == '\r' || bytes_[end - 1] == ' ' || bytes_[end - 1] == '\t')) --end;
  line.text = bytes_.substr(pos_, end - pos_);
  line.number = ++line_;
  pos_ = nl == std::string_view::npos ? bytes_.size() : nl + 1;
  return true;
}

bool TextLines::nextNonBlank(TextLine& line) {
  while (next(line))
    if (skipBlanks(line.text, 0) != line.text.size()) return true;
  return false;
}

void TextLines::skip(std::size_t n) {
  n = std::min(n, remaining());
  const auto block = bytes_.substr(pos_, n);
  line_ += static_cast<int>(std::count(block.begin(), block.end(), '\n'));
  pos_ += n;
}

bool isUffDelimiter(std::string_view line) {
  const std::size_t p = skipBlanks(line, 0);
  return line.substr(p) == "-1";
}

}  // namespace mx
