#include "modal_fit/lscf_diagram.h"

#include <algorithm>

#include "modal_fit/lscf.h"

namespace mx {

StabilisationDiagram lscfDiagram(const FrfBand& band, int max_order, const StabilityCriteria& criteria,
                                 const JobControl& job) {
  const int top = std::max(max_order, 2);
  const LscfEstimator estimator(band, top);
  StabilisationDiagram diagram;
  for (int order = 2; order <= top; ++order) {
    if (job.cancelled()) throw Cancelled();
    DiagramOrder row{order, physicalPoles(estimator.poles(order), band.from_hz, band.to_hz, criteria)};
    if (!diagram.orders.empty()) classifyPoles(row.poles, diagram.orders.back().poles, criteria);
    diagram.orders.push_back(std::move(row));
    job.report(static_cast<double>(order - 1) / static_cast<double>(top - 1));
  }
  return diagram;
}

}  // namespace mx
