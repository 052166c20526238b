#include "services/batch_results.h"

#include <QJsonDocument>

#include "services/service_errors.h"

namespace mx::app {

namespace {

std::optional<QJsonObject> resultLine(const QByteArray& text) {
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(text, &error);
  if (error.error != QJsonParseError::NoError || !document.isObject()) return std::nullopt;
  if (!document.object().value("hash").isString()) return std::nullopt;
  return document.object();
}

}  // namespace

BatchResultsScan scanBatchResults(const QString& path, const std::function<void(const QJsonObject&)>& line) {
  BatchResultsScan scan;
  QFile file(path);
  if (!file.exists()) return scan;
  if (!file.open(QIODevice::ReadOnly)) throw InputError(QString("%1: cannot read the results file").arg(path));
  while (!file.atEnd()) {
    const QByteArray text = file.readLine();
    const std::optional<QJsonObject> object = text.endsWith('\n') ? resultLine(text) : std::nullopt;
    if (object) {
      line(*object);
      ++scan.whole_lines;
      scan.whole_bytes = file.pos();
      continue;
    }
    if (!file.atEnd())
      throw InputError(QString("%1:%2: not a results line (a JSON object with \"hash\"); only the last line "
                               "may be torn")
                           .arg(path)
                           .arg(scan.whole_lines + 1));
    scan.torn_last_line = true;
  }
  return scan;
}

QSet<QString> resumeBatchResults(const QString& path) {
  QSet<QString> hashes;
  const BatchResultsScan scan =
      scanBatchResults(path, [&](const QJsonObject& line) { hashes.insert(line.value("hash").toString()); });
  if (scan.torn_last_line && !QFile::resize(path, scan.whole_bytes))
    throw InputError(QString("%1: cannot cut off the torn last line").arg(path));
  return hashes;
}

BatchResultsWriter::BatchResultsWriter(const QString& path) : file_(path) {
  if (!file_.open(QIODevice::WriteOnly | QIODevice::Append))
    throw InputError(QString("--out = '%1': cannot open for appending: %2").arg(path, file_.errorString()));
}

void BatchResultsWriter::append(const QJsonObject& line) {
  const QByteArray text = QJsonDocument(line).toJson(QJsonDocument::Compact).append('\n');
  const std::lock_guard lock(mutex_);
  if (file_.write(text) != text.size() || !file_.flush())
    throw ComputationError(QString("%1: write failed: %2").arg(file_.fileName(), file_.errorString()));
}

}  // namespace mx::app
