// The fuzz smoke of the test command: runs a libFuzzer target's LLVMFuzzerTestOneInput without libFuzzer
// (any compiler), over every seed of its corpus and a fixed number of seeded mutations of each. The
// mutations are libFuzzer's simplest ones (flip, insert, erase, duplicate, truncate, splice a dictionary
// token), so that a failure replays identically from the printed seed. The long coverage-guided runs
// are the libFuzzer builds (preset fuzz, packaging/run-checks.sh).
//   replay --mutations N [--seed S] [--dict FILE] CORPUS_DIR...
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::string;

Bytes readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// libFuzzer dictionary lines: [name=]"token" with \\, \" and \xNN escapes; '#' lines are comments.
std::vector<Bytes> readDictionary(const std::filesystem::path& path) {
  std::vector<Bytes> tokens;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const auto open = line.find('"');
    const auto close = line.rfind('"');
    if (line.empty() || line[0] == '#' || open == std::string::npos || close <= open) continue;
    Bytes token;
    for (std::size_t i = open + 1; i < close; ++i) {
      if (line[i] == '\\' && i + 3 < close + 1 && line[i + 1] == 'x' && hexDigit(line[i + 2]) >= 0 &&
          hexDigit(line[i + 3]) >= 0) {
        token.push_back(static_cast<char>(hexDigit(line[i + 2]) * 16 + hexDigit(line[i + 3])));
        i += 3;
      } else if (line[i] == '\\' && i + 1 < close) {
        token.push_back(line[++i]);
      } else {
        token.push_back(line[i]);
      }
    }
    tokens.push_back(token);
  }
  return tokens;
}

class Mutator {
 public:
  Mutator(std::uint64_t seed, std::vector<Bytes> dictionary) : rng_(seed), dictionary_(std::move(dictionary)) {}

  Bytes mutate(Bytes b) {
    const int steps = pick(1, 4);
    for (int s = 0; s < steps; ++s) step(b);
    return b;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::size_t at(const Bytes& b) { return std::uniform_int_distribution<std::size_t>(0, b.size())(rng_); }

  void step(Bytes& b) {
    switch (pick(0, 5)) {
      case 0:
        if (!b.empty()) b[std::min(at(b), b.size() - 1)] ^= static_cast<char>(1 << pick(0, 7));
        break;
      case 1:
        b.insert(at(b), 1, static_cast<char>(pick(0, 255)));
        break;
      case 2: {
        const std::size_t from = at(b);
        b.erase(from, static_cast<std::size_t>(pick(1, 16)));
        break;
      }
      case 3: {
        const std::size_t from = at(b);
        b.insert(at(b), b.substr(from, static_cast<std::size_t>(pick(1, 64))));
        break;
      }
      case 4:
        b.resize(at(b));
        break;
      default:
        if (!dictionary_.empty())
          b.insert(at(b), dictionary_[static_cast<std::size_t>(pick(0, static_cast<int>(dictionary_.size()) - 1))]);
        break;
    }
  }

  std::mt19937_64 rng_;
  std::vector<Bytes> dictionary_;
};

void run(const Bytes& b) {
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 0;
  std::uint64_t seed = 1;
  std::vector<Bytes> dictionary;
  std::vector<std::filesystem::path> corpora;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mutations" && i + 1 < argc) {
      mutations = std::strtol(argv[++i], nullptr, 10);
    } else if (arg == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (arg == "--dict" && i + 1 < argc) {
      dictionary = readDictionary(argv[++i]);
    } else {
      corpora.emplace_back(arg);
    }
  }
  std::vector<std::filesystem::path> seeds;
  for (const auto& dir : corpora)
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file()) seeds.push_back(entry.path());
  if (seeds.empty()) {
    std::fprintf(stderr, "replay: no seed files in the corpus folders given\n");
    return 2;
  }
  Mutator mutator(seed, dictionary);
  long runs = 0;
  for (const auto& path : seeds) {
    const Bytes original = readAll(path);
    run(original);
    ++runs;
    for (long m = 0; m < mutations; ++m, ++runs) run(mutator.mutate(original));
  }
  std::printf("replay: %zu seeds, %ld inputs (seed %llu), no finding\n", seeds.size(), runs,
              static_cast<unsigned long long>(seed));
  return 0;
}
