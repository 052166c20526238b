#pragma once
// The materials library's entries as the machine and operation panel's picker offers them: the
// project's copy of each entry, with its ISO group and a tooltip of its values and their sources.
#include <QList>
#include <vector>

#include "material_choice.h"
#include "services/material_library.h"

namespace mx::gui {

QList<widgets::MaterialChoice> materialChoices(const std::vector<app::MaterialEntry>& library);

// The bundled library's choices; none (and a warning on stderr) if this build lacks it.
QList<widgets::MaterialChoice> bundledMaterialChoices();

}  // namespace mx::gui
