#include "machining/part_program_override.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"

namespace mx {

BlockFeedController modelBasedFeedController(const ModelBasedForceController& controller) {
  return [c = controller](const CutState& s) {
    const auto d = c.feed(s.depth_m, s.speed_rev_per_s);
    return FeedDecision{d.feed_rate_m_per_s, d.predicted_force_N, ModelBasedForceController::limitName(d.limit)};
  };
}

PartProgramOverrider::PartProgramOverrider(BlockFeedController controller, PartProgramOverrideSettings settings)
    : controller_(std::move(controller)),
      settings_(std::move(settings)),
      profile_(settings_.depth_profile.empty() ? DepthProfile::fromStockTop(settings_.stock_top_z_m)
                                               : DepthProfile::fromSegments(settings_.depth_profile)) {
  if (!controller_) throw InvalidInput("part-program override: controller = none: a force controller is required");
  const double n = settings_.speed_rev_per_s;
  if (n == n && !(n > 0.0 && std::isfinite(n)))
    throw InvalidInput("part-program override: speed = " + std::to_string(n * 60.0) + " rpm: must be > 0");
}

PartProgramOverrideResult PartProgramOverrider::run(std::string_view text) const {
  return run(GcodeReader::parse(text));
}

namespace {

// The value of a number once written with `decimals` decimals (what the machine will read).
double written(double v, int decimals) {
  const std::string s = GcodeWriter::formatNumber(v, decimals);
  double out = 0.0;
  std::from_chars(s.data(), s.data() + s.size(), out);
  return out;
}

bool sameFeed(double a, double b) {
  return a == a && b == b && std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

// LinuxCNC's adaptive-feed input (M52 P1 on, M52 P0 or M52 off) scales every F by an analogue input: a
// changed F under it is not the feed the machine will run, which the operator is told once.
// Followed block by block, in LinuxCNC programs only.
struct AdaptiveFeedInput {
  int enabled_at = 0;  // the line of the M52 P1 in effect, 0 when off
  bool warned = false;

  void follow(const GcodeBlock& b) {
    for (const GcodeWord& w : b.words)
      if (w.known && w.address == "M" && std::abs(w.value - 52.0) < 1e-9) {
        const GcodeWord* p_word = b.find('P');
        enabled_at = p_word && p_word->value != 0.0 ? b.line : 0;
      }
  }
  void warnIfScaling(const GcodeBlock& b, std::vector<GcodeWarning>& warnings) {
    if (warned || enabled_at == 0) return;
    warned = true;
    warnings.push_back({b.line, 0, b.text,
                        "M52 P1 (line " + std::to_string(enabled_at) +
                            ") is in effect: the machine's adaptive-feed input scales the new F further"});
  }
};

}  // namespace

PartProgramOverrideResult PartProgramOverrider::run(GcodeProgram program) const {
  PartProgramOverrideResult r;
  r.program = std::move(program);
  r.run = GcodeInterpreter(settings_.interpreter).run(r.program);
  r.depths_m = profile_.blockDepths(r.run);
  r.edits.assign(r.program.blocks.size(), GcodeBlockEdit{});

  const bool speed_override = settings_.speed_rev_per_s == settings_.speed_rev_per_s;
  const double target_rpm = settings_.speed_rev_per_s * 60.0;
  double out_feed = std::numeric_limits<double>::quiet_NaN();   // feed in effect in the output [m/s]
  double out_speed = std::numeric_limits<double>::quiet_NaN();  // speed in effect in the output [rev/s]
  double path = 0.0;
  constexpr std::size_t kNone = std::string::npos;
  std::size_t speed_carrier = kNone;  // the last block that has or takes an S word
  const bool linuxcnc = r.program.dialect.dialect == GcodeDialect::LinuxCnc;
  AdaptiveFeedInput adaptive_input;

  for (std::size_t i = 0; i < r.program.blocks.size(); ++i) {
    const auto& b = r.program.blocks[i];
    const auto& m = r.run.motions[i];
    auto& e = r.edits[i];
    if (linuxcnc) adaptive_input.follow(b);
    std::string reason;
    const double unit = m.inch ? GcodeInterpreter::kInch : 1e-3;
    const int decimals = m.inch ? settings_.feed_decimals_inch : settings_.feed_decimals_mm;
    e.feed_decimals = decimals;

    // Spindle speed: every S word becomes the expert system's speed; a feed move with no S in effect
    // gets one, in its own block or, where the dialect keeps S elsewhere (Heidenhain: in the TOOL CALL),
    // in the last block before it that takes one.
    bool speed_changed = false;
    if (m.speed_word) out_speed = m.speed_rev_per_s;
    if (b.speedWord() || b.speed_insert_at != std::string::npos) speed_carrier = i;
    const bool wrong_word = m.speed_word && std::abs(m.speed_rev_per_s * 60.0 - target_rpm) > 1e-9;
    if (speed_override && (wrong_word || (m.isFeedMove() && !sameFeed(out_speed, settings_.speed_rev_per_s)))) {
      const std::size_t carrier = wrong_word ? i : speed_carrier;
      if (carrier == kNone)
        throw InvalidInput("part program line " + std::to_string(b.line) +
                           ": a feed move with no spindle speed before it, "
                           "and no block before it that takes an S word in " +
                           std::string(dialectTitle(r.program.dialect.dialect)) + " (a TOOL CALL): add one");
      const std::string speed_reason = "S " + GcodeWriter::formatNumber(target_rpm, 0) + " rpm from the expert system";
      r.edits[carrier].speed_rpm = target_rpm;
      out_speed = settings_.speed_rev_per_s;
      speed_changed = true;
      if (carrier == i)
        reason = speed_reason;
      else if (r.edits[carrier].comment.empty())
        r.edits[carrier].comment = "MX: " + speed_reason;
    }
    // The F word of the block, unless edited below, sets the output's modal feed.
    if (m.feed_word) out_feed = m.feed_m_per_s;
    if (!m.isFeedMove()) {
      if (!reason.empty()) e.comment = "MX: " + reason;
      continue;
    }

    CutState s;
    s.block = i;
    s.line = b.line;
    s.depth_m = r.depths_m[i];
    s.speed_rev_per_s = speed_override ? settings_.speed_rev_per_s : m.speed_rev_per_s;
    s.programmed_feed_m_per_s = m.feed_missing ? std::numeric_limits<double>::quiet_NaN() : m.feed_m_per_s;
    s.path_position_m = path;
    s.length_m = m.length_m;
    path += m.length_m;

    FeedDecision d;
    std::string feed_reason;
    const bool plunge = settings_.keep_plunge_feed && m.end_m[2] < m.start_m[2] &&
                        std::hypot(m.end_m[0] - m.start_m[0], m.end_m[1] - m.start_m[1]) < 1e-9;
    if (s.depth_m <= 0.0 && m.feed_missing)
      throw InvalidInput("part program line " + std::to_string(b.line) +
                         ": a feed move with no F word before it, above the stock where no controller sets the "
                         "feed: add an F word to this line or an earlier one");
    if ((s.depth_m <= 0.0 || plunge) && !m.feed_missing) {  // air move or plunge: keep the programmed feed
      d.feed_m_per_s = s.programmed_feed_m_per_s;
      d.predicted_force_N = s.depth_m <= 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
      feed_reason = s.depth_m <= 0.0 ? "restore programmed feed (air move)" : "restore programmed feed (plunge)";
    } else {
      if (!(s.speed_rev_per_s > 0.0))
        throw InvalidInput("part-program override: spindle speed at line " + std::to_string(b.line) +
                           " = none: the program has no S before this feed move and no speed was given (must be > 0)");
      d = controller_(s);
      if (!(d.feed_m_per_s > 0.0) || !std::isfinite(d.feed_m_per_s))
        throw InvalidInput("part-program override: controller feed at line " + std::to_string(b.line) + " = " +
                           std::to_string(d.feed_m_per_s) + " m/s: must be > 0 and finite");
      feed_reason = (m.feed_missing ? "missing F, " : "") + d.reason;
    }
    const double wanted_units = d.feed_m_per_s * 60.0 / unit;  // program units / min
    const double wanted = written(wanted_units, decimals);
    const double wanted_si = wanted * unit / 60.0;
    // Unchanged when the feed in effect already equals the wanted one at the written resolution.
    const double resolution = 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9);
    const bool same = out_feed == out_feed && (sameFeed(out_feed, d.feed_m_per_s) ||
                                               std::abs(out_feed * 60.0 / unit - wanted_units) <= resolution);
    bool feed_changed = false;
    if (!same) {
      e.feed = wanted;
      out_feed = wanted_si;
      feed_changed = true;
      if (reason.empty()) {
        reason = feed_reason;
      } else {
        reason.insert(0, "; ");
        reason.insert(0, feed_reason);
      }
    }
    if (!reason.empty()) {
      std::string c = "MX: ";
      if (feed_changed) {
        c += "F " + GcodeWriter::formatNumber(wanted, decimals) + (m.inch ? " in/min" : " mm/min") + ", ";
        if (d.predicted_force_N == d.predicted_force_N && s.depth_m > 0.0)
          c += "predicted " + GcodeWriter::formatNumber(d.predicted_force_N, 0) + " N at depth " +
               GcodeWriter::formatNumber(s.depth_m * 1e3, 3) + " mm, ";
      }
      e.comment = c + reason;
    }
    if (feed_changed) adaptive_input.warnIfScaling(b, r.warnings);
    FeedOverrideRow row;
    row.block = i + 1;
    row.line = b.line;
    row.original_feed_m_per_s = s.programmed_feed_m_per_s;
    row.new_feed_m_per_s = out_feed;
    row.speed_rev_per_s = s.speed_rev_per_s;
    row.depth_m = s.depth_m;
    row.predicted_force_N = d.predicted_force_N;
    row.feed_changed = feed_changed;
    row.speed_changed = speed_changed;
    row.reason = reason;
    r.rows.push_back(std::move(row));
  }
  r.changed_blocks = static_cast<std::size_t>(
      std::count_if(r.edits.begin(), r.edits.end(), [](const GcodeBlockEdit& e) { return !e.empty(); }));
  r.warnings.insert(r.warnings.begin(), r.program.warnings.begin(), r.program.warnings.end());
  r.warnings.insert(r.warnings.end(), r.run.warnings.begin(), r.run.warnings.end());
  std::stable_sort(r.warnings.begin(), r.warnings.end(),
                   [](const GcodeWarning& a, const GcodeWarning& c) { return a.line < c.line; });
  return r;
}

}  // namespace mx
