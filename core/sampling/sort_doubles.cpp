#include "core/sampling/sort_doubles.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace fp {
namespace {

constexpr int kDigitBits = 16;
constexpr int kPasses = 64 / kDigitBits;
constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
// Below this std::sort is as fast (the histograms cost kPasses x kBuckets).
constexpr std::size_t kRadixFrom = 1 << 14;

// Unsigned keys in the order of the doubles: flip every bit of a negative, the sign bit of a positive.
std::uint64_t key_of(double x) {
  const auto b = std::bit_cast<std::uint64_t>(x);
  return (b >> 63) ? ~b : b | (std::uint64_t{1} << 63);
}
double value_of(std::uint64_t k) {
  return std::bit_cast<double>((k >> 63) ? k & ~(std::uint64_t{1} << 63) : ~k);
}

}  // namespace

void sort_doubles(std::vector<double>& values) {
  const std::size_t n = values.size();
  if (n < kRadixFrom) {
    std::sort(values.begin(), values.end(), [](double a, double b) { return key_of(a) < key_of(b); });
    return;
  }
  std::vector<std::uint64_t> keys(n), spare(n);
  std::vector<std::array<std::size_t, kBuckets>> count(kPasses);
  for (auto& c : count) c.fill(0);
  for (std::size_t i = 0; i < n; ++i) {
    keys[i] = key_of(values[i]);
    for (int p = 0; p < kPasses; ++p) ++count[p][(keys[i] >> (p * kDigitBits)) & (kBuckets - 1)];
  }
  for (int p = 0; p < kPasses; ++p) {
    std::array<std::size_t, kBuckets>& c = count[p];
    // A digit that every key shares moves nothing (e.g. the sign and exponent of radii).
    if (std::find(c.begin(), c.end(), n) != c.end()) continue;
    std::size_t start = 0;
    for (std::size_t& b : c) start += std::exchange(b, start);
    for (const std::uint64_t k : keys) spare[c[(k >> (p * kDigitBits)) & (kBuckets - 1)]++] = k;
    keys.swap(spare);
  }
  for (std::size_t i = 0; i < n; ++i) values[i] = value_of(keys[i]);
}

}  // namespace fp
