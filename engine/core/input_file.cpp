#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "core/invalid_input.h"

namespace mx {

namespace {

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / static_cast<double>(kMegabyte));
  return text;
}

[[noreturn]] void tooLarge(std::uint64_t bytes, const InputFileLimit& limit) {
  throw InvalidInput(megabytes(bytes) + " (" + std::to_string(bytes) + " bytes) is over the " +
                     std::to_string(limit.max_bytes / kMegabyte) + " MB limit of " + std::string(limit.kind));
}

void requireRegular(unsigned mode, const InputFileLimit& limit) {
  if (S_ISREG(mode)) return;
  throw InvalidInput(std::string(nonRegularFileKind(mode)) + ", not a regular file: " + std::string(limit.kind) +
                     " must be a regular file");
}

}  // namespace

std::string_view nonRegularFileKind(unsigned mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}

std::string readInputFile(const std::string& path, const InputFileLimit& limit) {
  const char* unreadable = "cannot be read (expected a readable file)";
  struct stat before {};
  if (::stat(path.c_str(), &before) != 0) throw InvalidInput(unreadable);
  requireRegular(before.st_mode, limit);
  if (static_cast<std::uint64_t>(before.st_size) > limit.max_bytes) tooLarge(before.st_size, limit);
  // O_NONBLOCK: should the path have become a FIFO since, opening it does not wait for a writer.
  const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) throw InvalidInput(unreadable);
  struct stat opened {};
  if (::fstat(fd.get(), &opened) != 0) throw InvalidInput(unreadable);
  requireRegular(opened.st_mode, limit);
  std::string data;
  data.reserve(static_cast<std::size_t>(opened.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InvalidInput(unreadable);
    if (n == 0) break;
    data.append(buffer, static_cast<std::size_t>(n));
    if (data.size() > limit.max_bytes) tooLarge(data.size(), limit);  // it grew while being read
  }
  return data;
}

}  // namespace mx
