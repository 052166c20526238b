#pragma once
#include <stdexcept>

namespace mx {

// Thrown for inputs outside a method's domain; the message names the quantity, value and range.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace mx
