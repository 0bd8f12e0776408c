// Exact decimal arithmetic for absolute coordinates (core/io/exact_decimal.hpp): a coordinate
// written as origin + local and read back in the same frame is the same double, for every
// magnitude of origin and local; the arithmetic agrees with exact rational arithmetic.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "core/io/exact_decimal.hpp"

namespace fp {
namespace {

std::string shortest(double v) {
  char b[32];
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}

TEST(ExactDecimal, ParsesPlainNumbersAndRefusesTheRest) {
  EXPECT_EQ(ExactDecimal::parse("0012.5000")->fixed(), "12.5");
  EXPECT_EQ(ExactDecimal::parse("-0.000125")->fixed(), "-0.000125");
  EXPECT_EQ(ExactDecimal::parse("1.5e3")->fixed(), "1500");
  EXPECT_EQ(ExactDecimal::parse("+25E-3")->fixed(), "0.025");
  EXPECT_EQ(ExactDecimal::parse("-0.0")->fixed(), "0");
  EXPECT_EQ(ExactDecimal::parse(".5")->fixed(), "0.5");
  for (const char* bad : {"", "-", ".", "e5", "1e", "1e+", "inf", "nan", "0x10", "1.2.3", "1 ", " 1", "1,5"})
    EXPECT_FALSE(ExactDecimal::parse(bad).has_value()) << bad;
}

TEST(ExactDecimal, OfADoubleHasEveryDigit) {
  EXPECT_EQ(ExactDecimal::of(0.1).fixed(), "0.1000000000000000055511151231257827021181583404541015625");
  EXPECT_EQ(ExactDecimal::of(1e9).fixed(), "1000000000");
  EXPECT_EQ(ExactDecimal::of(std::ldexp(1.0, -10)).fixed(), "0.0009765625");
  EXPECT_EQ(ExactDecimal::of(-std::ldexp(3.0, 70)).fixed(), "-3541774862152233910272");
  // The smallest subnormal: 1074 decimal places, read back exactly.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(ExactDecimal::of(tiny).to_double(), tiny);
  EXPECT_EQ(ExactDecimal::of(std::numeric_limits<double>::max()).to_double(), std::numeric_limits<double>::max());
}

TEST(ExactDecimal, SumsAndDifferencesAreExact) {
  const auto d = [](const char* s) { return *ExactDecimal::parse(s); };
  EXPECT_EQ((d("999.999") + d("0.001")).fixed(), "1000");
  EXPECT_EQ((d("1000000000") + d("-0.25")).fixed(), "999999999.75");
  EXPECT_EQ((d("0.25") - d("1000000000")).fixed(), "-999999999.75");
  EXPECT_EQ((d("-3") - d("-3")).fixed(), "0");
  EXPECT_EQ((d("1e-30") + d("1e30")).fixed(), "1000000000000000000000000000000.000000000000000000000000000001");
  // Against integer arithmetic on random 18-digit integers scaled by powers of ten.
  std::mt19937_64 rng(7);
  for (int k = 0; k < 2000; ++k) {
    const std::int64_t a = static_cast<std::int64_t>(rng() % 1000000000000000000ULL) - 500000000000000000LL;
    const std::int64_t b = static_cast<std::int64_t>(rng() % 1000000000000000000ULL) - 500000000000000000LL;
    const std::string sa = std::to_string(a) + "e-7", sb = std::to_string(b) + "e-7";
    const ExactDecimal sum = d(sa.c_str()) + d(sb.c_str()), diff = d(sa.c_str()) - d(sb.c_str());
    EXPECT_EQ(sum.fixed(), (d((std::to_string(a + b) + "e-7").c_str())).fixed());
    EXPECT_EQ(diff.fixed(), (d((std::to_string(a - b) + "e-7").c_str())).fixed());
  }
}

TEST(OffsetAxis, RoundTripsEveryLocalCoordinateBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double origin : {0.0, 1e3, 1e6, 1e9, -1e9, 4503599627370496.0, std::ldexp(1.0, -40), 1e100}) {
    const OffsetAxis axis(origin);
    for (const double scale : {1e-12, 1e-3, 0.5, 1.0, 1e3}) {
      for (int k = 0; k < 300; ++k) {
        const double local = u(rng) * scale;
        std::string text;
        axis.append_absolute(text, local);
        const auto back = axis.local_from_text(text);
        ASSERT_TRUE(back.has_value()) << text;
        ASSERT_EQ(*back, local) << "origin " << origin << " text " << text;
        // The text is the absolute position: read as a double it is origin + local up to an ulp
        // of the sum and half an ulp of local (the text holds origin + shortest(local)).
        double abs = 0;
        std::from_chars(text.data(), text.data() + text.size(), abs);
        const double sum = origin + local;
        const auto ulp = [](double v) { return std::nextafter(std::abs(v), INFINITY) - std::abs(v); };
        EXPECT_LE(std::abs(abs - sum), ulp(sum) + ulp(local)) << text;
      }
    }
  }
}

TEST(OffsetAxis, PlainNumbersWithOriginZero) {
  const OffsetAxis axis(0.0);
  EXPECT_TRUE(axis.zero());
  std::string text;
  axis.append_absolute(text, 0.1);
  EXPECT_EQ(text, shortest(0.1));
  EXPECT_EQ(*axis.local_from_text("1e-5"), 1e-5);
  EXPECT_FALSE(axis.local_from_text("abc").has_value());
}

TEST(OffsetAxis, ReadsForeignTextInAnyNotation) {
  const OffsetAxis axis(1e9);
  EXPECT_EQ(*axis.local_from_text("1.00000000025e9"), 0.25);
  EXPECT_EQ(*axis.local_from_text("1000000000"), 0.0);
  EXPECT_EQ(*axis.local_from_text("-0"), -1e9);
}

}  // namespace
}  // namespace fp
