#pragma once
// Promises shared by the tool-library targets (tool_csv, tool_json): every number of an accepted
// tool is finite, and the tools satisfy validateTools, the rules a project applies to its library.
#include <cstdio>
#include <vector>

#include "document/project.h"
#include "document/project_validation.h"
#include "fuzz_check.h"

namespace mx::fuzz {

inline void requireFiniteTool(const app::ToolSpec& t) {
  const char* what = "an accepted tool holds finite numbers only";
  for (const double v : {t.diameter_mm, t.helix_deg}) requireFinite(v, what);
  for (const auto& v : {t.Kt_N_mm2, t.Kr, t.Kte_N_mm, t.Kre_N_mm, t.Ka_N_mm2, t.Kae_N_mm, t.radial_depth_mm,
                        t.max_force_N, t.flute_length_mm, t.overall_length_mm, t.stickout_mm, t.corner_radius_mm})
    if (v) requireFinite(*v, what);
  for (const app::CuttingPresetSpec& p : t.cutting_data)
    for (const auto& v :
         {p.speed_rpm, p.surface_speed_m_min, p.feed_per_tooth_mm, p.feed_mm_min, p.axial_depth_mm, p.radial_depth_mm})
      if (v) requireFinite(*v, what);
  for (const auto& list : {t.pitch_deg, t.runout_um})
    if (list)
      for (const double v : *list) requireFinite(v, what);
  for (const auto* modes : {&t.modes_x, &t.modes_y})
    for (const app::ModeSpec& m : *modes)
      for (const double v : {m.freq_Hz, m.damping_pct, m.stiffness_N_per_um}) requireFinite(v, what);
}

inline void requireValidTools(const std::vector<app::ToolSpec>& tools) {
  for (const app::ToolSpec& t : tools) requireFiniteTool(t);
  try {
    app::validateTools(tools, std::nullopt);
  } catch (const app::ProjectError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    brokenPromise("accepted tools pass validateTools");
  }
}

}  // namespace mx::fuzz
