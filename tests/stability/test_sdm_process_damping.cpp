// Process damping in the semi-discretization (stability/sdm_model.h; docs/fidelity.md, "Process damping"):
// the C_i / V model against the exact boundary of a single-degree-of-freedom cut.
//
// Four teeth slotting with one mode on y and a rigid x: at every instant two teeth cut, 90 deg apart, so
// sum_j (sin phi_j cos phi_j) = 0 and sum_j cos^2 phi_j = 1 over the cutting teeth. The periodic model
// is then exactly the autonomous delay equation
//   m y'' + (c + C_i b / V) y' + k y + K_t K_r b (y(t) - y(t - tau)) = 0,   tau = 1 / (n_t N),  V = pi D N,
// whose stability boundary at s = i omega is
//   k - m omega^2 + K_t K_r b (1 - cos omega tau) = 0,   (c + C_i b / V) omega + K_t K_r b sin omega tau = 0.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "stability/semi_discretization.h"
#include "support/fixtures.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {

using mx::test::kPi;
constexpr double kModeHz = 300.0, kZeta = 0.01, kStiffness = 5e6;
constexpr double kCi = 1e4;  // N/m

MillingSetup slotOnOneMode(double process_damping_n_per_m) {
  MillingSetup s = test::makeSetup(4, 0.010, 6e8, 0.3, {}, {{kModeHz, kZeta, kStiffness}}, MillingDirection::Down, 1.0);
  s.process_damping_n_per_m = process_damping_n_per_m;
  return s;
}

// The least depth on the boundary above, by a scan of omega over (omega_n, 4 omega_n] and bisection of
// b_real(omega) - b_imag(omega), the depths that satisfy each equation alone.
double exactDepthLimit(const MillingSetup& s, double rev_per_s) {
  const Mode& mode = s.modes_y.front();
  const double w_n = mode.angularFrequency(), m = mode.modalMass(), c = 2.0 * kZeta * m * w_n;
  const double beta = s.tangential_coefficient_pa * s.radial_ratio;
  const double gamma = s.processDampingPerDepth(rev_per_s), tau = 1.0 / (s.teeth * rev_per_s);
  auto b_real = [&](double w) { return (m * w * w - kStiffness) / (beta * (1.0 - std::cos(w * tau))); };
  auto b_imag = [&](double w) { return -c * w / (gamma * w + beta * std::sin(w * tau)); };
  auto gap = [&](double w) { return b_real(w) - b_imag(w); };
  auto admissible = [&](double w) { return b_real(w) > 0.0 && b_imag(w) > 0.0 && std::isfinite(gap(w)); };
  double best = std::numeric_limits<double>::infinity();
  constexpr int kScan = 200000;
  double w0 = w_n * (1.0 + 1e-9);
  for (int i = 1; i <= kScan; ++i) {
    const double w1 = w_n * (1.0 + 3.0 * i / kScan);
    if (admissible(w0) && admissible(w1) && (gap(w0) > 0.0) != (gap(w1) > 0.0)) {
      double lo = w0, hi = w1;
      for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((gap(mid) > 0.0) == (gap(lo) > 0.0) ? lo : hi) = mid;
      }
      const double b = b_real(0.5 * (lo + hi));
      if (std::abs(gap(0.5 * (lo + hi))) < 1e-6 * b) best = std::min(best, b);  // a root, not a pole
    }
    w0 = w1;
  }
  return best;
}

double sdmDepthLimit(const MillingSetup& s, double rev_per_s) {
  SdmOptions o;
  o.depth_tolerance = 1e-5;
  return computeSdmLobes(s, {rev_per_s}, o).envelope_depth_m.front();
}

}  // namespace

