#include "gcode/gcode_interpreter.h"

#include <cmath>
#include <optional>
#include <string>

#include "gcode/arc_geometry.h"
#include "gcode/heidenhain_interpreter.h"

namespace mx {

GcodeInterpreter::GcodeInterpreter(GcodeInterpreterSettings settings) : settings_(settings) {}

GcodeRun GcodeInterpreter::run(const GcodeProgram& program) const {
  if (program.dialect.dialect == GcodeDialect::Heidenhain) return interpretHeidenhain(program, settings_);
  GcodeRun out;
  out.motions.reserve(program.blocks.size());
  const bool sinumerik = program.dialect.dialect == GcodeDialect::Sinumerik;
  bool inch = settings_.start_inch;       // lengths
  bool feed_inch = settings_.start_inch;  // F in inch/min
  bool incremental = false;
  int mode = -1;  // 0..3, -1 none yet
  double feed = std::numeric_limits<double>::quiet_NaN();
  double speed = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> pos = settings_.start_m;
  bool warned_no_mode = false;

  for (const auto& b : program.blocks) {
    GcodeMotion m;
    bool dwell = false;
    int block_mode = -1;
    for (const auto& w : b.words) {
      if (!w.known || w.letter != 'G') continue;
      const int g = static_cast<int>(std::lround(w.value));
      switch (g) {
        case 20:
        case 700:
          inch = feed_inch = true;
          break;
        case 21:
        case 710:
          inch = feed_inch = false;
          break;
        case 70:  // Sinumerik: lengths in inch, F in the machine's basic unit (mm)
          inch = true;
          break;
        case 71:
          inch = false;
          break;
        case 90:
          incremental = false;
          break;
        case 91:
          incremental = true;
          break;
        case 4:
          dwell = true;
          break;
        case 0:
        case 1:
        case 2:
        case 3:
          block_mode = g;
          break;
        default:
          break;  // G17: the only plane supported
      }
    }
    const double unit = inch ? kInch : 1e-3;
    const double feed_unit = feed_inch ? kInch : 1e-3;
    m.inch = feed_inch;
    m.incremental = incremental;
    // Sinumerik's G4 F.. / S.. give the dwell in seconds / revolutions: not a feed or a speed.
    const bool dwell_words = dwell && sinumerik;
    if (const auto* f = b.find('F'); f && f->known && !dwell_words) {
      feed = f->value * feed_unit / 60.0;
      m.feed_word = true;
      if (!(f->value > 0.0))
        out.warnings.push_back({b.line, f->column, b.text.substr(f->column - 1, f->length), "F must be > 0"});
    }
    if (const auto* s = b.find('S'); s && s->known && !dwell_words) {
      speed = s->value / 60.0;
      m.speed_word = true;
    }
    if (block_mode >= 0) mode = block_mode;
    m.feed_m_per_s = feed;
    m.speed_rev_per_s = speed;
    m.start_m = pos;
    m.end_m = pos;

    if (dwell) {
      m.kind = MotionKind::Dwell;
      if (const auto* p = b.find(sinumerik ? 'F' : 'P')) m.dwell_s = p->value;
      out.motions.push_back(m);
      continue;
    }
    bool has_axis = false;
    static constexpr char kAxes[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
      if (const auto* w = b.find(kAxes[a])) {
        has_axis = true;
        const double v = w->value * unit;
        m.end_m[static_cast<std::size_t>(a)] = incremental ? pos[static_cast<std::size_t>(a)] + v : v;
      }
    }
    const auto* wi = b.find('I');
    const auto* wj = b.find('J');
    const auto* wr = b.findAddress("CR");  // Sinumerik arc radius
    const bool arc_mode = mode == 2 || mode == 3;
    if (!has_axis && !(arc_mode && (wi || wj) && block_mode >= 0)) {
      out.motions.push_back(m);  // no motion in this block
      continue;
    }
    if (mode < 0) {
      if (!warned_no_mode)
        out.warnings.push_back({b.line, 0, b.text, "axis words without a motion mode (G0/G1/G2/G3): treated as G0"});
      warned_no_mode = true;
    }
    const double dx = m.end_m[0] - m.start_m[0], dy = m.end_m[1] - m.start_m[1], dz = m.end_m[2] - m.start_m[2];
    const arc::Point start{m.start_m[0], m.start_m[1]}, end{m.end_m[0], m.end_m[1]};
    std::optional<arc::Point> centre;
    if (arc_mode && (wi || wj))
      centre = arc::Point{start[0] + (wi ? wi->value * unit : 0.0), start[1] + (wj ? wj->value * unit : 0.0)};
    else if (arc_mode && wr)
      centre = arc::centreFromRadius(start, end, wr->value * unit, mode == 2);
    if (mode <= 0) {
      m.kind = MotionKind::Rapid;
      m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    } else if (mode == 1 || !centre) {
      if (mode != 1)
        out.warnings.push_back({b.line, 0, b.text,
                                wr ? "arc radius shorter than half the chord: treated as a straight feed move"
                                   : "arc without I or J: treated as a straight feed move"});
      m.kind = MotionKind::Linear;
      m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    } else {
      m.kind = mode == 2 ? MotionKind::ArcCw : MotionKind::ArcCcw;
      const double r0 = std::hypot(start[0] - (*centre)[0], start[1] - (*centre)[1]);
      const double r1 = std::hypot(end[0] - (*centre)[0], end[1] - (*centre)[1]);
      if (std::abs(r0 - r1) > std::max(1e-5, 1e-3 * r0))
        out.warnings.push_back({b.line, 0, b.text,
                                "arc end radius " + std::to_string(r1 * 1e3) + " mm differs from start radius " +
                                    std::to_string(r0 * 1e3) + " mm"});
      m.length_m = std::hypot(arc::length(start, end, *centre, mode == 2), dz);
    }
    if (m.isFeedMove() && !(feed > 0.0)) {
      m.feed_missing = true;
      out.warnings.push_back({b.line, 0, b.text, "feed move without F (no modal F either)"});
    }
    pos = m.end_m;
    out.motions.push_back(m);
  }
  return out;
}

}  // namespace mx
