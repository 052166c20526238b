#pragma once
// The one error of the FRF readers: the message names the source (file name), where the problem is
// (a 1-based text line, or a byte offset inside a 58b binary block) and what was expected there.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace mx {

class FrfFileError : public std::runtime_error {
 public:
  // "<source>: line <line>: <expected>"; line 0 means the whole file ("<source>: <expected>").
  FrfFileError(const std::string& source, int line, const std::string& expected);
  // "<source>: binary block of the dataset at line <line>, byte <offset>: <expected>"; offset counts
  // from the first byte of the block.
  FrfFileError(const std::string& source, int line, std::size_t block_offset, const std::string& expected);

  const std::string& source() const { return source_; }
  int line() const { return line_; }
  std::optional<std::size_t> blockOffset() const { return block_offset_; }

 private:
  std::string source_;
  int line_ = 0;
  std::optional<std::size_t> block_offset_;
};

}  // namespace mx