class TestSdmProcessDamping : public QObject {
  Q_OBJECT
 private slots:
  // The SDM agrees with the exact boundary to 0.1 %, with and without process damping, from 600 rpm (V =
  // 0.31 m/s) to 6000 rpm.
  void matchesTheExactSingleModeBoundary_data() {
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("process_damping");
    for (double rpm : {600.0, 1000.0, 2500.0, 6000.0}) {
      QTest::addRow("%g rpm, no process damping", rpm) << rpm << 0.0;
      QTest::addRow("%g rpm, C_i = 1e4 N/m", rpm) << rpm << kCi;
    }
  }
  void matchesTheExactSingleModeBoundary() {
    QFETCH(double, rpm);
    QFETCH(double, process_damping);
    const MillingSetup s = slotOnOneMode(process_damping);
    const double exact = exactDepthLimit(s, rpmToRevPerS(rpm)), sdm = sdmDepthLimit(s, rpmToRevPerS(rpm));
    qInfo("SDM %.5f mm, exact %.5f mm (%+.3f %%)", sdm * 1e3, exact * 1e3, 100.0 * (sdm / exact - 1.0));
    QVERIFY2(std::isfinite(exact), "no boundary found");
    QVERIFY2(std::abs(sdm / exact - 1.0) < 1e-3,
             qPrintable(QString("SDM %1 mm, exact %2 mm").arg(sdm * 1e3).arg(exact * 1e3)));
  }

  // Process damping raises the limit most at low speed, and its effect falls as 1 / V: at 600 rpm the limit
  // rises by over 30 %, at 6000 rpm by less than a quarter of that rise.
  void riseFallsWithSpeed() {
    auto rise = [](double rpm) {
      return sdmDepthLimit(slotOnOneMode(kCi), rpmToRevPerS(rpm)) /
             sdmDepthLimit(slotOnOneMode(0.0), rpmToRevPerS(rpm));
    };
    const double slow = rise(600.0), fast = rise(6000.0);
    qInfo("limit with / without C_i: %.4f at 600 rpm, %.4f at 6000 rpm", slow, fast);
    QVERIFY2(slow > 1.3, qPrintable(QString::number(slow)));
    QVERIFY2(fast > 1.0 && fast - 1.0 < 0.25 * (slow - 1.0), qPrintable(QString("%1 vs %2").arg(fast).arg(slow)));
  }

  // Strong enough, process damping stabilises every depth: with C_i = 1e5 N/m at 600 rpm the damping it adds,
  // C_i b / V, grows faster with b than the regenerative gain, and neither the exact boundary nor the SDM
  // has a limit below the 20 mm the search covers.
  void strongProcessDampingStabilisesEveryDepth() {
    const MillingSetup s = slotOnOneMode(10.0 * kCi);
    QVERIFY(!std::isfinite(exactDepthLimit(s, rpmToRevPerS(600.0))));
    QVERIFY(!std::isfinite(sdmDepthLimit(s, rpmToRevPerS(600.0))));
  }

  // At the minimum of a lobe (the asymptotic limit 2 k zeta (1 + zeta) / (K_t K_r) without process damping),
  // with zeta_e = zeta + C_i b / (2 m omega_n V) the limit solves b = 2 k zeta_e (1 + zeta_e) / (K_t K_r)
  // (V held at its value at 610 rpm): checked where the lobes are dense (the 7th lobe, about 80 rpm wide)
  // over a window of more than one lobe.
  void lobeMinimumFollowsTheEffectiveDamping() {
    const MillingSetup s = slotOnOneMode(kCi);
    const double beta = s.tangential_coefficient_pa * s.radial_ratio, w_n = 2.0 * kPi * kModeHz;
    const double m = kStiffness / (w_n * w_n);
    std::vector<double> speeds;
    for (int i = 0; i <= 100; ++i) speeds.push_back(rpmToRevPerS(560.0 + i));
    SdmOptions o;
    o.depth_tolerance = 1e-5;
    const LobeDiagram d = computeSdmLobes(s, speeds, o);
    double lowest = std::numeric_limits<double>::infinity();
    for (double b : d.envelope_depth_m) lowest = std::min(lowest, b);
    const double v = kPi * s.diameter_m * rpmToRevPerS(610.0);
    double b = 2.0 * kStiffness * kZeta * (1.0 + kZeta) / beta;  // fixed point of the effective damping
    for (int k = 0; k < 50; ++k) {
      const double zeta_e = kZeta + kCi * b / (2.0 * m * w_n * v);
      b = 2.0 * kStiffness * zeta_e * (1.0 + zeta_e) / beta;
    }
    qInfo("lowest SDM limit %.4f mm, effective-damping estimate %.4f mm", lowest * 1e3, b * 1e3);
    QVERIFY2(std::abs(lowest / b - 1.0) < 0.03,
             qPrintable(QString("SDM %1 mm, estimate %2 mm").arg(lowest * 1e3).arg(b * 1e3)));
  }
};

MX_REGISTER_TEST(TestSdmProcessDamping)
#include "test_sdm_process_damping.moc"
