#include "document/shortened_text.h"

namespace mx::app {

namespace {

QString lengthNote(const QString& text) {
  return QString(" (%1 characters)").arg(text.size());
}

// The first 80 characters; a surrogate pair is kept whole so that the cut stays valid UTF-16.
QString head(const QString& text) {
  qsizetype n = kMaxEchoedCharacters;
  if (text.at(n - 1).isHighSurrogate()) --n;
  return text.left(n) + QChar(0x2026);
}

}  // namespace

QString shortened(const QString& text) {
  if (text.size() <= kMaxEchoedCharacters) return text;
  return head(text) + lengthNote(text);
}

QString quoted(const QString& text, QChar quote) {
  if (text.size() <= kMaxEchoedCharacters) return quote + text + quote;
  return quote + head(text) + quote + lengthNote(text);
}

}  // namespace mx::app
