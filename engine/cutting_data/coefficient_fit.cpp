#include "cutting_data/coefficient_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/invalid_input.h"

namespace mx {
namespace {

// Integrals over the immersion [phi_st, phi_ex] of the model's angle factors.
struct ArcIntegrals {
  double sc = 0.0;   // sin cos
  double ss = 0.0;   // sin^2
  double c = 0.0;    // cos
  double s = 0.0;    // sin
  double arc = 0.0;  // phi_ex - phi_st
};

ArcIntegrals arcIntegrals(const TestCutSetup& setup) {
  const Immersion im =
      Immersion::fromRadialDepth(setup.radial_ratio * setup.diameter_m, setup.diameter_m, setup.direction);
  auto between = [&](auto f) { return f(im.exit_rad) - f(im.entry_rad); };
  ArcIntegrals i;
  i.sc = between([](double p) { return 0.5 * std::sin(p) * std::sin(p); });
  i.ss = between([](double p) { return 0.5 * p - 0.25 * std::sin(2.0 * p); });
  i.c = between([](double p) { return std::sin(p); });
  i.s = between([](double p) { return -std::cos(p); });
  i.arc = im.exit_rad - im.entry_rad;
  return i;
}

double engagedTeethFactor(const TestCutSetup& setup) {  // n_t a / 2 pi
  return setup.teeth * setup.depth_m / (2.0 * std::numbers::pi);
}

void validate(const TestCutSetup& s) {
  auto fail = [](const std::string& field, double v, const char* range) {
    throw InvalidInput("test cut " + field + " = " + std::to_string(v) + ": must be " + range);
  };
  if (s.teeth < 1 || s.teeth > MillingSetup::kMaxTeeth) fail("teeth", s.teeth, "an integer in [1, 100]");
  if (!(s.diameter_m > 0.0) || !std::isfinite(s.diameter_m)) fail("diameter_m", s.diameter_m, "> 0");
  if (!(s.depth_m > 0.0) || !std::isfinite(s.depth_m)) fail("depth_m", s.depth_m, "> 0");
  if (!(s.radial_ratio > 0.0 && s.radial_ratio <= 1.0)) fail("radial_ratio", s.radial_ratio, "in (0, 1]");
}

void validate(const std::vector<TestCut>& cuts) {
  if (cuts.size() < 2)
    throw InvalidInput("test cuts: " + std::to_string(cuts.size()) + " given: at least 2 feeds are needed for a line");
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const TestCut& c = cuts[i];
    const std::string row = "test cut " + std::to_string(i + 1) + ": ";
    if (!(c.feed_per_tooth_m > 0.0) || !std::isfinite(c.feed_per_tooth_m))
      throw InvalidInput(row + "feed per tooth = " + std::to_string(c.feed_per_tooth_m) + " m: must be > 0");
    if (!std::isfinite(c.fx_n) || !std::isfinite(c.fy_n) || !std::isfinite(c.fz_n))
      throw InvalidInput(row + "a force is not a finite number");
  }
  const auto [lo, hi] = std::minmax_element(cuts.begin(), cuts.end(), [](const TestCut& a, const TestCut& b) {
    return a.feed_per_tooth_m < b.feed_per_tooth_m;
  });
  if (hi->feed_per_tooth_m - lo->feed_per_tooth_m <= 1e-9 * hi->feed_per_tooth_m)
    throw InvalidInput("test cuts: every cut has the feed per tooth " + std::to_string(lo->feed_per_tooth_m) +
                       " m: at least 2 different feeds are needed for a line");
}

AxisLine fitLine(const std::vector<TestCut>& cuts, double TestCut::*force) {
  const auto n = static_cast<double>(cuts.size());
  double c_mean = 0.0, f_mean = 0.0;
  for (const TestCut& c : cuts) c_mean += c.feed_per_tooth_m / n, f_mean += c.*force / n;
  double sxx = 0.0, sxy = 0.0, sst = 0.0;
  for (const TestCut& c : cuts) {
    const double dc = c.feed_per_tooth_m - c_mean, df = c.*force - f_mean;
    sxx += dc * dc, sxy += dc * df, sst += df * df;
  }
  AxisLine line;
  line.slope = sxy / sxx;
  line.intercept = f_mean - line.slope * c_mean;
  double sse = 0.0;
  for (const TestCut& c : cuts) {
    const double r = c.*force - (line.slope * c.feed_per_tooth_m + line.intercept);
    line.residuals_n.push_back(r);
    sse += r * r;
  }
  line.r2 = sst > 0.0 ? 1.0 - sse / sst : 1.0;
  if (cuts.size() > 2) {
    const double s2 = sse / (n - 2.0);
    line.slope_stderr = std::sqrt(s2 / sxx);
    line.intercept_stderr = std::sqrt(s2 * (1.0 / n + c_mean * c_mean / sxx));
  }
  return line;
}

}  // namespace

