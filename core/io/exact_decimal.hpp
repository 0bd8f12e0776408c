#pragma once
// Absolute coordinates in text files without losing the local frame's digits.
//
// Particles are stored relative to the container's frame origin (core/geometry/local_frame.hpp).
// Far from the origin a double cannot hold origin + local: at 1e9 its spacing is 1.2e-7, which
// would turn contacts exact to 1e-9 r into overlaps of 1e-5 r. So the writers print the exact
// decimal sum of the origin (a short number by construction) and the shortest text of the local
// coordinate, and the readers subtract the origin from the text exactly before rounding once to
// a double. A file written and read back in the same frame gives the packer's doubles bit for
// bit; a program that reads the file into doubles gets the nearest double, as it would anyway.
// With origin 0 both sides reduce to the plain shortest round-trip number.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fp {

/// A decimal number held exactly: (-1)^negative * digits * 10^exponent, digits without leading
/// or trailing zeros ("" is zero).
struct ExactDecimal {
  bool negative = false;
  std::string digits;
  int exponent = 0;

  /// Parses a plain decimal number: [+-]digits[.digits][(e|E)[+-]digits]. nullopt otherwise
  /// (no inf, nan, hex or empty text).
  static std::optional<ExactDecimal> parse(std::string_view text);
  /// Every digit of a finite double (a double is a dyadic rational: finite decimal expansion).
  static ExactDecimal of(double v);

  bool is_zero() const { return digits.empty(); }
  ExactDecimal operator+(const ExactDecimal& o) const;
  ExactDecimal operator-(const ExactDecimal& o) const;
  /// Fixed notation, every digit ("-0.000125", "1000000000.25", "0").
  std::string fixed() const;
  /// The double nearest to the value (correctly rounded, like from_chars).
  double to_double() const;
};

/// One axis of a frame: prints origin + local exactly, and reads text back as text - origin.
class OffsetAxis {
 public:
  explicit OffsetAxis(double origin = 0.0);

  /// The origin is 0: writers and readers take the plain path.
  bool zero() const { return zero_; }
  /// Appends the exact decimal text of origin + local.
  void append_absolute(std::string& out, double local) const;
  /// The double nearest to (the number in `text`) - origin, the subtraction done exactly;
  /// nullopt when `text` is not a plain decimal number.
  std::optional<double> local_from_text(std::string_view text) const;

 private:
  bool zero_ = true;
  double origin_ = 0.0;
  ExactDecimal exact_;
};

/// The three axes of a frame origin given by its first `dims` coordinates (z = 0 in 2D).
inline std::array<OffsetAxis, 3> offset_axes(const double* origin, int dims) {
  return {OffsetAxis(dims > 0 ? origin[0] : 0.0), OffsetAxis(dims > 1 ? origin[1] : 0.0),
          OffsetAxis(dims > 2 ? origin[2] : 0.0)};
}

}  // namespace fp
