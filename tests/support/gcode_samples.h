#pragma once
// Test helper: the sample part programs of tests/data/gcode, read byte for byte.
#include <fstream>
#include <sstream>
#include <string>

namespace mx::test {

// Every sample program (mm, CRLF, inch, unknown words, missing F, truncated, UTF-8 comments, empty).
inline constexpr const char* kGcodeSamples[] = {"pocket_mm.nc", "crlf.nc",      "inch.nc",          "unknown_words.nc",
                                                "missing_f.nc", "truncated.nc", "utf8_comments.nc", "empty.nc"};

// The same pocket in every dialect (pocket_mm.nc is the ISO one).
inline constexpr const char* kDialectSamples[] = {"pocket_mm.nc", "heidenhain_pocket.h", "sinumerik_pocket.mpf",
                                                  "linuxcnc_pocket.ngc"};

inline std::string gcodeSample(const std::string& name) {
  std::ifstream in(std::string(MX_TEST_DATA_DIR) + "/gcode/" + name, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace mx::test
