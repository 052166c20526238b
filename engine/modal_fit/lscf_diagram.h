#pragma once
// The LSCF stabilisation diagram over model orders 2 .. max_order (lscf.h, stabilisation.h).
#include "core/cancellation.h"
#include "modal_fit/frf_band.h"
#include "modal_fit/stabilisation.h"

namespace mx {

// Reports progress over the orders; throws Cancelled when job is cancelled between orders.
StabilisationDiagram lscfDiagram(const FrfBand& band, int max_order, const StabilityCriteria& criteria = {},
                                 const JobControl& job = {});

}  // namespace mx
