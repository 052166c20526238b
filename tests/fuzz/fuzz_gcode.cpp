// Fuzz target of the G-code part program: GcodeReader::parse, then the GcodeInterpreter, then the
// GcodeWriter. Bad input ends in InvalidInput (a line too long, a word out of its range); anything
// else is read, with warnings. A program that reads keeps the reader's promises: its blocks give the
// file back byte for byte, unedited it writes back byte for byte, its motions are finite, and with
// new F and S words on every block it writes a program that reads again with exactly those values.
#include <cstdint>
#include <string>
#include <vector>

#include "core/invalid_input.h"
#include "fuzz_check.h"
#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "gcode/gcode_writer.h"

namespace {

using mx::fuzz::require;
using mx::fuzz::requireFinite;

// Blocks longer than this keep their text: an inserted word must not push a line past the reader's
// line limit (4096 bytes).
constexpr std::size_t kEditableLine = 4000;

void checkMotions(const mx::GcodeProgram& program) {
  const mx::GcodeRun run = mx::GcodeInterpreter().run(program);
  require(run.motions.size() == program.blocks.size(), "one motion per block");
  for (const mx::GcodeMotion& m : run.motions) {
    for (int axis = 0; axis < 3; ++axis) {
      requireFinite(m.start_m[axis], "finite start points");
      requireFinite(m.end_m[axis], "finite end points");
    }
    require(std::isfinite(m.length_m) && m.length_m >= 0.0, "finite, non-negative path lengths");
    require(std::isfinite(m.dwell_s) && m.dwell_s >= 0.0, "finite, non-negative dwells");
    require(std::isnan(m.feed_m_per_s) || (std::isfinite(m.feed_m_per_s) && m.feed_m_per_s >= 0.0),
            "a feed is unknown (NaN) or finite and non-negative");
    require(std::isnan(m.speed_rev_per_s) || (std::isfinite(m.speed_rev_per_s) && m.speed_rev_per_s >= 0.0),
            "a spindle speed is unknown (NaN) or finite and non-negative");
  }
}

std::vector<mx::GcodeBlockEdit> editsFor(const mx::GcodeProgram& program, mx::fuzz::InputNumbers& numbers) {
  std::vector<mx::GcodeBlockEdit> edits(program.blocks.size());
  for (std::size_t i = 0; i < edits.size(); ++i) {
    if (program.blocks[i].text.size() > kEditableLine) continue;
    edits[i].feed = numbers.uniform(0.0, 1e6);
    edits[i].speed_rpm = numbers.uniform(0.0, 1e5);
    edits[i].feed_decimals = static_cast<int>(numbers.next() % 4);
    if (numbers.next() % 4 == 0) edits[i].comment = "override (fuzz)";
  }
  return edits;
}

double writtenValue(double value, int decimals) {
  return std::stod(mx::GcodeWriter::formatNumber(value, decimals));
}

mx::GcodeProgram reread(const std::string& text, const char* promise) {
  try {
    return mx::GcodeReader::parse(text);
  } catch (const mx::InvalidInput& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise(promise);
  }
}

void checkEditedProgram(const mx::GcodeProgram& program, mx::fuzz::InputNumbers& numbers) {
  const std::vector<mx::GcodeBlockEdit> edits = editsFor(program, numbers);
  const mx::GcodeProgram edited = reread(mx::GcodeWriter::write(program, edits), "an edited program reads again");
  require(edited.blocks.size() == program.blocks.size(), "edits keep every block");
  for (std::size_t i = 0; i < edits.size(); ++i) {
    if (edits[i].empty()) continue;
    const mx::GcodeWord* f = edited.blocks[i].find('F');
    const mx::GcodeWord* s = edited.blocks[i].find('S');
    const bool kept = f != nullptr && f->value == writtenValue(edits[i].feed, edits[i].feed_decimals) && s != nullptr &&
                      s->value == writtenValue(edits[i].speed_rpm, edits[i].speed_decimals);
    if (!kept)
      std::fprintf(stderr, "fuzz: '%s' edited to '%s'\n", program.blocks[i].text.c_str(),
                   edited.blocks[i].text.c_str());
    require(kept, "an edited block reads again with the new F and S");
  }
  const mx::GcodeHeader header{"fuzz (project)", "none", "2024-01-01"};
  const mx::GcodeProgram headed =
      reread(mx::GcodeWriter::write(program, {}, &header), "a program with a header reads again");
  require(headed.blocks.size() > program.blocks.size(), "a header adds lines and keeps every block");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = mx::fuzz::bytesOf(data, size);
  mx::GcodeProgram program;
  try {
    program = mx::GcodeReader::parse(text);
  } catch (const mx::InvalidInput&) {
    return 0;
  }
  require(program.text() == text, "the blocks give the file back byte for byte");
  require(mx::GcodeWriter::write(program, {}) == text, "an unedited program writes back byte for byte");
  checkMotions(program);
  mx::fuzz::InputNumbers numbers(text);
  checkEditedProgram(program, numbers);
  return 0;
}
