#pragma once
// Test helper: what the views show in place of a value.
#include <QString>

namespace mx::test {

inline const QString kDash = QStringLiteral("\u2013");  // no value, or one that is not finite

}  // namespace mx::test
