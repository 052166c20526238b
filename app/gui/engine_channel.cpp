#include "engine_channel.h"

namespace mx::gui {

std::mutex& handOverMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace mx::gui
