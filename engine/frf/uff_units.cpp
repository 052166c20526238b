#include "frf/uff_units.h"

namespace mx {
namespace {

constexpr double kStandardGravity = 9.80665;     // m/s^2 (CGPM 1901)
constexpr double kPoundForce = 4.4482216152605;  // N (0.45359237 kg * g)

bool isSi(const std::string& n) {
  return n.empty() || n == "none";
}

void replaceAll(std::string& s, std::string_view from, std::string_view to) {
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
}

std::optional<double> lengthFactor(std::string_view n) {
  if (n == "m") return 1.0;
  if (n == "mm") return 1e-3;
  if (n == "um" || n == "\xc2\xb5m" || n == "micron" || n == "microns") return 1e-6;
  if (n == "in") return 0.0254;
  return std::nullopt;
}

// "<length><suffix>" -> the length factor.
std::optional<double> lengthWithSuffix(std::string_view n, std::string_view suffix) {
  if (n.size() <= suffix.size() || n.substr(n.size() - suffix.size()) != suffix) return std::nullopt;
  return lengthFactor(n.substr(0, n.size() - suffix.size()));
}

}  // namespace

std::string normaliseUnitsLabel(std::string_view label) {
  std::string n;
  n.reserve(label.size());
  for (char c : label) {
    if (c == ' ' || c == '\t') continue;
    n += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  replaceAll(n, "**", "^");
  replaceAll(n, "\xc2\xb2", "^2");
  replaceAll(n, "sec", "s");
  return n;
}

std::optional<double> numeratorUnitsToSi(FrfQuantity quantity, std::string_view label) {
  const std::string n = normaliseUnitsLabel(label);
  if (isSi(n)) return 1.0;
  switch (quantity) {
    case FrfQuantity::Receptance:
      return lengthFactor(n);
    case FrfQuantity::Mobility:
      return lengthWithSuffix(n, "/s");
    case FrfQuantity::Accelerance:
      if (auto f = lengthWithSuffix(n, "/s^2")) return f;
      if (auto f = lengthWithSuffix(n, "/s2")) return f;
      if (n.find('g') != std::string::npos) return kStandardGravity;
      return std::nullopt;
  }
  return std::nullopt;
}

std::optional<double> forceUnitsToSi(std::string_view label) {
  const std::string n = normaliseUnitsLabel(label);
  if (isSi(n) || n == "n") return 1.0;
  if (n == "kn") return 1e3;
  if (n == "lbf" || n == "lb" || n == "lbs") return kPoundForce;
  return std::nullopt;
}

std::optional<double> frequencyUnitsToHz(std::string_view label) {
  const std::string n = normaliseUnitsLabel(label);
  if (isSi(n) || n == "hz") return 1.0;
  return std::nullopt;
}

std::optional<double> timeUnitsToSeconds(std::string_view label) {
  const std::string n = normaliseUnitsLabel(label);
  if (isSi(n) || n == "s") return 1.0;
  if (n == "ms") return 1e-3;
  return std::nullopt;
}

}  // namespace mx
