#include "services/frf_export.h"

#include "document/output_file.h"
#include "document/shortened_text.h"
#include "frf/frf_csv.h"
#include "frf/uff_writer.h"
#include "services/service_errors.h"

namespace mx::app {

FrfFormat frfFormatFromName(const QString& field, const QString& name) {
  if (name == "uff58") return FrfFormat::Uff58;
  if (name == "uff58b") return FrfFormat::Uff58b;
  if (name == "csv") return FrfFormat::Csv;
  throw InputError(QString("%1 = %2: must be uff58, uff58b or csv").arg(field, quoted(name, u'"')));
}

FrfDirection frfAxisFromName(const QString& field, const QString& name) {
  if (name == "x") return FrfDirection::X;
  if (name == "y") return FrfDirection::Y;
  throw InputError(QString("%1 = %2: must be x or y").arg(field, quoted(name, u'"')));
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
  const QByteArray data(bytes.data(), static_cast<qsizetype>(bytes.size()));
  if (const QString error = writeFileAtomically(path, data); !error.isEmpty())
    throw InputError(QString("%1: cannot write: %2").arg(path, error));
}

}  // namespace mx::app
