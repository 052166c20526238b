#pragma once
// Test helper: an optional number (a readout that may be missing) as a QtTest data column.
#include <QMetaType>
#include <optional>

using OptD = std::optional<double>;
Q_DECLARE_METATYPE(OptD)
