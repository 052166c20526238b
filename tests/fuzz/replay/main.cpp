// The fuzz smoke of the test command: runs a target's LLVMFuzzerTestOneInput without libFuzzer (any
// compiler) over every file of its corpus, then over seeded mutations of them (replay/mutator.h) for a
// time budget or a count. A finding (crash, abort, sanitizer report, an input over the time or memory
// limit) saves the input and fails (replay/finding.h). The long coverage-guided runs are the libFuzzer
// builds (preset fuzz, packaging/run-checks.sh).
//   <target>_replay [--seconds S] [--mutations N] [--seed S] [--dict FILE] [--timeout S]
//                   [--rss-limit-mb M] [--artifact-dir DIR] CORPUS_DIR_OR_FILE...
// With neither --seconds nor --mutations, only the files are run (the replay of a saved finding).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "replay/finding.h"
#include "replay/mutator.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;
using mx::fuzz::Bytes;

struct Options {
  double seconds = 0.0;
  long mutations = -1;  // -1: no count, the time budget alone
  std::uint64_t seed = 1;
  fs::path dictionary;
  mx::fuzz::FindingLimits limits;
  fs::path artifact_dir = ".";
  std::vector<fs::path> inputs;
};

[[noreturn]] void usage(const std::string& problem) {
  std::fprintf(stderr,
               "replay: %s\nusage: replay [--seconds S] [--mutations N] [--seed S] [--dict FILE] [--timeout S] "
               "[--rss-limit-mb M] [--artifact-dir DIR] CORPUS_DIR_OR_FILE...\n",
               problem.c_str());
  std::exit(2);
}

Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--seconds") {
      o.seconds = std::stod(value());
    } else if (arg == "--mutations") {
      o.mutations = std::stol(value());
    } else if (arg == "--seed") {
      o.seed = std::stoull(value());
    } else if (arg == "--dict") {
      o.dictionary = value();
    } else if (arg == "--timeout") {
      o.limits.per_input = std::chrono::milliseconds(static_cast<long>(std::stod(value()) * 1000.0));
    } else if (arg == "--rss-limit-mb") {
      o.limits.rss_mb = std::stoul(value());
    } else if (arg == "--artifact-dir") {
      o.artifact_dir = value();
    } else if (arg.starts_with("--")) {
      usage("unknown option " + arg);
    } else {
      o.inputs.emplace_back(arg);
    }
  }
  if (o.inputs.empty()) usage("no corpus folder or file given");
  return o;
}

Bytes readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The files of the folders (sorted, so that runs are reproducible) and the files given.
std::vector<fs::path> seedFiles(const std::vector<fs::path>& inputs) {
  std::vector<fs::path> files;
  for (const fs::path& input : inputs) {
    if (!fs::is_directory(input)) {
      if (!fs::is_regular_file(input)) usage("no such file or folder: " + input.string());
      files.push_back(input);
      continue;
    }
    std::vector<fs::path> inFolder;
    for (const auto& entry : fs::directory_iterator(input))
      if (entry.is_regular_file()) inFolder.push_back(entry.path());
    std::sort(inFolder.begin(), inFolder.end());
    files.insert(files.end(), inFolder.begin(), inFolder.end());
  }
  if (files.empty()) usage("no seed files in the corpus folders given");
  return files;
}

void run(const Bytes& input) {
  mx::fuzz::inputStarted(input);
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  mx::fuzz::inputDone();
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const std::string program = fs::path(argv[0]).filename().string();
  mx::fuzz::watchForFindings(options.artifact_dir / (program + "-finding"), options.limits);

  const auto started = std::chrono::steady_clock::now();
  const std::vector<fs::path> files = seedFiles(options.inputs);
  std::vector<Bytes> seeds;
  seeds.reserve(files.size());
  for (const fs::path& file : files) seeds.push_back(readAll(file));
  for (const Bytes& seed : seeds) run(seed);

  const bool mutate = options.seconds > 0.0 || options.mutations >= 0;
  const auto budget = std::chrono::duration<double>(options.seconds);
  std::vector<Bytes> tokens;
  try {
    if (!options.dictionary.empty()) tokens = mx::fuzz::readDictionary(options.dictionary);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "replay: %s\n", e.what());
    return 2;
  }
  mx::fuzz::Mutator mutator(options.seed, std::move(tokens), seeds);
  long mutants = 0;
  for (; mutate && mutants != options.mutations; ++mutants) {
    if (options.seconds > 0.0 && std::chrono::steady_clock::now() - started > budget) break;
    run(mutator.mutate(seeds[static_cast<std::size_t>(mutants) % seeds.size()]));
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("replay: %zu corpus files and %ld mutants (seed %llu) in %.1f s, no finding\n", seeds.size(), mutants,
              static_cast<unsigned long long>(options.seed), elapsed);
  return 0;
}
