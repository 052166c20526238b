#include "services/frf_export.h"

#include <QSaveFile>

#include "frf/frf_csv.h"
#include "frf/uff_writer.h"
#include "services/service_errors.h"

namespace mx::app {

FrfFormat frfFormatFromName(const QString& field, const QString& name) {
  if (name == "uff58") return FrfFormat::Uff58;
  if (name == "uff58b") return FrfFormat::Uff58b;
  if (name == "csv") return FrfFormat::Csv;
  throw InputError(QString("%1 = \"%2\": must be uff58, uff58b or csv").arg(field, name));
}

FrfDirection frfAxisFromName(const QString& field, const QString& name) {
  if (name == "x") return FrfDirection::X;
  if (name == "y") return FrfDirection::Y;
  throw InputError(QString("%1 = \"%2\": must be x or y").arg(field, name));
}

void saveFrfFile(const QString& path, FrfFormat format, const std::vector<FrfDataset>& datasets) {
  std::string bytes;
  switch (format) {
    case FrfFormat::Uff58:
      bytes = uff58String(datasets);
      break;
    case FrfFormat::Uff58b:
      bytes = uff58bString(datasets);
      break;
    case FrfFormat::Csv:
      if (datasets.size() != 1)
        throw InputError(
            QString("%1: a CSV holds one FRF, not %2; export one axis or a UFF file").arg(path).arg(datasets.size()));
      bytes = frfCsvString(datasets.front());
      break;
  }
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) throw InputError(QString("%1: cannot write: %2").arg(path, file.errorString()));
  if (file.write(bytes.data(), static_cast<qint64>(bytes.size())) != static_cast<qint64>(bytes.size())) {
    const QString reason = file.errorString();
    file.cancelWriting();
    throw InputError(QString("%1: cannot write: %2").arg(path, reason));
  }
  if (!file.commit()) throw InputError(QString("%1: cannot save: %2").arg(path, file.errorString()));
}

}  // namespace mx::app
