#include "services/frf_import.h"

#include "core/invalid_input.h"
#include "document/shortened_text.h"
#include "frf/frf_file.h"
#include "frf/frf_file_error.h"
#include "services/service_errors.h"

namespace mx::app {

FrfQuantity frfQuantityFromName(const QString& field, const QString& name) {
  if (name == "receptance") return FrfQuantity::Receptance;
  if (name == "mobility") return FrfQuantity::Mobility;
  if (name == "accelerance") return FrfQuantity::Accelerance;
  throw InputError(QString("%1 = %2: must be receptance, mobility or accelerance").arg(field, quoted(name, u'"')));
}

QString frfFormatName(FrfFormat format) {
  switch (format) {
    case FrfFormat::Uff58:
      return "uff58";
    case FrfFormat::Uff58b:
      return "uff58b";
    case FrfFormat::Csv:
      break;
  }
  return "csv";
}

FrfFile loadFrfFile(const QString& path, std::optional<FrfQuantity> quantity) {
  FrfFile file;
  try {
    file = readFrfFile(path.toStdString(), quantity);
  } catch (const FrfFileError& e) {
    throw InputError(QString::fromStdString(e.what()));
  } catch (const InvalidInput& e) {
    throw InputError(QString("%1: %2").arg(path, QString::fromStdString(e.what())));
  }
  if (file.format != FrfFormat::Csv && quantity) {
    for (const FrfDataset& d : file.datasets)
      if (d.quantity != *quantity)
        throw InputError(QString("%1: quantity = %2, but FRF dataset %3 of the file is %4")
                             .arg(path, QString::fromStdString(std::string(frfQuantityName(*quantity))))
                             .arg(d.index)
                             .arg(QString::fromStdString(std::string(frfQuantityName(d.quantity)))));
  }
  return file;
}

Receptance frfReceptance(const FrfFile& file, const QString& path, int index) {
  const int count = static_cast<int>(file.datasets.size());
  if (count == 0) throw InputError(QString("%1: the file holds no FRF dataset (function type 4)").arg(path));
  if (index < 0 || index >= count)
    throw InputError(
        QString("%1: dataset = %2: must be in [0, %3] (the file's FRF datasets)").arg(path).arg(index).arg(count - 1));
  try {
    return toReceptance(file.datasets[static_cast<std::size_t>(index)]);
  } catch (const InvalidInput& e) {
    throw InputError(QString("%1: dataset %2: %3").arg(path).arg(index).arg(QString::fromStdString(e.what())));
  }
}

ModalFitResult fitFrfModes(const Receptance& receptance, std::optional<double> from_hz, std::optional<double> to_hz,
                           ModalFitSettings settings, const JobControl& job) {
  const auto& f = receptance.frequency_hz;
  if (f.empty()) throw InputError("the FRF has no points");
  settings.from_hz = from_hz.value_or(f.front());  // the band leaves out 0 Hz itself (frf_band.h)
  settings.to_hz = to_hz.value_or(f.back());
  try {
    return fitModes(f, receptance.h_m_per_n, settings, job);
  } catch (const InvalidInput& e) {
    throw InputError(QString::fromStdString(e.what()));
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception& e) {
    throw ComputationError(QString("modal fit failed: %1").arg(QString::fromStdString(e.what())));
  }
}

}  // namespace mx::app
