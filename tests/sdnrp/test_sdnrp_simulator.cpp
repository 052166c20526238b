// The SDNRP loop: exact convergence without disturbance, Table 2 of Cus & Zuperl with the disturbance
// on (reference data and tolerances in tests/data/sdnrp/table2.csv), the six console signals.
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "sdnrp/gp_models.h"
#include "sdnrp/sdnrp_simulator.h"
#include "test_registry.h"

using namespace mx;

namespace {
constexpr double kMmMin = 1e-3 / 60.0;
SdnrpSettings row(double ra_um, double fc_mm_min, double nc_rpm, bool disturbance) {
  SdnrpSettings s;
  s.ra_desired_m = ra_um * 1e-6;
  s.initial_feed_m_per_s = fc_mm_min * kMmMin;
  s.initial_speed_rev_per_s = nc_rpm / 60.0;
  s.disturbance.enabled = disturbance;
  return s;
}
}  // namespace

class TestSdnrpSimulator : public QObject {
  Q_OBJECT
 private slots:
  void convergesExactlyWithoutDisturbance() {
    // Table 2 row 5: Ra 0.81 um from f = 430.41 mm/min, n = 1571 rpm
    const auto r = SdnrpSimulator(row(0.81, 430.41, 1571, false)).run();
    QVERIFY(std::abs(r.fd_N - SdnrpModels::desiredForce(0.81)) < 1e-12);
    QVERIFY2(std::abs(r.f_final_N - r.fd_N) < 1e-8, qPrintable(QString::number(r.f_final_N - r.fd_N)));
    QVERIFY(std::abs(r.ra_produced_m / r.ra_desired_m - 1.0) < 1e-5);  // K5(K1(Ra)) = 0.999998 Ra
    QVERIFY(std::abs(r.speed_final_rev_per_s - SdnrpModels::speedCommand(r.fd_N) / 60.0) < 1e-9);
    // the final feed solves K4(n_c, f) = F_d
    QVERIFY(std::abs(SdnrpModels::cuttingForce(r.speed_final_rev_per_s * 60.0, r.feed_final_m_per_s / kMmMin) -
                     r.fd_N) < 1e-8);
    QVERIFY(!r.feed_saturated);
    // the last samples are flat
    const auto& last = r.samples.back();
    QVERIFY(std::abs(last.t_s - 15.0) < 1e-9);
    QVERIFY(std::abs(last.force_N - r.fd_N) < 1e-8);
    QCOMPARE(last.force_dynamic_N, last.force_N);
  }
  void k2NegativeIsClamped() {
    // Ra 0.38 um: F_d = 139.7 N, K2 = -2914 mm/min; the loop still converges from the clamp
    const auto r = SdnrpSimulator(row(0.38, 357.12, 1974, false)).run();
    QVERIFY(r.feed_feedforward_raw_m_per_s < 0.0);
    QVERIFY(std::abs(r.f_final_N - r.fd_N) < 1e-8);
    QVERIFY(r.feed_final_m_per_s > SdnrpModels::turningFeed() * kMmMin);
  }
  void table2_data() {
    QTest::addColumn<double>("ra_um");
    QTest::addColumn<double>("fc");
    QTest::addColumn<double>("nc");
    std::ifstream in(std::string(MX_TEST_DATA_DIR) + "/sdnrp/table2.csv");
    QVERIFY(in.good());
    std::string line;
    int rows = 0;
    bool header = true;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      if (header) {
        header = false;
        continue;
      }
      std::stringstream ss(line);
      std::string cell;
      std::vector<double> v;
      while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
      QCOMPARE(v.size(), std::size_t(9));
      QTest::newRow(("sim " + std::to_string(static_cast<int>(v[0]))).c_str()) << v[1] << v[3] << v[4];
      ++rows;
    }
    QCOMPARE(rows, 10);
  }
  void table2() {
    QFETCH(double, ra_um);
    QFETCH(double, fc);
    QFETCH(double, nc);
    const auto r = SdnrpSimulator(row(ra_um, fc, nc, true)).run();
    QVERIFY2(std::abs(r.f_final_N - r.fd_N) <= 0.02 * r.fd_N,
             qPrintable(QString("F %1 vs Fd %2").arg(r.f_final_N).arg(r.fd_N)));
    QVERIFY2(std::abs(r.ra_produced_m - r.ra_desired_m) <= 0.10 * r.ra_desired_m,
             qPrintable(QString("Ra %1 um").arg(r.ra_produced_m * 1e6)));
    QVERIFY(!r.feed_saturated);
    // the disturbance is really there: the measured force scatters around the cutting force
    double sq = 0.0;
    for (const auto& s : r.samples) sq += (s.force_dynamic_N - s.force_N) * (s.force_dynamic_N - s.force_N);
    const double rms = std::sqrt(sq / static_cast<double>(r.samples.size()));
    QVERIFY2(rms > 2.5 && rms < 3.5, qPrintable(QString::number(rms)));
  }
  void consoleSignals() {
    auto s = row(0.81, 430.41, 1571, true);
    s.output_period_s = 0.05;
    const auto r = SdnrpSimulator(s).run();
    QCOMPARE(r.samples.size(), std::size_t(301));
    const auto& first = r.samples.front();
    QCOMPARE(first.t_s, 0.0);
    QVERIFY(std::abs(first.feed_m_per_s - 430.41 * kMmMin) < 1e-15);
    QVERIFY(std::abs(first.speed_rev_per_s - 1571.0 / 60.0) < 1e-12);
    QVERIFY(std::abs(first.force_N - SdnrpModels::cuttingForce(1571.0, 430.41)) < 1e-9);
    for (const auto& x : r.samples) {
      QVERIFY(std::abs(x.ra_m * 1e6 - SdnrpModels::roughness(x.force_N)) < 1e-9);
      QVERIFY(std::abs(x.ra_dynamic_m * 1e6 - SdnrpModels::roughness(x.force_dynamic_N)) < 1e-9);
    }
    // same seed, same run; another seed, another run
    const auto again = SdnrpSimulator(s).run();
    QCOMPARE(again.f_final_N, r.f_final_N);
    s.disturbance.seed = 99;
    QVERIFY(SdnrpSimulator(s).run().f_final_N != r.f_final_N);
  }
  void cancellation() {
    std::atomic<bool> cancel{true};
    JobControl job;
    job.cancel = &cancel;
    QVERIFY_THROWS_EXCEPTION(Cancelled, SdnrpSimulator(row(0.81, 430.41, 1571, true)).run(job));
  }
  void invalidSettings() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpSimulator(row(0.1, 430.41, 1571, true)));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpSimulator(row(3.0, 430.41, 1571, true)));
    auto s = row(0.81, 430.41, 1571, true);
    s.min_feed_m_per_s = 50.0 * kMmMin;  // below K4's turning feed
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpSimulator{s});
    s = row(0.81, -1.0, 1571, true);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpSimulator{s});
    s = row(0.81, 430.41, 1571, true);
    s.duration_s = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpSimulator{s});
    try {
      SdnrpSimulator(row(3.0, 430.41, 1571, true));
    } catch (const InvalidInput& e) {
      QVERIFY(std::string(e.what()).find("Ra = 3") != std::string::npos);
      QVERIFY(std::string(e.what()).find("[0.25, 2.5]") != std::string::npos);
    }
  }
};

MX_REGISTER_TEST(TestSdnrpSimulator)
#include "test_sdnrp_simulator.moc"
