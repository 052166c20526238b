#pragma once
// The errors of the services besides the project's own ProjectError: a value given from outside the
// project (a flag's or a field's text) that is out of range, and a computation without an answer.
#include <QString>
#include <stdexcept>

#include "services/exit_code.h"

namespace mx::app {

// Exit code 2; the message names the field, the value and the allowed range.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const QString& message) : std::runtime_error(message.toStdString()) {}
  static constexpr int exitCode() { return kExitBadInput; }
};

// Exit code 1: valid input, no result (an empty admissible space, every point excluded by the rules).
class ComputationError : public std::runtime_error {
 public:
  explicit ComputationError(const QString& message) : std::runtime_error(message.toStdString()) {}
  static constexpr int exitCode() { return kExitComputationFailed; }
};

}  // namespace mx::app
