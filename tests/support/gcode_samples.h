#pragma once
// Test helper: the sample part programs of tests/data/gcode, and the examples of projects/programs
// ("programs/..."), read byte for byte; and the text of a lexed word.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "gcode/gcode_block.h"

namespace mx::test {

// Every sample program (mm, CRLF, inch, unknown words, missing F, truncated, UTF-8 comments, empty).
inline constexpr const char* kGcodeSamples[] = {"pocket_mm.nc", "crlf.nc",      "inch.nc",          "unknown_words.nc",
                                                "missing_f.nc", "truncated.nc", "utf8_comments.nc", "empty.nc"};

// The same pocket in every dialect (pocket_mm.nc is the ISO one), the examples shipped in projects/.
inline constexpr const char* kDialectSamples[] = {"pocket_mm.nc", "programs/pocket_mm.h", "programs/pocket_mm.mpf",
                                                  "programs/pocket_mm.ngc"};

inline std::string gcodeSample(const std::string& name) {
  const bool example = name.rfind("programs/", 0) == 0;
  const std::filesystem::path folder = example ? MX_PROJECTS_DIR : MX_TEST_DATA_DIR "/gcode";
  std::ifstream in(folder / name, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The characters of word `w` in its block, "none" for no word.
inline std::string wordText(const GcodeBlock& b, const GcodeWord* w) {
  return w ? b.text.substr(w->column - 1, w->length) : std::string("none");
}

}  // namespace mx::test
