#pragma once
// The message of the exception of type Error that fn() throws; a null string when it throws nothing.
// Any other exception propagates, so that a test sees the wrong error fail loudly.
#include <QString>

namespace mx::test {

template <typename Error, typename F>
QString messageOf(F fn) {
  try {
    fn();
  } catch (const Error& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace mx::test
