#pragma once
// Tap-test FRF files for the CLI and the GUI: reading with the quantity given by the user (required for
// CSV, checked against the file for UFF), choosing one FRF dataset, and fitting modes to it. Errors are
// InputError (exit 2) naming the file, the field and the value; a fit without an answer is
// ComputationError (exit 1).
#include <QString>
#include <optional>

#include "frf/frf_dataset.h"
#include "frf/receptance_conversion.h"
#include "modal_fit/modal_fit.h"

namespace mx::app {

// "receptance" | "mobility" | "accelerance"; InputError naming `field` otherwise.
FrfQuantity frfQuantityFromName(const QString& field, const QString& name);
QString frfFormatName(FrfFormat format);  // "uff58" | "uff58b" | "csv"

// Reads `path`; `quantity` is required for CSV and, for UFF, must agree with every dataset.
FrfFile loadFrfFile(const QString& path, std::optional<FrfQuantity> quantity);

// The FRF dataset at `index` (0-based among the file's FRFs) as receptance [m/N].
Receptance frfReceptance(const FrfFile& file, const QString& path, int index);

// Fits modes to `receptance` over [from_hz, to_hz] (the whole measured range, f > 0, when unset).
ModalFitResult fitFrfModes(const Receptance& receptance, std::optional<double> from_hz, std::optional<double> to_hz,
                           ModalFitSettings settings, const JobControl& job = {});

}  // namespace mx::app
