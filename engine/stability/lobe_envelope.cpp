#include "stability/lobe_envelope.h"

#include <algorithm>

namespace mx {

LobeEnvelopeBuilder::LobeEnvelopeBuilder(std::vector<double> speeds_rev_per_s)
    : speeds_(std::move(speeds_rev_per_s)),
      depth_(speeds_.size(), LobeDiagram::kNone),
      chatter_hz_(speeds_.size(), 0.0) {}

void LobeEnvelopeBuilder::add(const LobeCurve& curve) {
  const auto& n = curve.speed_rev_per_s;
  for (size_t i = 0; i + 1 < n.size(); ++i) {
    const double n0 = n[i], n1 = n[i + 1];
    const double lo = std::min(n0, n1), hi = std::max(n0, n1);
    auto it = std::lower_bound(speeds_.begin(), speeds_.end(), lo);
    for (; it != speeds_.end() && *it <= hi; ++it) {
      const auto j = static_cast<size_t>(it - speeds_.begin());
      const double t = hi > lo ? (*it - n0) / (n1 - n0) : 0.0;
      const double b = curve.depth_m[i] + t * (curve.depth_m[i + 1] - curve.depth_m[i]);
      if (b < depth_[j]) {
        depth_[j] = b;
        chatter_hz_[j] = curve.chatter_hz[i] + t * (curve.chatter_hz[i + 1] - curve.chatter_hz[i]);
      }
    }
  }
}

void LobeEnvelopeBuilder::finish(LobeDiagram& out, double max_depth_m) const {
  out.speed_rev_per_s = speeds_;
  out.envelope_depth_m = depth_;
  out.envelope_chatter_hz = chatter_hz_;
  for (size_t j = 0; j < depth_.size(); ++j) {
    if (out.envelope_depth_m[j] > max_depth_m) {
      out.envelope_depth_m[j] = LobeDiagram::kNone;
      out.envelope_chatter_hz[j] = 0.0;
    }
  }
  out.minima = envelopeMinima(out.speed_rev_per_s, out.envelope_depth_m, out.envelope_chatter_hz);
}

}  // namespace mx
