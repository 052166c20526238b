#pragma once
// Test helper: the FRF quantity (receptance, mobility, accelerance) as a QtTest data column.
#include <QMetaType>

#include "frf/frf_dataset.h"

Q_DECLARE_METATYPE(mx::FrfQuantity)
