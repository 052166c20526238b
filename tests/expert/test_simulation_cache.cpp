// Each point is simulated once; parallel and serial evaluation agree exactly.
#include "expert/simulation_cache.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestSimulationCache : public QObject {
  Q_OBJECT
 private slots:
  void cachesAndParallelMatchesSerial() {
    const MillingSetup r1 = test::rubioR1();
    std::vector<SimulationCache::Request> requests;
    requests.reserve(7);
    for (int i = 0; i < 6; ++i) requests.push_back({0, &r1, {(4000.0 + 300.0 * i) / 60.0, 0.4e-3, 0.1e-3}});
    requests.push_back(requests.front());  // a duplicate within one call is simulated once
    RefinementSettings parallel_settings;
    parallel_settings.revolutions = 30;
    parallel_settings.evaluated_revolutions = 10;
    parallel_settings.threads = 2;
    RefinementSettings serial_settings = parallel_settings;
    serial_settings.threads = 1;
    SimulationCache parallel(parallel_settings), serial(serial_settings);
    const auto a = parallel.evaluate(requests);
    const auto b = serial.evaluate(requests);
    QCOMPARE(parallel.simulationsRun(), std::size_t(6));
    QCOMPARE(parallel.size(), std::size_t(6));
    for (std::size_t i = 0; i < a.size(); ++i) {
      QCOMPARE(a[i].settling_time_s, b[i].settling_time_s);
      QCOMPARE(a[i].r12h, b[i].r12h);
      QCOMPARE(a[i].a_chatter, b[i].a_chatter);
    }
    parallel.evaluate({requests[2], requests[3]});
    QCOMPARE(parallel.simulationsRun(), std::size_t(6));  // cached
    parallel.evaluate({{1, &r1, requests[2].point}});     // another tool id is another key
    QCOMPARE(parallel.simulationsRun(), std::size_t(7));
  }
};

MX_REGISTER_TEST(TestSimulationCache)
#include "test_simulation_cache.moc"
