#include "replay/mutator.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

namespace mx::fuzz {

namespace {

// Numbers at the edges of what parsers and models accept: signs, zero, limits of int and double,
// subnormals, overflow, and the words of non-finite values.
const std::vector<Bytes>& edgeNumbers() {
  static const std::vector<Bytes> kNumbers{"0",          "-0",
                                           "1",          "-1",
                                           "0.5",        ".5",
                                           "1.",         "1e308",
                                           "-1e308",     "1.7976931348623157e308",
                                           "1e999",      "4.9e-324",
                                           "1e-320",     "2147483647",
                                           "2147483648", "-2147483649",
                                           "4294967296", "9223372036854775808",
                                           "1e6",        "1e10",
                                           "100000",     "99999999999999999999999",
                                           "nan",        "inf",
                                           "-inf",       "NaN",
                                           "1e",         "-",
                                           "0x10",       "1e-5"};
  return kNumbers;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool isDigit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isNumberChar(char c) {
  return isDigit(c) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

// libFuzzer's escapes (FuzzerUtil.cpp, ParseOneDictionaryEntry): \\, \" and \xAB; any other one makes
// libFuzzer refuse the whole dictionary, so the replay refuses it too. nullopt: a bad escape.
std::optional<Bytes> unescape(const std::string& line, std::size_t open, std::size_t close) {
  Bytes token;
  for (std::size_t i = open + 1; i < close; ++i) {
    if (line[i] != '\\') {
      token.push_back(line[i]);
    } else if (i + 1 < close && (line[i + 1] == '\\' || line[i + 1] == '"')) {
      token.push_back(line[++i]);
    } else if (i + 3 < close && line[i + 1] == 'x' && hexDigit(line[i + 2]) >= 0 && hexDigit(line[i + 3]) >= 0) {
      token.push_back(static_cast<char>(hexDigit(line[i + 2]) * 16 + hexDigit(line[i + 3])));
      i += 3;
    } else {
      return std::nullopt;
    }
  }
  return token;
}

}  // namespace

std::vector<Bytes> readDictionary(const std::filesystem::path& path) {
  std::vector<Bytes> tokens;
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto open = line.find('"');
    const auto close = line.rfind('"');
    const std::optional<Bytes> token =
        open == std::string::npos || close <= open ? std::nullopt : unescape(line, open, close);
    if (!token)
      throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": '" + line +
                               "' is not a libFuzzer dictionary entry (\"...\" with the escapes \\\\, \\\" and "
                               "\\xAB only)");
    tokens.push_back(*token);
  }
  return tokens;
}

Mutator::Mutator(std::uint64_t seed, std::vector<Bytes> tokens, std::vector<Bytes> seeds)
    : rng_(seed), tokens_(std::move(tokens)), seeds_(std::move(seeds)) {
  tokens_.insert(tokens_.end(), edgeNumbers().begin(), edgeNumbers().end());
}

std::size_t Mutator::pick(std::size_t lo, std::size_t hi) {
  return std::uniform_int_distribution<std::size_t>(lo, hi)(rng_);
}

Bytes Mutator::mutate(const Bytes& original) {
  Bytes b = original;
  const std::size_t steps = pick(1, 8);
  for (std::size_t s = 0; s < steps; ++s) step(b);
  return b;
}

void Mutator::step(Bytes& b) {
  switch (pick(0, 9)) {
    case 0:
      if (!b.empty()) b[pick(0, b.size() - 1)] ^= static_cast<char>(1 << pick(0, 7));
      break;
    case 1:
      b.insert(at(b), 1, static_cast<char>(pick(0, 255)));
      break;
    case 2:
      b.erase(at(b), pick(1, 16));
      break;
    case 3: {
      const std::size_t from = at(b);
      b.insert(at(b), b.substr(from, pick(1, 64)));
      break;
    }
    case 4:
      b.resize(at(b));
      break;
    case 5:
    case 6:
      replaceNumber(b);
      break;
    case 7:
      repeatChunk(b);
      break;
    case 8:
      splice(b);
      break;
    default:
      b.insert(at(b), anyOf(tokens_));
      break;
  }
}

// The first number at or after a random place (wrapping around) becomes an edge value.
void Mutator::replaceNumber(Bytes& b) {
  if (b.empty()) return;
  const std::size_t start = pick(0, b.size() - 1);
  std::size_t digit = b.size();
  for (std::size_t k = 0; k < b.size() && digit == b.size(); ++k)
    if (isDigit(b[(start + k) % b.size()])) digit = (start + k) % b.size();
  if (digit == b.size()) return;
  std::size_t first = digit;
  while (first > 0 && isNumberChar(b[first - 1])) --first;
  std::size_t last = digit;
  while (last < b.size() && isNumberChar(b[last])) ++last;
  b.replace(first, last - first, anyOf(edgeNumbers()));
}

// A short chunk many times over: deep nesting, long lines, many elements.
void Mutator::repeatChunk(Bytes& b) {
  if (b.empty()) return;
  const std::size_t from = pick(0, b.size() - 1);
  const Bytes chunk = b.substr(from, pick(1, 16));
  const std::size_t times = pick(2, 512);
  Bytes run;
  run.reserve(chunk.size() * times);
  for (std::size_t k = 0; k < times; ++k) run += chunk;
  b.insert(from, run);
}

// Part of another seed: inserted, or replacing the tail (a crossover).
void Mutator::splice(Bytes& b) {
  if (seeds_.empty()) return;
  const Bytes& other = anyOf(seeds_);
  if (other.empty()) return;
  const std::size_t from = pick(0, other.size() - 1);
  if (pick(0, 1) == 0) {
    b.insert(at(b), other.substr(from, pick(1, 256)));
  } else {
    b.resize(at(b));
    b += other.substr(from);
  }
}

}  // namespace mx::fuzz
