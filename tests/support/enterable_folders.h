#pragma once
// Test helper for services started by a test (postgres_server.h, cli.batch_slurm): a daemon that runs
// as another user (postgres) or checks the path to its socket (munged) needs every folder above its
// files to be enterable by all. The runner's TMPDIR may be a 0700 `mktemp -d`, so the folders from
// `folder` up to / that lack it get the search permission for group and others (munged requires
// both; search only: nothing is listed).
#include <sys/stat.h>

#include <QDir>
#include <QFile>
#include <QString>

namespace mx::test {

inline void makeEnterableByAll(const QString& folder) {
  for (QDir d(folder); !d.isRoot(); d.cdUp()) {
    struct stat info {};
    const QByteArray path = QFile::encodeName(d.absolutePath());
    constexpr mode_t kSearch = S_IXGRP | S_IXOTH;
    if (::stat(path.constData(), &info) == 0 && (info.st_mode & kSearch) != kSearch)
      ::chmod(path.constData(), (info.st_mode & 07777) | kSearch);
  }
}

}  // namespace mx::test
