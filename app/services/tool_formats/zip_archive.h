#pragma once
// An in-memory zip archive holding one JSON document (Fusion 360's `.tools` library is a zip of its
// JSON library), over libzip. Reading is bounded before any inflating: at most kMaxZipEntries entries,
// and the entry's declared uncompressed size at most kMaxZipEntryBytes (a zip bomb is refused from its
// central directory, and libzip's CRC and length checks refuse an entry whose data disagrees with it).
#include <QByteArray>
#include <QString>
#include <stdexcept>

namespace mx::app {

inline constexpr qint64 kMaxZipEntryBytes = 64ll * 1024 * 1024;
inline constexpr qint64 kMaxZipEntries = 1000;

// What is wrong with the archive, in words for the user ("the archive holds no .json entry").
class ZipArchiveError : public std::runtime_error {
 public:
  explicit ZipArchiveError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

// True when the bytes start as a zip archive does: a local file header ("PK\3\4") or, for an archive
// without entries, the end of central directory record ("PK\5\6").
bool looksLikeZip(const QByteArray& bytes);

// The data of the archive's one entry whose name ends in ".json" (any case); throws ZipArchiveError
// when the archive is unreadable, holds no such entry or more than one, or the entry is encrypted,
// larger than kMaxZipEntryBytes or corrupt.
QByteArray readSingleJsonEntry(const QByteArray& archive);

// An archive of one deflated entry `name` holding `data`, with a fixed time stamp so that the same
// data gives the same bytes. Throws ZipArchiveError when libzip fails.
QByteArray writeSingleEntryZip(const QString& name, const QByteArray& data);

}  // namespace mx::app
