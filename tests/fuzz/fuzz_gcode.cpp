// Fuzz target of the part-program reader with dialect detection: GcodeReader::parse without a named
// dialect, then the interpreter and the writer. An undetectable program, or one its dialect cannot read,
// ends in InvalidInput; what reads keeps the promises of gcode_checks.h, written back and read again in
// the detected dialect.
#include <cstdint>

#include "gcode_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mx::fuzz::gcode::checkProgramText(mx::fuzz::bytesOf(data, size), std::nullopt);
}
