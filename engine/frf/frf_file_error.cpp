#include "frf/frf_file_error.h"

namespace mx {
namespace {

std::string lineMessage(const std::string& source, int line, const std::string& expected) {
  if (line <= 0) return source + ": " + expected;
  return source + ": line " + std::to_string(line) + ": " + expected;
}

std::string blockMessage(const std::string& source, int line, std::size_t offset, const std::string& expected) {
  return source + ": binary block of the dataset at line " + std::to_string(line) + ", byte " + std::to_string(offset) +
         ": " + expected;
}

}  // namespace

FrfFileError::FrfFileError(const std::string& source, int line, const std::string& expected)
    : std::runtime_error(lineMessage(source, line, expected)), source_(source), line_(line) {}

FrfFileError::FrfFileError(const std::string& source, int line, std::size_t block_offset, const std::string& expected)
    : std::runtime_error(blockMessage(source, line, block_offset, expected)),
      source_(source),
      line_(line),
      block_offset_(block_offset) {}

}  // namespace mx
