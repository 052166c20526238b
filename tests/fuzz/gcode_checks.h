#pragma once
// The promises of the part-program reader, interpreter and writer, shared by the G-code fuzz targets
// (fuzz_gcode: the dialect detected; fuzz_gcode_<dialect>: the dialect named). Bad input ends in
// InvalidInput (an undetectable dialect, a line too long, text that cannot be split into words, a word
// out of its range); a program that reads keeps these promises:
//  - its blocks give the file back byte for byte, and unedited it writes back byte for byte;
//  - its motions are finite (one per block);
//  - with new F and S words on every block that takes them in its dialect (an editable word, or a
//    place to insert one), it writes a program that reads again in the same dialect with exactly those
//    values, every block kept and the unedited ones unchanged;
//  - with a header it reads again: ISO, Sinumerik and LinuxCNC gain comment lines, Heidenhain keeps its
//    numbered blocks (the header is a comment on BEGIN PGM or the first block).
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/invalid_input.h"
#include "fuzz_check.h"
#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "gcode/gcode_writer.h"

namespace mx::fuzz::gcode {

// Blocks longer than this keep their text: an inserted word or comment must not push a line past the
// reader's line limit (kMaxGcodeLineLength, 4096 bytes).
constexpr std::size_t kEditableLine = 4000;

inline void checkMotions(const GcodeProgram& program) {
  const GcodeRun run = GcodeInterpreter().run(program);
  require(run.motions.size() == program.blocks.size(), "one motion per block");
  for (const GcodeMotion& m : run.motions) {
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

inline bool takesFeed(const GcodeBlock& b) {
  return b.feedWord() != nullptr || b.feed_insert_at != std::string::npos;
}
inline bool takesSpeed(const GcodeBlock& b) {
  return b.speedWord() != nullptr || b.speed_insert_at != std::string::npos;
}

// New F and S on every block that takes them (the writer refuses the others), a comment now and then.
inline std::vector<GcodeBlockEdit> editsFor(const GcodeProgram& program, InputNumbers& numbers) {
  std::vector<GcodeBlockEdit> edits(program.blocks.size());
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const GcodeBlock& b = program.blocks[i];
    if (b.text.size() > kEditableLine) continue;
    if (takesFeed(b)) edits[i].feed = numbers.uniform(0.0, GcodeWordLimits::kMaxFeed);
    if (takesSpeed(b)) edits[i].speed_rpm = numbers.uniform(0.0, GcodeWordLimits::kMaxSpindleRpm);
    edits[i].feed_decimals = static_cast<int>(numbers.next() % 4);
    if (numbers.next() % 4 == 0) edits[i].comment = "override (fuzz)";
  }
  return edits;
}

inline double writtenValue(double value, int decimals) {
  return std::stod(GcodeWriter::formatNumber(value, decimals));
}

inline std::string writeOrBreak(const GcodeProgram& program, const std::vector<GcodeBlockEdit>& edits,
                                const GcodeHeader* header, const char* promise) {
  try {
    return GcodeWriter::write(program, edits, header);
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    brokenPromise(promise);
  }
}

// Reads a written program again in the dialect it was read in.
inline GcodeProgram reread(const std::string& text, GcodeDialect dialect, const char* promise) {
  try {
    return GcodeReader::parse(text, dialect);
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    brokenPromise(promise);
  }
}

inline void checkEditedProgram(const GcodeProgram& program, InputNumbers& numbers) {
  const GcodeDialect dialect = program.dialect.dialect;
  const std::vector<GcodeBlockEdit> edits = editsFor(program, numbers);
  const std::string written = writeOrBreak(program, edits, nullptr, "F and S are written where a block takes them");
  const GcodeProgram edited = reread(written, dialect, "an edited program reads again in its dialect");
  require(edited.blocks.size() == program.blocks.size(), "edits keep every block");
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const GcodeBlockEdit& e = edits[i];
    const GcodeBlock& before = program.blocks[i];
    const GcodeBlock& after = edited.blocks[i];
    if (e.empty()) {
      require(after.text == before.text, "an unedited block is written as read");
      continue;
    }
    const GcodeWord* f = after.feedWord();
    const GcodeWord* s = after.speedWord();
    const bool feed_kept = !(e.feed == e.feed) || (f != nullptr && f->value == writtenValue(e.feed, e.feed_decimals));
    const bool speed_kept =
        !(e.speed_rpm == e.speed_rpm) || (s != nullptr && s->value == writtenValue(e.speed_rpm, e.speed_decimals));
    if (!feed_kept || !speed_kept)
      std::fprintf(stderr, "fuzz: '%s' edited to '%s'\n", before.text.c_str(), after.text.c_str());
    require(feed_kept, "an edited block reads again with the new F");
    require(speed_kept, "an edited block reads again with the new S");
  }
}

inline void checkHeader(const GcodeProgram& program) {
  const GcodeHeader header{"fuzz (project)", "none", "2024-01-01"};
  const GcodeDialect dialect = program.dialect.dialect;
  if (dialect == GcodeDialect::Heidenhain && !program.blocks.empty()) {
    // The header's comment goes on the first BEGIN PGM block (or the first block): it must leave room.
    const GcodeBlock* carrier = &program.blocks.front();
    for (const GcodeBlock& b : program.blocks)
      if (b.keyword == "BEGIN PGM") {
        carrier = &b;
        break;
      }
    if (carrier->text.size() > kEditableLine) return;
  }
  const std::string written = writeOrBreak(program, {}, &header, "a header is written");
  const GcodeProgram headed = reread(written, dialect, "a program with a header reads again in its dialect");
  if (dialect == GcodeDialect::Heidenhain)
    require(headed.blocks.size() == program.blocks.size(), "a Heidenhain header keeps the numbered blocks");
  else
    require(headed.blocks.size() > program.blocks.size(), "a header adds lines and keeps every block");
}

// The target's body: reads the input (in `dialect`, or the detected one) and checks every promise.
inline int checkProgramText(std::string_view text, std::optional<GcodeDialect> dialect) {
  GcodeProgram program;
  try {
    program = GcodeReader::parse(text, dialect);
  } catch (const InvalidInput&) {
    return 0;
  }
  if (dialect) require(program.dialect.dialect == *dialect && program.dialect.line == 0, "a named dialect is kept");
  require(program.text() == text, "the blocks give the file back byte for byte");
  require(GcodeWriter::write(program, {}) == text, "an unedited program writes back byte for byte");
  checkMotions(program);
  InputNumbers numbers(text);
  checkEditedProgram(program, numbers);
  checkHeader(program);
  return 0;
}

}  // namespace mx::fuzz::gcode
