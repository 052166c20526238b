#pragma once
// FRFs of known modes: the export of a fitted or typed-in model, and synthetic tap tests.
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include "frf/frf_dataset.h"
#include "model/modal_model.h"

namespace mx {

// receptance(modes, i w) (i w)^k with k = 0, 1, 2 for receptance, mobility, accelerance; positive
// response and reference `direction`, node 1.
FrfDataset modalFrfDataset(const ModalAxis& modes, FrfQuantity quantity, const std::vector<double>& frequency_hz,
                           FrfDirection direction, std::string name);

// H (1 + noise (n1 + i n2) / sqrt 2) at every line, n1 and n2 standard normal: complex noise of RMS
// `noise` relative to |H|. Box-Muller over std::mt19937, so a seed gives the same values everywhere.
void addRelativeNoise(std::vector<std::complex<double>>& values, double noise, std::uint32_t seed);

}  // namespace mx
