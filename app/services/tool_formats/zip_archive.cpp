#include "services/tool_formats/zip_archive.h"

#include <zip.h>

#include <QStringList>
#include <algorithm>
#include <cstdio>
#include <memory>

#include "document/shortened_text.h"

namespace mx::app {
namespace {

// 2020-01-01 00:00 UTC: the time stamp of every written entry, so that the bytes depend on the data only.
constexpr time_t kEntryTime = 1577836800;

struct ZipDiscard {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
struct ZipSourceFree {
  void operator()(zip_source_t* source) const { zip_source_free(source); }
};
struct ZipFileClose {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};
using ZipHandle = std::unique_ptr<zip_t, ZipDiscard>;
using ZipSourceHandle = std::unique_ptr<zip_source_t, ZipSourceFree>;
using ZipFileHandle = std::unique_ptr<zip_file_t, ZipFileClose>;

// libzip's zip_error_t, released on every path.
class ZipErrorText {
 public:
  ZipErrorText() { zip_error_init(&error_); }
  ~ZipErrorText() { zip_error_fini(&error_); }
  ZipErrorText(const ZipErrorText&) = delete;
  ZipErrorText& operator=(const ZipErrorText&) = delete;
  zip_error_t* get() { return &error_; }
  QString text() { return QString::fromUtf8(zip_error_strerror(&error_)); }

