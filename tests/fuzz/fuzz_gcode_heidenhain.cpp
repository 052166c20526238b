// Fuzz target of the Heidenhain Klartext reader: GcodeReader::parse with the dialect named (no detection), then
// the interpreter and the writer. Text the dialect cannot read ends in InvalidInput; what reads keeps the
// promises of gcode_checks.h, written back and read again as Heidenhain Klartext.
#include <cstdint>

#include "gcode_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mx::fuzz::gcode::checkProgramText(mx::fuzz::bytesOf(data, size), mx::GcodeDialect::Heidenhain);
}
