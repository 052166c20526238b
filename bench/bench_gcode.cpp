// Part-program overrides: a 100k-block G-code program (ISO, and Heidenhain Klartext) parsed, run through
// the model-based force controller block by block, written back and exported as the feed-override CSV.
// Target: <= 2 s.
#include <benchmark/benchmark.h>

#include <string>

#include "gcode/gcode_dialect.h"
#include "gcode/gcode_reader.h"
#include "machining/part_program_override.h"

namespace {

// Zig-zag passes at alternating depths with arcs, comments and an unknown word now and then.
std::string program(std::size_t blocks) {
  std::string s = "%\n(bench program)\nG21 G90 G17\nG0 Z5 S1500 M3\nG0 X0 Y0\n";
  std::size_t n = 5;
  int pass = 0;
  while (n < blocks) {
    const double z = (pass % 3 == 0) ? -2.0 : (pass % 3 == 1 ? -1.0 : 0.5);
    s += "G1 Z" + std::to_string(z) + " F150\n";
    s += "G1 X100 Y" + std::to_string(pass) + " F600 (pass " + std::to_string(pass) + ")\n";
    s += "G2 X110 Y" + std::to_string(pass + 10) + " I0 J10 ; arc\n";
    s += "G1 X0 M8\n";
    s += "G0 Z5\n";
    n += 5;
    ++pass;
  }
  s += "M30\n%\n";
  return s;
}

// The same passes in Klartext: numbered blocks, TOOL CALL with S, L moves with F, a CC + C half circle,
// a CR arc back, FMAX rapids, comments and M words.
std::string heidenhainProgram(std::size_t blocks) {
  std::string s;
  std::size_t n = 0;
  const auto block = [&](const std::string& text) {
    s.append(std::to_string(n++)).append(" ").append(text).append("\n");
  };
  const auto y = [](int value) {
    std::string out(value < 0 ? "" : "+");
    return out.append(std::to_string(value));
  };
  block("BEGIN PGM BENCH MM");
  block("; bench program");
  block("TOOL CALL 1 Z S1500");
  block("L Z+5 R0 FMAX M3");
  block("L X+0 Y+0 R0 FMAX");
  // One block at a time, so that the program has exactly `blocks` blocks.
  for (int k = 0; n + 2 < blocks; ++k) {
    const int pass = k / 6;
    const char* z = (pass % 3 == 0) ? "Z-2" : (pass % 3 == 1 ? "Z-1" : "Z+0.5");
    switch (k % 6) {
      case 0:
        block(std::string("L ") + z + " F150");
        break;
      case 1:
        block("L X+100 Y" + y(pass) + " F600 ; pass " + std::to_string(pass));
        break;
      case 2:
        block("CC X+100 Y" + y(pass + 5));
        break;
      case 3:
        block("C X+100 Y" + y(pass + 10) + " DR+");
        break;
      case 4:
        block("CR X+0 Y" + y(pass) + " R+60 DR- M8");
        break;
      default:
        block("L Z+5 FMAX");
    }
  }
  block("M5");
  block("END PGM BENCH MM");
  return s;
}

void runOverride(benchmark::State& state, const std::string& text) {
  mx::ModelBasedForceSettings ms;
  ms.reference_force_N = 400.0;
  const mx::PartProgramOverrider overrider(mx::modelBasedFeedController(mx::ModelBasedForceController(ms)), {});
  const mx::GcodeHeader header{"bench", "model-based", "2024-01-01"};
  std::size_t bytes = 0, changed = 0, blocks = 0;
  for (auto _ : state) {
    auto r = overrider.run(std::string_view(text));
    const std::string out = r.writeProgram(header);
    const std::string csv = r.csv();
    bytes = out.size() + csv.size();
    changed = r.changed_blocks;
    blocks = r.program.blocks.size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["blocks"] = static_cast<double>(blocks);
  state.counters["changed"] = static_cast<double>(changed);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}

void BM_GcodeOverride(benchmark::State& state) {
  runOverride(state, program(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_GcodeOverride)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_HeidenhainOverride(benchmark::State& state) {
  runOverride(state, heidenhainProgram(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_HeidenhainOverride)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_DialectDetection(benchmark::State& state) {
  const std::string text = heidenhainProgram(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(mx::detectDialect(text).line);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_DialectDetection)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_GcodeParse(benchmark::State& state) {
  const std::string text = program(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(mx::GcodeReader::parse(text).blocks.size());
}
BENCHMARK(BM_GcodeParse)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
