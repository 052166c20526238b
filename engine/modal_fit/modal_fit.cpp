#include "modal_fit/modal_fit.h"

#include <algorithm>

#include "modal_fit/fit_error.h"
#include "modal_fit/frf_band.h"
#include "modal_fit/lscf_diagram.h"
#include "modal_fit/lsfd.h"
#include "modal_fit/modal_pole.h"
#include "modal_fit/mode_selection.h"
#include "modal_fit/nlls_refinement.h"
#include "modal_fit/peak_picking.h"

namespace mx {
namespace {

constexpr double kDiagramProgress = 0.8;

// LSFD residues of the poles, then the NLLS refinement when asked for.
FittedModel fitPoles(const FrfBand& band, const std::vector<std::complex<double>>& poles,
                     const ModalFitSettings& settings, const JobControl& job, ModalFitResult& result) {
  if (job.cancelled()) throw Cancelled();
  FittedModel model = fittedModel(poles, fitResidues(band, poles));
  result.method = "LSCF + LSFD";
  job.report(0.9);
  if (settings.refine && !model.modes.empty()) {
    model = refineModel(band, model, job);
    if (job.cancelled()) throw Cancelled();
    result.method += " + NLLS";
  }
  return model;
}

FittedModel lscfModel(const FrfBand& band, const ModalFitSettings& settings, const JobControl& job,
                      ModalFitResult& result) {
  const int max_order = std::min(2 * settings.max_modes, static_cast<int>(band.size()) - 2);
  const JobControl diagram_job{job.cancel, [&job](double x) { job.report(kDiagramProgress * x); }};
  const StabilityCriteria criteria;
  result.diagram = lscfDiagram(band, max_order, criteria, diagram_job);
  const int orders = static_cast<int>(result.diagram.orders.size());
  const auto stable = stablePoles(result.diagram, std::min(kMinStableOrders, orders), criteria);
  auto poles = selectPoles(band, stable, settings.modes, settings.max_modes);
  FittedModel model = fitPoles(band, poles, settings, job, result);
  if (!settings.modes) {
    // A mode refined to insignificance or onto a neighbour (which took its share) goes; the rest are
    // fitted again.
    const ModalAxis kept = distinctModes(significantModes(band, model.modes));
    if (kept.size() < model.modes.size()) {
      poles.clear();
      for (const Mode& m : kept) poles.push_back(poleOf(m));
      model = fitPoles(band, poles, settings, job, result);
    }
  }
  return model;
}

}  // namespace

ModalFitResult fitModes(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                        const ModalFitSettings& settings, const JobControl& job) {
  validateFitInput(frequency_hz, h_m_per_n, settings);
  const FrfBand band = selectBand(frequency_hz, h_m_per_n, settings.from_hz, settings.to_hz);
  ModalFitResult result;
  FittedModel model;
  if (settings.method == ModalFitSettings::Method::Peak) {
    model.modes = pickPeaks(band, settings.modes.value_or(settings.max_modes));
    result.method = "peak picking (half-power bandwidth)";
  } else {
    model = lscfModel(band, settings, job, result);
  }
  std::sort(model.modes.begin(), model.modes.end(),
            [](const Mode& a, const Mode& b) { return a.natural_frequency_hz < b.natural_frequency_hz; });
  result.modes = model.modes;
  result.residuals = model.residuals;
  result.band_frequency_hz = band.frequency_hz;
  result.fitted = fittedReceptance(model, band.frequency_hz);
  result.fit_error_pct = fitErrorPercent(band.h_m_per_n, result.fitted);
  job.report(1.0);
  return result;
}

}  // namespace mx
