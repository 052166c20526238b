#pragma once
// Result of a stability-lobe computation: the individual lobes, the lower envelope b_lim(N) on the
// requested speed grid, and the local minima of the envelope. SI units: rev/s and m.
#include <limits>
#include <vector>

namespace mx {

struct SpeedGrid {
  double from_rev_per_s = 0.0;
  double to_rev_per_s = 0.0;
  double step_rev_per_s = 0.0;
  // from, from + step, ... <= to (inclusive within 1e-9 step); a whole number of steps ends at `to` exactly
  std::vector<double> values() const;
};

struct LobeCurve {
  int index = 0;  // k in omega_c T = eps + 2 k pi (eq. 9)
  std::vector<double> speed_rev_per_s;
  std::vector<double> depth_m;
  std::vector<double> chatter_hz;
};

struct LobeMinimum {
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  double chatter_hz = 0.0;  // 0 where the method does not give it
};

struct LobeDiagram {
  std::vector<LobeCurve> lobes;             // may be empty for methods without lobe curves
  std::vector<double> speed_rev_per_s;      // the requested grid
  std::vector<double> envelope_depth_m;     // b_lim at each speed; +inf where none below the cap
  std::vector<double> envelope_chatter_hz;  // chatter frequency on the envelope (0 if unknown)
  std::vector<LobeMinimum> minima;          // local minima of the envelope, by speed
  double delta_per_s = 0.0;                 // margin used (Rule 1.1)

  static constexpr double kNone = std::numeric_limits<double>::infinity();
};

// Local minima of a sampled envelope (interior points lower than both neighbours, refined by a
// parabola through three samples). Points at +inf are skipped, and so is a minimum that the envelope
// does not rise 1 % above on both sides before falling below it (root-finding noise, not a lobe).
std::vector<LobeMinimum> envelopeMinima(const std::vector<double>& speed, const std::vector<double>& depth,
                                        const std::vector<double>& chatter_hz);

}  // namespace mx
