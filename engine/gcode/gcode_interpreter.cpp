#include "gcode/gcode_interpreter.h"

#include <cmath>
#include <numbers>
#include <string>

namespace mx {

GcodeInterpreter::GcodeInterpreter(GcodeInterpreterSettings settings) : settings_(settings) {}

namespace {

double arcSweep(double a0, double a1, bool clockwise, bool full) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  if (full) return two_pi;
  double d = clockwise ? a0 - a1 : a1 - a0;
  while (d <= 0.0) d += two_pi;
  while (d > two_pi) d -= two_pi;
  return d;
}

}  // namespace

GcodeRun GcodeInterpreter::run(const GcodeProgram& program) const {
  GcodeRun out;
  out.motions.reserve(program.blocks.size());
  bool inch = settings_.start_inch;
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
          inch = true;
          break;
        case 21:
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
    m.inch = inch;
    m.incremental = incremental;
    if (const auto* f = b.find('F'); f && f->known) {
      feed = f->value * unit / 60.0;
      m.feed_word = true;
      if (!(f->value > 0.0))
        out.warnings.push_back({b.line, f->column, b.text.substr(f->column - 1, f->length), "F must be > 0"});
    }
    if (const auto* s = b.find('S'); s && s->known) {
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
      if (const auto* p = b.find('P')) m.dwell_s = p->value;
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
    if (mode <= 0) {
      m.kind = MotionKind::Rapid;
      m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    } else if (mode == 1 || (!wi && !wj)) {
      if (mode != 1) out.warnings.push_back({b.line, 0, b.text, "arc without I or J: treated as a straight feed move"});
      m.kind = MotionKind::Linear;
      m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    } else {
      m.kind = mode == 2 ? MotionKind::ArcCw : MotionKind::ArcCcw;
      const double cx = m.start_m[0] + (wi ? wi->value * unit : 0.0);
      const double cy = m.start_m[1] + (wj ? wj->value * unit : 0.0);
      const double r0 = std::hypot(m.start_m[0] - cx, m.start_m[1] - cy);
      const double r1 = std::hypot(m.end_m[0] - cx, m.end_m[1] - cy);
      if (std::abs(r0 - r1) > std::max(1e-5, 1e-3 * r0))
        out.warnings.push_back({b.line, 0, b.text,
                                "arc end radius " + std::to_string(r1 * 1e3) + " mm differs from start radius " +
                                    std::to_string(r0 * 1e3) + " mm"});
      const bool full = std::hypot(dx, dy) < 1e-9;
      const double sweep = arcSweep(std::atan2(m.start_m[1] - cy, m.start_m[0] - cx),
                                    std::atan2(m.end_m[1] - cy, m.end_m[0] - cx), mode == 2, full);
      const double r = 0.5 * (r0 + r1);
      m.length_m = std::hypot(r * sweep, dz);
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