double studentT95(int dof) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) throw InvalidInput("Student t: degrees of freedom = " + std::to_string(dof) + ": must be >= 1");
  if (dof <= 30) return kTable[dof - 1];
  // Cornish-Fisher expansion about the normal quantile (Abramowitz & Stegun 26.7.5).
  const double z = 1.959963984540054, v = dof;
  return z + (z * z * z + z) / (4.0 * v) + (5 * std::pow(z, 5) + 16 * std::pow(z, 3) + 3 * z) / (96.0 * v * v) +
         (3 * std::pow(z, 7) + 19 * std::pow(z, 5) + 17 * std::pow(z, 3) - 15 * z) / (384.0 * v * v * v);
}

TestCut meanCutForces(const TestCutSetup& setup, const CuttingCoefficients& k, double c) {
  validate(setup);
  const ArcIntegrals i = arcIntegrals(setup);
  const double g = engagedTeethFactor(setup);
  TestCut cut;
  cut.feed_per_tooth_m = c;
  cut.fx_n = g * (-k.Ktc_pa * c * i.sc - k.Krc_pa * c * i.ss - k.Kte_n_per_m * i.c - k.Kre_n_per_m * i.s);
  cut.fy_n = g * (k.Ktc_pa * c * i.ss - k.Krc_pa * c * i.sc + k.Kte_n_per_m * i.s - k.Kre_n_per_m * i.c);
  cut.fz_n = g * (k.Kac_pa * c * i.s + k.Kae_n_per_m * i.arc);
  return cut;
}

CoefficientFit fitCuttingCoefficients(const TestCutSetup& setup, const std::vector<TestCut>& cuts) {
  validate(setup);
  validate(cuts);
  CoefficientFit fit;
  fit.lines = {fitLine(cuts, &TestCut::fx_n), fitLine(cuts, &TestCut::fy_n), fitLine(cuts, &TestCut::fz_n)};
  const ArcIntegrals i = arcIntegrals(setup);
  const double g = engagedTeethFactor(setup);
  const AxisLine &x = fit.lines[0], &y = fit.lines[1], &z = fit.lines[2];
  // x and y: [-S_sc -S_ss; S_ss -S_sc] (K_tc, K_rc) = slopes / g, and the same with S_c, S_s for the edges.
  const double det_c = i.sc * i.sc + i.ss * i.ss, det_e = i.c * i.c + i.s * i.s;
  CuttingCoefficients& k = fit.coefficients;
  k.Ktc_pa = (-i.sc * x.slope + i.ss * y.slope) / (g * det_c);
  k.Krc_pa = (-i.ss * x.slope - i.sc * y.slope) / (g * det_c);
  k.Kte_n_per_m = (-i.c * x.intercept + i.s * y.intercept) / (g * det_e);
  k.Kre_n_per_m = (-i.s * x.intercept - i.c * y.intercept) / (g * det_e);
  k.Kac_pa = z.slope / (g * i.s);
  k.Kae_n_per_m = z.intercept / (g * i.arc);
  if (cuts.size() > 2) {
    const double t = studentT95(static_cast<int>(cuts.size()) - 2);
    auto pair = [&](double a, double b, double sa, double sb, double det) {
      return t * std::hypot(a * sa, b * sb) / (g * det);
    };
    CuttingCoefficients& h = fit.half_width_95;
    h.Ktc_pa = pair(i.sc, i.ss, x.slope_stderr, y.slope_stderr, det_c);
    h.Krc_pa = pair(i.ss, i.sc, x.slope_stderr, y.slope_stderr, det_c);
    h.Kte_n_per_m = pair(i.c, i.s, x.intercept_stderr, y.intercept_stderr, det_e);
    h.Kre_n_per_m = pair(i.s, i.c, x.intercept_stderr, y.intercept_stderr, det_e);
    h.Kac_pa = t * z.slope_stderr / (g * i.s);
    h.Kae_n_per_m = t * z.intercept_stderr / (g * i.arc);
  }
  return fit;
}

}  // namespace mx
