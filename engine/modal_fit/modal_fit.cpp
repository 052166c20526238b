#include "modal_fit/modal_fit.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/invalid_input.h"
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

// LSFD residues of the poles, then the NLLS refinement when asked for; `source` names where the poles
// came from in result.method.
FittedModel fitPoles(const FrfBand& band, const std::vector<std::complex<double>>& poles,
                     const ModalFitSettings& settings, const JobControl& job, ModalFitResult& result,
                     const std::string& source = "LSCF") {
  if (job.cancelled()) throw Cancelled();
  FittedModel model = fittedModel(poles, fitResidues(band, poles));
  result.method = source + " + LSFD";
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

// Modes sorted by frequency, the model over the band and its fit error.
void storeModel(FittedModel model, const FrfBand& band, const JobControl& job, ModalFitResult& result) {
  std::sort(model.modes.begin(), model.modes.end(),
            [](const Mode& a, const Mode& b) { return a.natural_frequency_hz < b.natural_frequency_hz; });
  result.band_frequency_hz = band.frequency_hz;
  result.fitted = fittedReceptance(model, band.frequency_hz);
  result.fit_error_pct = fitErrorPercent(band.h_m_per_n, result.fitted);
  result.modes = std::move(model.modes);
  result.residuals = model.residuals;
  job.report(1.0);
}

void validatePoles(const std::vector<std::complex<double>>& poles, double from_hz, double to_hz) {
  if (poles.empty()) throw InvalidInput("poles: none given, at least one pole is needed");
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const double f = poleFrequencyHz(poles[i]);
    if (poles[i].imag() > 0.0 && std::isfinite(f) && f >= from_hz && f <= to_hz) continue;
    std::ostringstream message;
    message << "pole " << i + 1 << " = " << poles[i].real() << (poles[i].imag() < 0 ? " - " : " + ")
            << std::abs(poles[i].imag()) << "i rad/s (" << f
            << " Hz): must lie in the upper half-plane within the band [" << from_hz << ", " << to_hz << "] Hz";
    throw InvalidInput(message.str());
  }
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
  storeModel(std::move(model), band, job, result);
  return result;
}

ModalFitResult fitModesAtPoles(const std::vector<double>& frequency_hz,
                               const std::vector<std::complex<double>>& h_m_per_n, const ModalFitSettings& settings,
                               const std::vector<std::complex<double>>& poles, const JobControl& job) {
  // Only the data and the band are checked: the pole count replaces modes / max_modes.
  ModalFitSettings checked = settings;
  checked.modes.reset();
  checked.max_modes = 1;
  checked.method = ModalFitSettings::Method::Lscf;
  validateFitInput(frequency_hz, h_m_per_n, checked);
  validatePoles(poles, settings.from_hz, settings.to_hz);
  const FrfBand band = selectBand(frequency_hz, h_m_per_n, settings.from_hz, settings.to_hz);
  ModalFitResult result;
  FittedModel model = fitPoles(band, poles, settings, job, result, "chosen poles");
  storeModel(std::move(model), band, job, result);
  return result;
}

}  // namespace mx
