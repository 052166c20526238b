#pragma once
// Values echoed in messages (ids, flags, paths, JSON values) are the user's, and may be megabytes long:
// a message shows at most kMaxEchoedCharacters of one, its start, and says how long it was.
#include <QString>

namespace mx::app {

inline constexpr qsizetype kMaxEchoedCharacters = 80;

// The text itself up to 80 characters, else "aaaa…" (its first 80 characters and a mark) followed by
// " (10485760 characters)"; quoted: the same inside quotes, the length outside them ("'aaaa…' (… characters)").
QString shortened(const QString& text);
QString quoted(const QString& text, QChar quote = u'\'');

}  // namespace mx::app
