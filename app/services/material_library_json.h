#pragma once
// The materials library written back as JSON: one entry as the CLI lists it, and a whole library file
// that parseMaterialLibrary reads back to the same entries.
#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <vector>

#include "services/material_library.h"

namespace mx::app {

// {"id", "name", "iso_group", "Kt_N_mm2", "Kr", the optional numbers it has, "sources": {key: {...}}}.
QJsonObject materialEntryJson(const MaterialEntry& entry);
QJsonArray materialEntriesJson(const std::vector<MaterialEntry>& entries);
// {"format": "millexpert-materials", "version": 1, "materials": [...]}, indented.
QByteArray materialLibraryJson(const std::vector<MaterialEntry>& entries);

}  // namespace mx::app
