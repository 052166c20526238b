#pragma once
// The genetic-programming models of Cus & Zuperl (2008), section 4.1, exactly as printed. They work in
// the paper's units (Ra in um, F in N, feed f in mm/min, spindle speed n in rpm); the SI wrappers
// convert at the boundary.
//   K1 (eq. 1): F_d = 293 - 593 / sqrt(39.37 Ra)             desired force for a desired roughness
//   K2 (eq. 2): f   = 25.4 (189 - 5926160 / F^2)              feed command (negative for F < 177.07 N)
//   K3 (eq. 3): n   = sqrt(30064193 - 2.28 F^3)               spindle speed command (F < 236.25 N)
//   K4 (eq. 4): F   = 286.44 - 5.82e-10 n^3 - 8973 ln(0.039 f) / f    cutting process
//   K5 (eq. 5): Ra  = 0.0254 (593 / (293 - F))^2              roughness check (K1's exact inverse)
// K4 is not monotonic in f: it falls with f below f = e / 0.039 = 69.7 mm/min and rises above.
namespace mx {

class SdnrpModels {
 public:
  // Paper units. Each throws InvalidInput (naming the quantity, value and domain) outside its domain.
  static double desiredForce(double ra_um);                          // K1
  static double feedCommand(double force_N);                         // K2, may be negative
  static double speedCommand(double force_N);                        // K3
  static double cuttingForce(double speed_rpm, double feed_mm_min);  // K4
  static double roughness(double force_N);                           // K5
  // dK4/df [N per mm/min], > 0 for f > 69.7 mm/min.
  static double cuttingForceFeedSensitivity(double feed_mm_min);
  // The feed where K4 turns (its minimum over f): e / 0.039 mm/min.
  static double turningFeed();
};

}  // namespace mx
