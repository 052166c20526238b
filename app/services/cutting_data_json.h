#pragma once
// The cutting coefficients a computation used (the tool's overrides over the material), for the CLI's
// JSON and the GUI: in the project file's units, and the note that the ZOA leaves out process damping.
#include <QJsonObject>
#include <QString>

#include "model/milling_setup.h"
#include "stability/lobe_computation.h"

namespace mx::app {

// {"Kt_N_mm2", "Kr", "Kte_N_mm", "Kre_N_mm", "Ka_N_mm2", "Kae_N_mm", "process_damping_N_per_m"}.
QJsonObject cuttingDataJson(const MillingSetup& setup);

// Empty unless the method leaves out the setup's process damping (the ZOA; docs/fidelity.md, "Process
// damping"); then a sentence that says so and names the method that includes it.
QString processDampingNote(StabilityMethod method, const MillingSetup& setup);

}  // namespace mx::app
