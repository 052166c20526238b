#pragma once
// Files from outside (projects, part programs, tap tests, tool libraries) are read whole, so each kind
// has a maximum size, checked before a byte is read. Only a regular file is read: a device never ends
// (/dev/zero), a FIFO blocks, and opening some devices has effects of its own, so their type is checked
// before they are opened.
#include <cstdint>
#include <string>
#include <string_view>

namespace mx {

inline constexpr std::uint64_t kMegabyte = 1024 * 1024;  // "MB" in every limit and message

struct InputFileLimit {
  std::uint64_t max_bytes = 0;
  std::string_view kind;  // "a part program", named in the refusal
};

// The whole content of the regular file at `path`. Throws InvalidInput whose message leaves the path
// to the caller: "cannot be read (expected a readable file)", "a FIFO, not a regular file: a part
// program must be a regular file", "80.0 MB (83886080 bytes) is over the 16 MB limit of a part program".
std::string readInputFile(const std::string& path, const InputFileLimit& limit);

// "a directory", "a character device", "a block device", "a FIFO", "a socket", "a symbolic link" or
// "not a regular file", for a st_mode that is not a regular file's.
std::string_view nonRegularFileKind(unsigned mode);

}  // namespace mx
