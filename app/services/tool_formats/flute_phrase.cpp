#include "services/tool_formats/flute_phrase.h"

#include <QRegularExpression>

#include "document/project_rules.h"
#include "document/shortened_text.h"

namespace mx::app {

namespace {

const QRegularExpression& phrasePattern() {
  static const QRegularExpression pattern(
      QStringLiteral(R"((?<![\w.,])([0-9]{1,4})\s*-?\s*(?:flutes|fluted|flute|flts|flt|fl|teeth|tooth)(?![a-z]))"),
      QRegularExpression::CaseInsensitiveOption);
  return pattern;
}

}  // namespace

FlutePhrase flutePhrase(const QString& comment) {
  FlutePhrase result;
  QString first;
  QRegularExpressionMatchIterator it = phrasePattern().globalMatch(comment);
  while (it.hasNext()) {
    const QRegularExpressionMatch match = it.next();
    const int count = match.captured(1).toInt();
    if (!rules::kTeeth.accepts(count))
      return {std::nullopt, QString("%1: %2").arg(quoted(match.captured(0)), rules::kTeeth.mustBe(count))};
    if (result.count && *result.count != count)
      return {std::nullopt, QString("%1 and %2 disagree").arg(quoted(first), quoted(match.captured(0)))};
    if (!result.count) first = match.captured(0);
    result.count = count;
  }
  return result;
}

QString withFluteCount(const QString& comment, int teeth) {
  QString out;
  qsizetype done = 0;
  QRegularExpressionMatchIterator it = phrasePattern().globalMatch(comment);
  while (it.hasNext()) {
    const QRegularExpressionMatch match = it.next();
    out += comment.mid(done, match.capturedStart(1) - done) + QString::number(teeth);
    done = match.capturedEnd(1);
  }
  return out + comment.mid(done);
}

}  // namespace mx::app
