#pragma once
// The replay driver's mutations: the simple byte-level ones of libFuzzer (flip, insert, erase, copy,
// truncate, dictionary tokens) plus two for text formats (a number replaced by an edge value, a
// short chunk repeated to build nesting and long lines), and splices with the other seeds. A mutant
// depends only on the seed of the generator and the order of the calls, never on time, so that a
// run replays identically.
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace mx::fuzz {

using Bytes = std::string;

// libFuzzer dictionary lines: [name=]"token" with \\, \" and \xNN escapes; '#' lines are comments.
std::vector<Bytes> readDictionary(const std::filesystem::path& path);

class Mutator {
 public:
  // `seeds` are the corpus files' bytes (for splices); `tokens` the dictionary's.
  Mutator(std::uint64_t seed, std::vector<Bytes> tokens, std::vector<Bytes> seeds);

  // One to eight mutations of `original`.
  Bytes mutate(const Bytes& original);

 private:
  std::size_t pick(std::size_t lo, std::size_t hi);  // uniform in [lo, hi]
  std::size_t at(const Bytes& b) { return pick(0, b.size()); }
  const Bytes& anyOf(const std::vector<Bytes>& list) { return list[pick(0, list.size() - 1)]; }

  void step(Bytes& b);
  void replaceNumber(Bytes& b);
  void repeatChunk(Bytes& b);
  void splice(Bytes& b);

  std::mt19937_64 rng_;
  std::vector<Bytes> tokens_;
  std::vector<Bytes> seeds_;
};

}  // namespace mx::fuzz
