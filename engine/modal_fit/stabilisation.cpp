#include "modal_fit/stabilisation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "modal_fit/modal_pole.h"

namespace mx {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::complex<double> poleFrom(double frequency_hz, double zeta) {
  const double w = 2.0 * std::numbers::pi * frequency_hz;
  return {-zeta * w, w * std::sqrt(1.0 - zeta * zeta)};
}

}  // namespace

std::vector<DiagramPole> physicalPoles(const std::vector<std::complex<double>>& lambdas, double from_hz, double to_hz,
                                       const StabilityCriteria& criteria) {
  std::vector<DiagramPole> poles;
  for (const auto& lambda : lambdas) {
    if (!std::isfinite(lambda.real()) || !std::isfinite(lambda.imag())) continue;
    if (lambda.imag() <= 0.0 || lambda.real() >= 0.0) continue;
    const double f = poleFrequencyHz(lambda), zeta = poleDampingRatio(lambda);
    if (f < from_hz || f > to_hz || zeta >= criteria.max_damping) continue;
    poles.push_back({lambda, f, zeta, PoleStability::Unstable, 1, 1});
  }
  std::sort(poles.begin(), poles.end(),
            [](const DiagramPole& a, const DiagramPole& b) { return a.frequency_hz < b.frequency_hz; });
  return poles;
}

void classifyPoles(std::vector<DiagramPole>& current, const std::vector<DiagramPole>& previous,
                   const StabilityCriteria& criteria) {
  for (DiagramPole& pole : current) {
    pole.stability = PoleStability::Unstable;
    pole.stable_orders = 1;
    pole.frequency_stable_orders = 1;
    const auto nearest =
        std::min_element(previous.begin(), previous.end(), [&](const DiagramPole& a, const DiagramPole& b) {
          return std::abs(a.frequency_hz - pole.frequency_hz) < std::abs(b.frequency_hz - pole.frequency_hz);
        });
    if (nearest == previous.end()) continue;
    if (std::abs(nearest->frequency_hz - pole.frequency_hz) > criteria.frequency_tol * pole.frequency_hz) continue;
    pole.stability = PoleStability::FrequencyStable;
    pole.frequency_stable_orders = nearest->frequency_stable_orders + 1;
    if (std::abs(nearest->damping_ratio - pole.damping_ratio) > criteria.damping_tol * pole.damping_ratio) continue;
    pole.stability = PoleStability::Stable;
    pole.stable_orders = nearest->stable_orders + 1;
  }
}

std::vector<std::complex<double>> stablePoles(const StabilisationDiagram& diagram, int min_orders,
                                              const StabilityCriteria& criteria) {
  std::vector<DiagramPole> candidates;
  for (const auto& order : diagram.orders)
    for (const auto& pole : order.poles)
      if (pole.stable_orders >= min_orders || pole.frequency_stable_orders > min_orders) candidates.push_back(pole);
  std::sort(candidates.begin(), candidates.end(),
            [](const DiagramPole& a, const DiagramPole& b) { return a.frequency_hz < b.frequency_hz; });
  std::vector<std::complex<double>> poles;
  for (std::size_t begin = 0; begin < candidates.size();) {
    std::size_t end = begin + 1;
    while (end < candidates.size() && candidates[end].frequency_hz - candidates[end - 1].frequency_hz <=
                                          criteria.frequency_tol * candidates[end - 1].frequency_hz)
      ++end;
    std::vector<double> f, zeta;
    for (std::size_t i = begin; i < end; ++i) {
      f.push_back(candidates[i].frequency_hz);
      zeta.push_back(candidates[i].damping_ratio);
    }
    poles.push_back(poleFrom(median(f), median(zeta)));
    begin = end;
  }
  return poles;
}

}  // namespace mx
