#pragma once
// What the stability chart's model is and when the ZOA is only approximate for a tool, as text.
#include <QString>

#include "model/milling_setup.h"
#include "stability/lobe_computation.h"

namespace mx::widgets {

// "SDM, 4 teeth, variable pitch, 30° helix" or "ZOA, 3 teeth, uniform pitch".
QString modelLabel(StabilityMethod method, const MillingSetup& setup);

// With the ZOA and a tool it approximates (variable pitch, helix, an intermittent cut: zoaValidity,
// engine/stability/zoa_validity.h; or process damping, which it leaves out):
// "ZOA: approximate for this tool (variable pitch, 30° helix); SDM models pitch, helix and process damping".
// "" with the SDM or when the ZOA fits.
QString methodAdvice(StabilityMethod method, const MillingSetup& setup);

}  // namespace mx::widgets
