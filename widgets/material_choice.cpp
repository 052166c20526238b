#include "material_choice.h"

namespace mx::widgets {

QStringList editedMaterialFields(const app::MaterialSpec& material, const app::MaterialSpec& entry) {
  QStringList edited;
  const auto compare = [&](const char* name, const auto& a, const auto& b) {
    if (a != b) edited << QString::fromLatin1(name);
  };
  compare("name", material.name, entry.name);
  compare("K_t", material.Kt_N_mm2, entry.Kt_N_mm2);
  compare("K_r", material.Kr, entry.Kr);
  compare("K_te", material.Kte_N_mm, entry.Kte_N_mm);
  compare("K_re", material.Kre_N_mm, entry.Kre_N_mm);
  compare("K_a", material.Ka_N_mm2, entry.Ka_N_mm2);
  compare("K_ae", material.Kae_N_mm, entry.Kae_N_mm);
  compare("C_i", material.process_damping_N_per_m, entry.process_damping_N_per_m);
  return edited;
}

}  // namespace mx::widgets
