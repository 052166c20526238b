// Fuzz target of the batch results reader (mergeBatchResults over one JSON Lines file, as batch-merge
// and the GUI's results table read them; docs/shop-scale.md, "Merge"). A refused file throws
// InputError (a bad line before the last) or ComputationError (two results for one hash); an accepted
// one gives a summary whose counts are non-negative and whose table lines all have the header's
// columns.
#include <QFile>
#include <QTemporaryDir>
#include <cstdint>

#include "fuzz_check.h"
#include "services/batch_merge.h"
#include "services/service_errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::fuzz::require;
  static QTemporaryDir dir;
  const QString path = dir.filePath("results.jsonl");
  {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) return 0;
    f.write(reinterpret_cast<const char*>(data), static_cast<qint64>(size));
  }
  QJsonObject summary;
  try {
    summary = mx::app::mergeBatchResults({path});
  } catch (const mx::app::InputError&) {
    return 0;
  } catch (const mx::app::ComputationError&) {
    return 0;
  }
  for (const char* key : {"cases", "duplicates", "failed", "torn_lines"})
    require(summary.value(key).toInteger(-1) >= 0, "the summary's counts are numbers >= 0");
  const qsizetype columns = mx::app::batchTableHeader().size();
  for (const QStringList& line : mx::app::batchTableLines(summary))
    require(line.size() == columns, "every table line has the header's columns");
  return 0;
}
