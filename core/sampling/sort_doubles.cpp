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
  // The keys live in the values' own storage (bit patterns; moves of doubles keep every bit on
  // x86-64 and AArch64, NaN patterns included); one spare buffer of n keys.
  std::vector<std::array<std::size_t, kBuckets>> count(kPasses);
  for (auto& c : count) c.fill(0);
  for (double& v : values) {
    const std::uint64_t k = key_of(v);
    v = std::bit_cast<double>(k);
    for (int p = 0; p < kPasses; ++p) ++count[p][(k >> (p * kDigitBits)) & (kBuckets - 1)];
  }
  std::vector<double> spare(n);
  for (int p = 0; p < kPasses; ++p) {
    std::array<std::size_t, kBuckets>& c = count[p];
    // A digit that every key shares moves nothing (e.g. the sign and exponent of radii).
    if (std::find(c.begin(), c.end(), n) != c.end()) continue;
    std::size_t start = 0;
    for (std::size_t& b : c) start += std::exchange(b, start);
    for (const double v : values) {
      const auto k = std::bit_cast<std::uint64_t>(v);
      spare[c[(k >> (p * kDigitBits)) & (kBuckets - 1)]++] = v;
    }
    values.swap(spare);
  }
  for (double& v : values) v = value_of(std::bit_cast<std::uint64_t>(v));
}

}  // namespace fp
