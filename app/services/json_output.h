#pragma once
#include <QJsonValue>
#include <cmath>

namespace mx::app {

// JSON number, or null for a non-finite value: no NaN ever reaches a JSON output.
inline QJsonValue jsonNumberOrNull(double value) {
  return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

}  // namespace mx::app
