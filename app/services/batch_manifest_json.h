#pragma once
// The batch manifest written back as the fixed JSON interface (docs/shop-scale.md): what File > Batch
// study saves. readBatchManifest() of the written file gives the same manifest.
#include <QJsonObject>

#include "services/batch_manifest.h"

namespace mx::app {

// {"computation", "projects", ["tools"], ["machines"], ["materials"], ["operations"], ["options"]}:
// the optional lists only when present (an absent list means the project's own section).
QJsonObject batchManifestJson(const BatchManifest& manifest);

}  // namespace mx::app
