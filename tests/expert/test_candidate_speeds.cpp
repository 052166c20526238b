// Rule 7.2 candidate speeds N = 60 f_n / (n_t k) merged into the regular grid.
#include <algorithm>
#include <cmath>

#include "core/invalid_input.h"
#include "expert/candidate_speeds.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestCandidateSpeeds : public QObject {
  Q_OBJECT
 private slots:
  void modalSpeedsOfR1() {
    const MillingSetup r1 = test::rubioR1();  // 603 / 666 Hz, 3 teeth
    const std::vector<double> n = modalCandidateSpeeds(r1, 3000.0 / 60.0, 7000.0 / 60.0);
    // 603: 12060/k -> 6030 (k=2), 4020, 3015; 666: 13320/k -> 6660, 4440, 3330
    const std::vector<double> expected{3015, 3330, 4020, 4440, 6030, 6660};
    QCOMPARE(n.size(), expected.size());
    for (std::size_t i = 0; i < n.size(); ++i) QCOMPARE_LE(std::abs(n[i] * 60.0 - expected[i]), 1e-9);
  }

  void mergedGrid_data() {
    QTest::addColumn<bool>("modal");
    QTest::addColumn<int>("count");
    QTest::newRow("regular only") << false << 6;       // 800, 1800, ..., 5800
    QTest::newRow("with Rule 7.2") << true << 6 + 27;  // plus 60 f / (3 k) of 603 and 666 Hz in [800, 6000]
  }
  void mergedGrid() {
    QFETCH(bool, modal);
    QFETCH(int, count);
    ExpertGrid g;
    g.speed_from_rev_per_s = 800.0 / 60.0;
    g.speed_to_rev_per_s = 6000.0 / 60.0;
    g.speed_step_rev_per_s = 1000.0 / 60.0;
    g.modal_candidate_speeds = modal;
    const std::vector<double> n = rankingSpeeds(test::rubioR1(), g);
    QCOMPARE(static_cast<int>(n.size()), count);
    QVERIFY(std::is_sorted(n.begin(), n.end()));
    QCOMPARE_LE(std::abs(n.front() * 60.0 - 800.0), 1e-9);
    QVERIFY(std::find_if(n.begin(), n.end(), [](double v) { return std::abs(v * 60.0 - 5800.0) < 1e-6; }) != n.end());
    QVERIFY(n.back() * 60.0 <= 6000.0 + 1e-9);
  }

  // No modes: the |H| peak line of each measured FRF stands for f_n. |H| of one mode peaks at
  // f_n sqrt(1 - 2 zeta^2): 602.08 and 665.18 Hz, the lines 602 and 665 Hz.
  void measuredPeaksWithoutModes() {
    const MillingSetup r1 = test::rubioR1();
    MillingSetup measured = r1;
    measured.measured_x = test::sampledAxis(r1.modes_x, 0.0, 2000.0, 1.0);
    measured.measured_y = test::sampledAxis(r1.modes_y, 0.0, 2000.0, 1.0);
    measured.modes_x.clear();
    measured.modes_y.clear();
    const std::vector<double> n = modalCandidateSpeeds(measured, 3000.0 / 60.0, 7000.0 / 60.0);
    const std::vector<double> expected{3010, 3325, 12040.0 / 3, 13300.0 / 3, 6020, 6650};
    QCOMPARE(n.size(), expected.size());
    for (std::size_t i = 0; i < n.size(); ++i) QCOMPARE_LE(std::abs(n[i] * 60.0 - expected[i]), 1e-9);
    // Modes on one axis: they alone give the candidates (measured y without modes is skipped).
    MillingSetup mixed = r1;
    mixed.measured_y = measured.measured_y;
    mixed.modes_y.clear();
    const std::vector<double> x_only = modalCandidateSpeeds(mixed, 3000.0 / 60.0, 7000.0 / 60.0);
    const std::vector<double> expected_x{3015, 4020, 6030};
    QCOMPARE(x_only.size(), expected_x.size());
    for (std::size_t i = 0; i < x_only.size(); ++i) QCOMPARE_LE(std::abs(x_only[i] * 60.0 - expected_x[i]), 1e-9);
    // Rigid on both axes: only the regular grid.
    MillingSetup rigid = measured;
    rigid.measured_x.reset();
    rigid.measured_y.reset();
    QVERIFY(modalCandidateSpeeds(rigid, 3000.0 / 60.0, 7000.0 / 60.0).empty());
  }

  void refusesBadGrid() {
    ExpertGrid g;
    g.speed_step_rev_per_s = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, rankingSpeeds(test::rubioR1(), g));
  }
};

MX_REGISTER_TEST(TestCandidateSpeeds)
#include "test_candidate_speeds.moc"
