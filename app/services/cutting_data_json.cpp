#include "services/cutting_data_json.h"

namespace mx::app {

QJsonObject cuttingDataJson(const MillingSetup& setup) {
  return {{"Kt_N_mm2", setup.tangential_coefficient_pa * 1e-6},      {"Kr", setup.radial_ratio},
          {"Kte_N_mm", setup.tangential_edge_n_per_m * 1e-3},        {"Kre_N_mm", setup.radial_edge_n_per_m * 1e-3},
          {"Ka_N_mm2", setup.axial_coefficient_pa * 1e-6},           {"Kae_N_mm", setup.axial_edge_n_per_m * 1e-3},
          {"process_damping_N_per_m", setup.process_damping_n_per_m}};
}

QString processDampingNote(StabilityMethod method, const MillingSetup& setup) {
  if (method != StabilityMethod::ZeroOrder || setup.process_damping_n_per_m == 0.0) return {};
  return QString(
             "the zero-order approximation leaves out the process damping (material.process_damping_N_per_m = %1 "
             "N/m): its lobes do not rise at low speed; the semi-discretization (method sdm) includes it")
      .arg(setup.process_damping_n_per_m);
}

}  // namespace mx::app
