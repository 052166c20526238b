#pragma once
// Modal interpretation of a GcodeProgram, block by block (Heidenhain: heidenhain_interpreter.h): units
// (G20 inch / G21 mm; Sinumerik G700 / G710, and G70 / G71 for lengths only), distance mode
// (G90 absolute / G91 incremental), motion mode (G0 G1 G2 G3), the plane G17, the current feed F and
// spindle speed S, and the position. For every block it gives the resolved motion in SI units: start
// and end points, path length (arc length for G2/G3 with I,J centre offsets in the G17 plane, helical
// when Z changes), the feed in effect, and dwell time (G4 P, P in seconds).
// Conventions (documented in docs/sdnrp-gcode-notes.md):
//  - Within a block, G20/G21, G90/G91 and F, S are applied before the motion.
//  - F is read in the units in effect in its block (mm/min or in/min) and kept in m/s; a later unit
//    change does not rescale it.
//  - I and J are always incremental from the arc start.
//  - Sinumerik arcs may give their radius (CR=, > 0 at most half a turn) instead of I, J; its G4 takes
//    the dwell from F (seconds).
//  - The start point is settings.start_m (the program zero unless told otherwise).
//  - A feed move (G1/G2/G3) with no F anywhere before it is flagged feed_missing and warned about.
#include <array>
#include <limits>
#include <vector>

#include "gcode/gcode_program.h"

namespace mx {

enum class MotionKind { None, Rapid, Linear, ArcCw, ArcCcw, Dwell };

struct GcodeMotion {
  MotionKind kind = MotionKind::None;
  std::array<double, 3> start_m{};                                    // X, Y, Z at the start of the block [m]
  std::array<double, 3> end_m{};                                      // at the end [m]
  double length_m = 0.0;                                              // path length [m]
  double feed_m_per_s = std::numeric_limits<double>::quiet_NaN();     // modal feed in effect
  double speed_rev_per_s = std::numeric_limits<double>::quiet_NaN();  // modal spindle speed in effect
  bool feed_word = false;                                             // the block carries its own F word
  bool speed_word = false;                                            // the block carries its own S word
  bool feed_missing = false;                                          // feed move without any F so far
  bool inch = false;                                                  // F in inch/min (G20; Sinumerik G700)
  bool incremental = false;                                           // G91 in effect for this block
  double dwell_s = 0.0;                                               // G4 P

  bool isFeedMove() const {
    return kind == MotionKind::Linear || kind == MotionKind::ArcCw || kind == MotionKind::ArcCcw;
  }
  double minZ() const { return start_m[2] < end_m[2] ? start_m[2] : end_m[2]; }
};

struct GcodeInterpreterSettings {
  std::array<double, 3> start_m{0.0, 0.0, 0.0};  // position before the first block [m]
  bool start_inch = false;                       // G20 in effect at program start
};

struct GcodeRun {
  std::vector<GcodeMotion> motions;    // one per block, same order
  std::vector<GcodeWarning> warnings;  // modal problems (missing F, arc radius mismatch, ...)
};

class GcodeInterpreter {
 public:
  explicit GcodeInterpreter(GcodeInterpreterSettings settings = {});
  GcodeRun run(const GcodeProgram& program) const;

  static constexpr double kInch = 0.0254;  // m

 private:
  GcodeInterpreterSettings settings_;
};

}  // namespace mx
