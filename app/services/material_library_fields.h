#pragma once
// The optional numbers of a materials-library entry: their keys, the project rule each must pass, and
// where the entry keeps them. The reader and the writer walk the same list, so that they agree.
#include <array>
#include <optional>

#include "document/project_rules.h"
#include "services/material_library.h"

namespace mx::app {

struct MaterialNumberField {
  const char* key;
  NumberRule rule;
  std::optional<double> MaterialEntry::*member;
};

// Kienzle's exponent mc: the specific force kc1.1 h^-mc must fall as the chip thickens, and
// F_t / b = kc1.1 h^(1 - mc) must still grow, so 0 <= mc < 1.
inline constexpr NumberRule kKienzleExponent{NumberRule::Bound::Closed, 0.0, NumberRule::Bound::Open, 1.0, false};

inline constexpr std::array<MaterialNumberField, 7> kOptionalMaterialNumbers{{
    {"Kte_N_mm", rules::kEdgeForceNmm, &MaterialEntry::Kte_N_mm},
    {"Kre_N_mm", rules::kEdgeForceNmm, &MaterialEntry::Kre_N_mm},
    {"Ka_N_mm2", rules::kAxialPressureNmm2, &MaterialEntry::Ka_N_mm2},
    {"Kae_N_mm", rules::kEdgeForceNmm, &MaterialEntry::Kae_N_mm},
    {"process_damping_N_per_m", rules::kProcessDampingNm, &MaterialEntry::process_damping_N_per_m},
    {"kc11_N_mm2", rules::kCuttingPressureNmm2, &MaterialEntry::kc11_N_mm2},
    {"mc", kKienzleExponent, &MaterialEntry::mc},
}};

}  // namespace mx::app