 private:
  zip_error_t error_;
};

[[noreturn]] void fail(const QString& what) {
  throw ZipArchiveError(what);
}

ZipHandle openForReading(const QByteArray& archive) {
  ZipErrorText error;
  ZipSourceHandle source(
      zip_source_buffer_create(archive.constData(), static_cast<zip_uint64_t>(archive.size()), 0, error.get()));
  if (!source) fail(QString("not a readable zip archive (libzip: %1)").arg(error.text()));
  ZipHandle zip(zip_open_from_source(source.get(), ZIP_RDONLY | ZIP_CHECKCONS, error.get()));
  if (!zip) fail(QString("not a readable zip archive (libzip: %1)").arg(error.text()));
  static_cast<void>(source.release());  // the archive owns its source now
  return zip;
}

bool isJsonName(const QString& name) {
  return name.endsWith(".json", Qt::CaseInsensitive);
}

// The index of the one ".json" entry, after the count and names are checked.
zip_uint64_t singleJsonEntry(zip_t* zip) {
  const zip_int64_t count = zip_get_num_entries(zip, 0);
  if (count < 0) fail(QString("not a readable zip archive (libzip: %1)").arg(zip_strerror(zip)));
  if (count > kMaxZipEntries)
    fail(QString("the archive has %1 entries; at most %2 are read").arg(count).arg(kMaxZipEntries));
  QStringList names;
  QStringList json_names;
  zip_uint64_t found = 0;
  for (zip_uint64_t i = 0; i < static_cast<zip_uint64_t>(count); ++i) {
    const char* raw = zip_get_name(zip, i, ZIP_FL_ENC_GUESS);
    if (raw == nullptr) fail("unreadable entry name: " + QString::fromUtf8(zip_strerror(zip)));
    const QString name = QString::fromUtf8(raw);
    names << quoted(name);
    if (!isJsonName(name)) continue;
    json_names << quoted(name);
    found = i;
  }
  if (json_names.isEmpty())
    fail(names.isEmpty() ? QString("the archive is empty")
                         : QString("the archive holds no .json entry (entries: %1)").arg(shortened(names.join(", "))));
  if (json_names.size() > 1)
    fail(QString("the archive holds %1 .json entries (%2); a tool library holds one")
             .arg(json_names.size())
             .arg(shortened(json_names.join(", "))));
  return found;
}

zip_stat_t checkedStat(zip_t* zip, zip_uint64_t index) {
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(zip, index, 0, &stat) != 0) fail("unreadable entry: " + QString::fromUtf8(zip_strerror(zip)));
  const QString name = quoted(QString::fromUtf8(stat.name ? stat.name : ""));
  if ((stat.valid & ZIP_STAT_SIZE) == 0) fail(QString("entry %1 declares no size").arg(name));
  if (stat.size > static_cast<zip_uint64_t>(kMaxZipEntryBytes))
    fail(QString("entry %1 inflates to %2 bytes; at most %3 (64 MB) are read")
             .arg(name)
             .arg(stat.size)
             .arg(kMaxZipEntryBytes));
  if ((stat.valid & ZIP_STAT_ENCRYPTION_METHOD) != 0 && stat.encryption_method != ZIP_EM_NONE)
    fail(QString("entry %1 is encrypted").arg(name));
  if ((stat.valid & ZIP_STAT_COMP_METHOD) != 0 && zip_compression_method_supported(stat.comp_method, 0) == 0)
    fail(QString("entry %1 uses compression method %2, which this build cannot inflate")
             .arg(name)
             .arg(stat.comp_method));
  return stat;
}

// Reads the declared size and one byte more, in chunks, so that memory follows the data actually
// inflated, not what a header claims: libzip checks the CRC at the end of the data, and a stream
// longer than declared is refused without inflating it further.
QByteArray readEntry(zip_t* zip, zip_uint64_t index, const zip_stat_t& stat) {
  const QString name = quoted(QString::fromUtf8(stat.name ? stat.name : ""));
  ZipFileHandle file(zip_fopen_index(zip, index, 0));
  if (!file) fail(QString("entry %1 cannot be opened: %2").arg(name, QString::fromUtf8(zip_strerror(zip))));
  const auto declared = static_cast<qsizetype>(stat.size);
  constexpr qsizetype kChunk = 1 << 16;
  QByteArray chunk(kChunk, Qt::Uninitialized);
  QByteArray data;
  while (data.size() <= declared) {
    const qsizetype wanted = std::min(kChunk, declared + 1 - data.size());
    const zip_int64_t got = zip_fread(file.get(), chunk.data(), static_cast<zip_uint64_t>(wanted));
    if (got < 0) fail(QString("entry %1 is corrupt: %2").arg(name, QString::fromUtf8(zip_file_strerror(file.get()))));
    if (got == 0) break;
    data.append(chunk.constData(), static_cast<qsizetype>(got));
  }
  if (data.size() > declared)
    fail(QString("entry %1 holds more than the %2 bytes its header declares").arg(name).arg(declared));
  if (data.size() < declared)
    fail(QString("entry %1 holds %2 bytes, not the %3 its header declares").arg(name).arg(data.size()).arg(declared));
  return data;
}

QByteArray sourceBytes(zip_source_t* source) {
  if (zip_source_open(source) != 0) fail("cannot read the written archive");
  QByteArray out;
  bool ok = zip_source_seek(source, 0, SEEK_END) == 0;
  const zip_int64_t size = ok ? zip_source_tell(source) : -1;
  ok = ok && size >= 0 && zip_source_seek(source, 0, SEEK_SET) == 0;
  if (ok) {
    out.resize(static_cast<qsizetype>(size));
    ok = zip_source_read(source, out.data(), static_cast<zip_uint64_t>(size)) == size;
  }
  zip_source_close(source);
  if (!ok) fail("cannot read the written archive");
  return out;
}

}  // namespace

bool looksLikeZip(const QByteArray& bytes) {
  return bytes.startsWith(QByteArray("PK\x03\x04", 4)) || bytes.startsWith(QByteArray("PK\x05\x06", 4));
}

QByteArray readSingleJsonEntry(const QByteArray& archive) {
  const ZipHandle zip = openForReading(archive);
  const zip_uint64_t index = singleJsonEntry(zip.get());
  return readEntry(zip.get(), index, checkedStat(zip.get(), index));
}

QByteArray writeSingleEntryZip(const QString& name, const QByteArray& data) {
  ZipErrorText error;
  ZipSourceHandle target(zip_source_buffer_create(nullptr, 0, 0, error.get()));
  if (!target) fail("cannot create the archive: " + error.text());
  ZipHandle zip(zip_open_from_source(target.get(), ZIP_TRUNCATE, error.get()));
  if (!zip) fail("cannot create the archive: " + error.text());
  zip_source_keep(target.get());  // the archive takes one reference; ours stays for reading the bytes
  auto fail_with_zip = [&zip](const char* what) { fail(QString("%1: %2").arg(what, zip_strerror(zip.get()))); };
  zip_source_t* entry = zip_source_buffer(zip.get(), data.constData(), static_cast<zip_uint64_t>(data.size()), 0);
  if (entry == nullptr) fail_with_zip("cannot add the entry");
  const QByteArray utf8_name = name.toUtf8();
  const zip_int64_t index = zip_file_add(zip.get(), utf8_name.constData(), entry, ZIP_FL_ENC_UTF_8);
  if (index < 0) {
    zip_source_free(entry);
    fail_with_zip("cannot add the entry");
  }
  const auto at = static_cast<zip_uint64_t>(index);
  if (zip_set_file_compression(zip.get(), at, ZIP_CM_DEFLATE, 9) != 0) fail_with_zip("cannot set the compression");
  if (zip_file_set_mtime(zip.get(), at, kEntryTime, 0) != 0) fail_with_zip("cannot set the time stamp");
  if (zip_close(zip.get()) != 0) fail_with_zip("cannot write the archive");
  static_cast<void>(zip.release());  // closed: freed by zip_close
  return sourceBytes(target.get());
}

}  // namespace mx::app
