#pragma once
// FRF files written by MillExpert (File > Export FRF, millexpert-cli frf-export): a tool's modes or
// measured FRF as UFF 58, 58b or CSV, as receptance, mobility or accelerance.
#include <QString>
#include <optional>
#include <vector>

#include "document/project.h"
#include "frf/frf_dataset.h"

namespace mx::app {

// "uff58" | "uff58b" | "csv"; InputError naming `field` otherwise.
FrfFormat frfFormatFromName(const QString& field, const QString& name);

// One tool axis, "x" or "y".
FrfDirection frfAxisFromName(const QString& field, const QString& name);

// Writes atomically (writeFileAtomically: only a regular file or a new one). A CSV holds one dataset.
// InputError naming the path when it cannot be written or the CSV would hold several datasets.
void saveFrfFile(const QString& path, FrfFormat format, const std::vector<FrfDataset>& datasets);

}  // namespace mx::app
