#pragma once
// An entry of the materials library as the machine and operation panel offers it. The GUI host fills
// these from the library (app/services/material_library.h), which the widgets do not link.
#include <QString>
#include <QStringList>

#include "document/project.h"

namespace mx::widgets {

struct MaterialChoice {
  QString iso_group;           // ISO 513 group, shown next to the name
  QString tooltip;             // the entry's values and how far their sources were checked
  app::MaterialSpec material;  // the project's copy of the entry: library = the entry's id
};

// The fields of `material` whose values differ from those of the library entry `entry` ("name",
// "K_t", "K_te", ...), in the panel's order; the library id is not compared.
QStringList editedMaterialFields(const app::MaterialSpec& material, const app::MaterialSpec& entry);

}  // namespace mx::widgets
