#pragma once
// Test helper: the three cost weights (c1, c2, c3) as a QtTest data column.
#include <QMetaType>
#include <array>

using W3 = std::array<double, 3>;
Q_DECLARE_METATYPE(W3)
