#pragma once
// The flute count a LinuxCNC tool comment states: "3FL", "3 FL", "3 flt", "3 flutes", "3-flute",
// "2 fluted", "4 teeth" (any case). The number stands alone: "1.5FL" and "x3FL" state no count.
#include <QString>
#include <optional>

namespace mx::app {

struct FlutePhrase {
  std::optional<int> count;  // the stated count (every phrase of the comment states the same)
  QString problem;           // "'0FL': must be an integer in [1, 100]", "'2FL' and '3 flutes' disagree"
};
FlutePhrase flutePhrase(const QString& comment);

// The comment with the number of each flute phrase set to `teeth` ("6mm 3FL" -> "6mm 4FL"); a comment
// without a phrase is returned unchanged.
QString withFluteCount(const QString& comment, int teeth);

}  // namespace mx::app
