// Grafcet interpreter: one scan of a 500-step chart. The chart: 20 parallel sequences of
// 25 steps (each a loop, its first step initial), every step with a "next" transition
// (priority 1) and a "skip" transition (priority 2) over 32 signals, plus a global hold; the inputs
// change at every scan, so a few transitions fire per scan and about 20 steps are active.
// Requirement: 1 kHz scan rate at >= 100x real time, i.e. <= 10 us per scan ("realtime_x" counter
// = simulated seconds per wall-clock second).
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "grafcet/grafcet_interpreter.h"

namespace {

constexpr int kBranches = 20;
constexpr int kLength = 25;
constexpr int kSignals = 32;

// prefix + number, by appending (operator+ on a literal trips GCC 12's -Wrestrict false positive)
std::string tag(const char* prefix, int n) {
  std::string s(prefix);
  s.append(std::to_string(n));
  return s;
}

mx::GrafcetChart chart500() {
  mx::GrafcetChart c;
  c.name = "bench 500";
  int tid = 1;
  for (int b = 0; b < kBranches; ++b)
    for (int k = 0; k < kLength; ++k) {
      const int id = 1 + b * kLength + k;
      std::vector<std::string> actions{tag("M", k % 12)};
      if (k == 0) actions.push_back(tag("R", b).append("*"));
      c.steps.push_back({id, tag("B", b).append(tag("S", k)), k == 0, actions});
    }
  for (int b = 0; b < kBranches; ++b)
    for (int k = 0; k < kLength; ++k) {
      const int id = 1 + b * kLength + k;
      const int next = 1 + b * kLength + (k + 1) % kLength;
      const int skip = 1 + b * kLength + (k + 2) % kLength;
      const std::string s1 = tag("s", (b + k) % kSignals), s2 = tag("s", (3 * b + k + 7) % kSignals);
      std::string next_r = s1, skip_r = "(";
      next_r.append(" > 0.9 and not hold");
      skip_r.append(s2).append(" >= 0.95 or alarm') and ").append(s1).append(" > 0.5");
      c.transitions.push_back({tid++, {id}, {next}, next_r, 1});
      c.transitions.push_back({tid++, {id}, {skip}, skip_r, 2});
    }
  return c;
}

std::vector<std::string> signalNames() {
  std::vector<std::string> n{"hold", "alarm"};
  for (int i = 0; i < kSignals; ++i) n.push_back(tag("s", i));
  return n;
}

std::vector<std::vector<double>> inputs(std::size_t n) {
  std::mt19937 rng(500);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::vector<double>> out(n);
  for (auto& v : out) {
    v = {u(rng) < 0.05 ? 1.0 : 0.0, u(rng) < 0.5 ? 1.0 : 0.0};
    for (int i = 0; i < kSignals; ++i) v.push_back(u(rng));
  }
  return out;
}

void BM_GrafcetScan500Fast(benchmark::State& state) {
  mx::GrafcetInterpreter g(chart500());
  g.bindSignals(signalNames());
  const auto in = inputs(1024);
  std::size_t k = 0, active = 0, fired = 0;
  for (auto _ : state) {
    const mx::GrafcetSituation& s = g.evolve(in[k++ & 1023]);
    active += s.active_steps.size();
    fired += static_cast<std::size_t>(s.iterations);
    benchmark::DoNotOptimize(s.level_actions.data());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["steps"] = static_cast<double>(g.chart().steps.size());
  state.counters["active_avg"] = static_cast<double>(active) / n;
  state.counters["evolutions_avg"] = static_cast<double>(fired) / n;
  state.counters["realtime_x"] = benchmark::Counter(n * 1e-3, benchmark::Counter::kIsRate);  // 1 ms per scan
}
BENCHMARK(BM_GrafcetScan500Fast)->Unit(benchmark::kMicrosecond);

void BM_GrafcetScan500ByName(benchmark::State& state) {
  mx::GrafcetInterpreter g(chart500());
  const auto names = signalNames();
  const auto in = inputs(1024);
  std::vector<mx::SignalValues> maps;
  for (const auto& v : in) {
    mx::SignalValues m;
    for (std::size_t i = 0; i < names.size(); ++i) m[names[i]] = v[i];
    maps.push_back(std::move(m));
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const mx::ScanOutput o = g.scan(maps[k++ & 1023]);
    benchmark::DoNotOptimize(o.active_steps.data());
  }
  state.counters["realtime_x"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 1e-3, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GrafcetScan500ByName)->Unit(benchmark::kMicrosecond);

}  // namespace
