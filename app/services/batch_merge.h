#pragma once
// batch-merge: the results lines of one manifest, from any number of files (shards, reruns), as one
// table with a row per project x machine x material x operation (docs/shop-scale.md, "Merge"):
//   rank: the selected tool and q*; pareto: the tool and q; lobes: the best pocket of each tool;
//   point: the verdict of each tool.
// A case (hash) found in several files counts once; two different results for one hash are an error.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <vector>

namespace mx::app {

// Reads the results files one line at a time, keeping per case only what its row shows and a digest
// of its result. {"computation", "files", "cases", "duplicates", "failed", "torn_lines", "rows": [...]}.
// Throws ComputationError (exit 1) naming the hash and both places when one hash has two different
// results, InputError (exit 2) for a bad line before a file's last.
QJsonObject mergeBatchResults(const QStringList& paths);

// The summary's rows flattened to one line per row and tool, for CSV and HTML: batchTableHeader() columns.
QStringList batchTableHeader();
std::vector<QStringList> batchTableLines(const QJsonObject& summary);

}  // namespace mx::app
