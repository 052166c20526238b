#pragma once
// Test helper: runs the queued calls and deletes what deleteLater() scheduled; a delegate commits and
// closes its editor through them.
#include <QCoreApplication>
#include <QEvent>

namespace mx::test {

inline void settle() {
  QCoreApplication::processEvents();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

}  // namespace mx::test
