#pragma once
// Lower envelope b_lim(N) of a set of lobe curves, sampled on a speed grid.
#include <vector>

#include "stability/lobe_diagram.h"

namespace mx {

class LobeEnvelopeBuilder {
 public:
  explicit LobeEnvelopeBuilder(std::vector<double> speeds_rev_per_s);

  // Folds one curve in: every grid speed covered by a segment of the curve takes the minimum of
  // its current value and the segment's linear interpolation (curves need not be monotonic in N).
  void add(const LobeCurve& curve);

  // Writes speeds, envelope (kNone above max_depth_m), chatter frequencies and local minima.
  void finish(LobeDiagram& out, double max_depth_m) const;

 private:
  std::vector<double> speeds_;
  std::vector<double> depth_;
  std::vector<double> chatter_hz_;
};

}  // namespace mx
