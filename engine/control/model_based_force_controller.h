#pragma once
// Model-based force control for a known static force process F = K d^b f^a (Landers & Ulsoy, SMC I:
// F_Y = 0.76 d^0.65 f^0.63 in kN with d [mm] the depth of cut and f [mm/tooth] the feed per tooth).
// The model is inverted for the feed per tooth that gives the reference force at the current depth,
//   f = L (F_ref / (K (d/L)^b))^(1/a),
// and the feed rate v = f n_t N is then limited by the feed-drive maximum and the feed-per-tooth maximum.
// SI inside: K in N, d and f in m, L the length unit of the fitted model (1 mm for Landers & Ulsoy).
// Depth d <= 0 (the tool out of the part) puts no force limit: the feed goes to the smaller maximum.
#include <limits>
#include <string>

namespace mx {

struct PowerLawForceModel {
  double K_N = 760.0;            // 0.76 kN
  double depth_exponent = 0.65;  // b
  double feed_exponent = 0.63;   // a
  double length_unit_m = 1e-3;   // d and f are divided by this before the power law
};

struct ModelBasedForceSettings {
  PowerLawForceModel model;
  double reference_force_N = std::numeric_limits<double>::quiet_NaN();  // required, > 0
  int teeth = 4;
  double max_feed_rate_m_per_s = 36e-3;  // feed drive (Landers & Ulsoy: 36 mm/s)
  double max_feed_per_tooth_m = 0.6e-3;  // tool / handbook (0.6 mm/tooth)
};

enum class FeedLimit { Force, FeedDrive, FeedPerTooth };

struct ForceControlDecision {
  double feed_rate_m_per_s = 0.0;
  double feed_per_tooth_m = 0.0;
  double predicted_force_N = 0.0;  // the model's force at the chosen feed
  FeedLimit limit = FeedLimit::Force;
};

class ModelBasedForceController {
 public:
  // Throws InvalidInput naming the field for K, exponents, length unit, reference force, teeth or a
  // maximum that is not > 0.
  explicit ModelBasedForceController(ModelBasedForceSettings settings);

  // The model's force [N] at depth d [m] and feed per tooth f [m] (0 when d or f <= 0).
  double force(double depth_m, double feed_per_tooth_m) const;
  // The feed per tooth [m] giving force_N at depth d (+infinity when d <= 0).
  double feedPerToothForForce(double depth_m, double force_N) const;
  // The limited feed for the reference force at depth d and spindle speed N [rev/s] (> 0, else throws).
  ForceControlDecision feed(double depth_m, double speed_rev_per_s) const;
  ForceControlDecision feed(double depth_m, double speed_rev_per_s, double reference_force_N) const;

  const ModelBasedForceSettings& settings() const { return settings_; }
  static std::string limitName(FeedLimit limit);

 private:
  ModelBasedForceSettings settings_;
};

}  // namespace mx
