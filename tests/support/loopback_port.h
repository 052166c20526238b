#pragma once
// Test helper: a TCP socket bound to a port of 127.0.0.1 that the kernel picks, held until destroyed.
// Bound only, it reserves the port (several held at once are distinct); listening, it accepts
// connections into the kernel's backlog and never answers, so a PostgreSQL client waits there for its
// connect_timeout.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mx::test {

class LoopbackPort {
 public:
  enum class Mode { Bound, Listening };

  explicit LoopbackPort(Mode mode = Mode::Bound) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t n = sizeof a;
    if (fd_ >= 0 && ::bind(fd_, reinterpret_cast<sockaddr*>(&a), n) == 0 &&
        (mode == Mode::Bound || ::listen(fd_, 16) == 0) && ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &n) == 0)
      port_ = ntohs(a.sin_port);
  }
  ~LoopbackPort() {
    if (fd_ >= 0) ::close(fd_);
  }
  LoopbackPort(const LoopbackPort&) = delete;
  LoopbackPort& operator=(const LoopbackPort&) = delete;

  int port() const { return port_; }  // 0 when no port could be had

 private:
  int fd_;
  int port_ = 0;
};

// A port of 127.0.0.1 that was free a moment ago (reserved, then released).
inline int freeLoopbackPort() {
  return LoopbackPort().port();
}

}  // namespace mx::test
