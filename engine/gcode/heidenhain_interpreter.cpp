#include "gcode/heidenhain_interpreter.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "gcode/arc_geometry.h"

namespace mx {
namespace {

class HeidenhainRun {
 public:
  explicit HeidenhainRun(const GcodeInterpreterSettings& settings)
      : pos_(settings.start_m), inch_(settings.start_inch) {}

  GcodeRun run(const GcodeProgram& program) {
    out_.motions.reserve(program.blocks.size());
    for (const GcodeBlock& b : program.blocks) out_.motions.push_back(block(b));
    return std::move(out_);
  }

 private:
  GcodeRun out_;
  std::array<double, 3> pos_;
  bool inch_;
  double feed_ = std::numeric_limits<double>::quiet_NaN();       // modal F [m/s]
  double tool_feed_ = std::numeric_limits<double>::quiet_NaN();  // TOOL CALL F: what F AUTO stands for
  double speed_ = std::numeric_limits<double>::quiet_NaN();      // [rev/s]
  std::optional<arc::Point> centre_;
  std::optional<arc::Point> tangent_;  // unit direction at the end of the last element in the plane

  double unit() const { return inch_ ? GcodeInterpreter::kInch : 1e-3; }

  GcodeMotion block(const GcodeBlock& b) {
    GcodeMotion m;
    m.start_m = pos_;
    m.end_m = pos_;
    if (b.keyword == "BEGIN PGM") inch_ = b.words.size() > 2 && b.words.back().address == "INCH";
    m.inch = inch_;
    if (b.keyword == "TOOL CALL") toolCall(b, m);
    const std::string& k = b.keyword;
    if (k == "L" || k == "C" || k == "CR" || k == "CT") feedWords(b, m);
    m.feed_m_per_s = feed_;
    m.speed_rev_per_s = speed_;
    if (k == "CC") circleCentre(b);
    if (k == "L") straight(b, m);
    if (k == "C" || k == "CR" || k == "CT") circular(b, m);
    if (m.isFeedMove() && !(feed_ > 0.0)) {
      m.feed_missing = true;
      out_.warnings.push_back({b.line, 0, b.text, "feed move without F (no modal F either)"});
    }
    pos_ = m.end_m;
    return m;
  }

  void toolCall(const GcodeBlock& b, GcodeMotion& m) {
    if (const GcodeWord* s = b.speedWord()) speed_ = s->value / 60.0, m.speed_word = true;
    for (std::size_t i = 1; i < b.words.size(); ++i)
      if (b.words[i].address == "F" && b.words[i].has_value) tool_feed_ = b.words[i].value * unit() / 60.0;
  }

  void feedWords(const GcodeBlock& b, GcodeMotion& m) {
    const GcodeWord* f = b.feedWord();
    if (!f) return;
    m.feed_word = true;
    if (f->address == "FAUTO") {
      feed_ = tool_feed_;
      if (!(tool_feed_ > 0.0))
        out_.warnings.push_back(
            {b.line, f->column, b.text.substr(f->column - 1, f->length), "F AUTO without a TOOL CALL F"});
      return;
    }
    feed_ = f->value * unit() / 60.0;
    if (!(f->value > 0.0))
      out_.warnings.push_back({b.line, f->column, b.text.substr(f->column - 1, f->length), "F must be > 0"});
  }

  // The block's end point from X, Y, Z (absolute) and IX, IY, IZ (incremental); true when any is given.
  bool endPoint(const GcodeBlock& b, std::array<double, 3>& end) const {
    static constexpr const char* kAbsolute[3] = {"X", "Y", "Z"};
    static constexpr const char* kIncremental[3] = {"IX", "IY", "IZ"};
    bool any = false;
    for (std::size_t a = 0; a < 3; ++a) {
      if (const GcodeWord* w = b.findAddress(kAbsolute[a]); w && w->known) end[a] = w->value * unit(), any = true;
      if (const GcodeWord* w = b.findAddress(kIncremental[a]); w && w->known)
        end[a] = pos_[a] + w->value * unit(), any = true;
    }
    return any;
  }

  void circleCentre(const GcodeBlock& b) {
    std::array<double, 3> c = pos_;
    endPoint(b, c);
    centre_ = arc::Point{c[0], c[1]};
  }

  void straight(const GcodeBlock& b, GcodeMotion& m) {
    if (!endPoint(b, m.end_m)) return;
    const bool rapid =
        std::any_of(b.words.begin(), b.words.end(), [](const GcodeWord& w) { return w.address == "FMAX"; });
    m.kind = rapid ? MotionKind::Rapid : MotionKind::Linear;
    const double dx = m.end_m[0] - m.start_m[0], dy = m.end_m[1] - m.start_m[1], dz = m.end_m[2] - m.start_m[2];
    m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (std::hypot(dx, dy) > 1e-12) tangent_ = arc::Point{dx / std::hypot(dx, dy), dy / std::hypot(dx, dy)};
  }

  void circular(const GcodeBlock& b, GcodeMotion& m) {
    const bool moved = endPoint(b, m.end_m);
    const arc::Point s{m.start_m[0], m.start_m[1]}, e{m.end_m[0], m.end_m[1]};
    const double dz = m.end_m[2] - m.start_m[2];
    const GcodeWord* dr = b.findAddress("DR");
    bool clockwise = dr && dr->value < 0.0;
    std::optional<arc::Point> centre;
    double plane_length = 0.0;
    if (b.keyword == "C") {
      if (!centre_)
        out_.warnings.push_back({b.line, 0, b.text, "C without a CC before it: the centre is the program zero"});
      centre = centre_.value_or(arc::Point{0.0, 0.0});
      if (!moved) m.end_m = m.start_m;  // C alone: a full circle
    } else if (b.keyword == "CR") {
      const GcodeWord* r = b.findAddress("R");
      if (r) centre = arc::centreFromRadius(s, e, r->value * unit(), clockwise);
      if (!centre)
        out_.warnings.push_back(
            {b.line, 0, b.text, "CR without R, or R shorter than half the chord: treated as a straight move"});
    } else if (tangent_) {
      if (const auto t = arc::tangentArc(s, e, *tangent_))
        centre = t->centre, clockwise = t->clockwise, plane_length = t->length;
    } else {
      out_.warnings.push_back({b.line, 0, b.text, "CT without an element before it: treated as a straight move"});
    }
    const double dx = m.end_m[0] - m.start_m[0], dy = m.end_m[1] - m.start_m[1];
    if (!centre) {
      m.kind = MotionKind::Linear;
      m.length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (std::hypot(dx, dy) > 1e-12) tangent_ = arc::Point{dx / std::hypot(dx, dy), dy / std::hypot(dx, dy)};
      return;
    }
    m.kind = clockwise ? MotionKind::ArcCw : MotionKind::ArcCcw;
    if (b.keyword != "CT") plane_length = arc::length(s, arc::Point{m.end_m[0], m.end_m[1]}, *centre, clockwise);
    m.length_m = std::hypot(plane_length, dz);
    const double rx = m.end_m[0] - (*centre)[0], ry = m.end_m[1] - (*centre)[1], r = std::hypot(rx, ry);
    if (r > 1e-12) tangent_ = clockwise ? arc::Point{ry / r, -rx / r} : arc::Point{-ry / r, rx / r};
  }
};

}  // namespace

GcodeRun interpretHeidenhain(const GcodeProgram& program, const GcodeInterpreterSettings& settings) {
  return HeidenhainRun(settings).run(program);
}

}  // namespace mx
