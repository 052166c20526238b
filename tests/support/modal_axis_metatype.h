#pragma once
// Test helper: a direction's modes (mx::ModalAxis) as a QtTest data column.
#include <QMetaType>

#include "model/modal_model.h"

Q_DECLARE_METATYPE(mx::ModalAxis)
