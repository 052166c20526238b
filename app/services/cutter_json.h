#pragma once
// The cutter geometry a computation used, for the CLI's JSON and the reports: teeth, the pitch of each
// tooth (uniform or not), the helix and the runout, in the project file's units.
#include <QJsonObject>

#include "model/milling_setup.h"

namespace mx::app {

// {"teeth", "pitch": "uniform"|"variable", "pitch_deg": [...], "helix_deg", "runout_um": [...],
//  "principal_period": "tooth"|"revolution"}; runout_um only when a runout is set.
QJsonObject cutterJson(const MillingSetup& setup);

}  // namespace mx::app
