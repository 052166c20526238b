#pragma once
// Test helper: makes a folder read-only for the calling thread while the guard lives. Mode 0555 alone
// stops nothing when the tests run as root (CAP_DAC_OVERRIDE bypasses the mode), so as root the
// calling thread also drops CAP_DAC_OVERRIDE from its effective capabilities; capabilities are per
// thread, and the guard raises it again (it stays in the permitted set) when it ends. writable()
// probes the result, so that a test can refuse to pass untested.
#include <linux/capability.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <QDir>
#include <QFile>
#include <QString>

namespace mx::test {

class ReadOnlyFolder {
 public:
  explicit ReadOnlyFolder(const QString& path) : path_(path) {
    QFile::setPermissions(path_, QFile::ReadOwner | QFile::ExeOwner | QFile::ReadGroup | QFile::ExeGroup |
                                     QFile::ReadOther | QFile::ExeOther);
    if (::geteuid() == 0) dropped_ = setDacOverride(false);
  }
  ~ReadOnlyFolder() {
    if (dropped_) setDacOverride(true);
    QFile::setPermissions(path_, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup |
                                     QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther);
  }
  ReadOnlyFolder(const ReadOnlyFolder&) = delete;
  ReadOnlyFolder& operator=(const ReadOnlyFolder&) = delete;

  bool asRoot() const { return dropped_; }
  // Whether a new file can still be created in the folder.
  bool writable() const {
    QFile probe(QDir(path_).filePath("probe"));
    if (!probe.open(QIODevice::WriteOnly)) return false;
    probe.remove();
    return true;
  }

 private:
  // Sets or clears CAP_DAC_OVERRIDE in the calling thread's effective set; true when done.
  static bool setDacOverride(bool on) {
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2]{};
    if (::syscall(SYS_capget, &header, data) != 0) return false;
    const unsigned bit = 1u << CAP_DAC_OVERRIDE;
    data[0].effective = on ? (data[0].effective | bit) : (data[0].effective & ~bit);
    return ::syscall(SYS_capset, &header, data) == 0;
  }

  QString path_;
  bool dropped_ = false;
};

}  // namespace mx::test
