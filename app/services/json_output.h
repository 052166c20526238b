#pragma once
// JSON outputs of the CLI and the services: no NaN or infinity ever reaches them, and null appears
// only under the keys whose documented meaning is "no value" (README, "Command-line tool").
#include <QJsonObject>
#include <QJsonValue>
#include <QSet>
#include <QString>
#include <cmath>

namespace mx::app {

// JSON number, or null for a non-finite value; only for a key of documentedNullKeys().
inline QJsonValue jsonNumberOrNull(double value) {
  return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

// The keys under which null is a documented "no value" (also for their array items and the members
// of their objects).
const QSet<QString>& documentedNullKeys();

// Throws ComputationError (exit 1) at the first number that is not finite, or the first null outside
// documentedNullKeys(), naming its JSON path ("ranking[2].C = nan: the computation gave no finite value").
void checkJsonOutput(const QJsonObject& object);

}  // namespace mx::app
