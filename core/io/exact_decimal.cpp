#include "core/io/exact_decimal.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <stdexcept>

namespace fp {
namespace {

void normalise(ExactDecimal& d) {
  const std::size_t first = d.digits.find_first_not_of('0');
  if (first == std::string::npos) {
    d.digits.clear();
    d.exponent = 0;
    d.negative = false;
    return;
  }
  d.digits.erase(0, first);
  const std::size_t last = d.digits.find_last_not_of('0');
  d.exponent += static_cast<int>(d.digits.size() - 1 - last);
  d.digits.resize(last + 1);
}

/// |a| vs |b| for digit strings of equal length (aligned to the same exponent).
int compare_aligned(const std::string& a, const std::string& b) { return a.compare(b) < 0 ? -1 : (a == b ? 0 : 1); }

/// Digit strings of equal length: a + b (may grow by one digit).
std::string add_aligned(const std::string& a, const std::string& b) {
  std::string out(a.size() + 1, '0');
  int carry = 0;
  for (std::size_t k = a.size(); k-- > 0;) {
    const int s = (a[k] - '0') + (b[k] - '0') + carry;
    out[k + 1] = static_cast<char>('0' + s % 10);
    carry = s / 10;
  }
  out[0] = static_cast<char>('0' + carry);
  return out;
}

/// Digit strings of equal length with a >= b: a - b.
std::string subtract_aligned(const std::string& a, const std::string& b) {
  std::string out(a.size(), '0');
  int borrow = 0;
  for (std::size_t k = a.size(); k-- > 0;) {
    int s = (a[k] - '0') - (b[k] - '0') - borrow;
    borrow = s < 0;
    if (s < 0) s += 10;
    out[k] = static_cast<char>('0' + s);
  }
  return out;
}

}  // namespace

std::optional<ExactDecimal> ExactDecimal::parse(std::string_view s) {
  ExactDecimal d;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) d.negative = s[i++] == '-';
  std::size_t mantissa_digits = 0;
  long long exponent = 0;
  for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i, ++mantissa_digits) d.digits.push_back(s[i]);
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i, ++mantissa_digits) {
      d.digits.push_back(s[i]);
      --exponent;
    }
  }
  if (mantissa_digits == 0) return std::nullopt;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool neg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    const std::size_t start = i;
    long long e = 0;
    for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) e = std::min<long long>(e * 10 + (s[i] - '0'), 1LL << 40);
    if (i == start) return std::nullopt;
    exponent += neg ? -e : e;
  }
  if (i != s.size()) return std::nullopt;
  // Far beyond the doubles only the class of the value matters: above 10^1000 it reads as inf and
  // below 10^-1100 as 0 (far under half the spacing of any double), whatever origin is subtracted.
  // Saturating there keeps the digit strings of +, - and to_double() as short as the text: an
  // exponent of 999999999 kept as is would be aligned to half a billion zeros.
  const std::size_t first = d.digits.find_first_not_of('0');
  if (first != std::string::npos) {
    const long long magnitude = exponent + static_cast<long long>(d.digits.size() - first);  // |value| < 10^magnitude
    if (magnitude > 1000) d.digits = "1", exponent = 1000;
    else if (magnitude < -1100) d.digits = "1", exponent = -1100;
  }
  d.exponent = static_cast<int>(exponent);
  normalise(d);
  return d;
}

ExactDecimal ExactDecimal::of(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("ExactDecimal::of: not a finite number");
  if (v == 0.0) return {};
  // v = m * 2^e with m an integer: exactly -e decimal places when e < 0.
  int e = 0;
  const double m = std::frexp(v, &e);          // v = m * 2^e, 0.5 <= |m| < 1
  int low = e - 53;                             // weight of the last bit of a 53-bit mantissa
  double scaled = std::ldexp(std::abs(m), 53);  // that mantissa, an integer below 2^53
  while (std::fmod(scaled, 2.0) == 0.0) {
    scaled /= 2.0;
    ++low;
  }
  const int places = std::max(0, -low);
  std::string buf(std::size_t(places) + 400, '\0');
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, places);
  if (res.ec != std::errc()) throw std::logic_error("ExactDecimal::of: buffer too small");
  return *parse(std::string_view(buf.data(), static_cast<std::size_t>(res.ptr - buf.data())));
}

ExactDecimal ExactDecimal::operator+(const ExactDecimal& o) const {
  if (is_zero()) return o;
  if (o.is_zero()) return *this;
  const int e = std::min(exponent, o.exponent);
  std::string a = digits + std::string(static_cast<std::size_t>(exponent - e), '0');
  std::string b = o.digits + std::string(static_cast<std::size_t>(o.exponent - e), '0');
  const std::size_t n = std::max(a.size(), b.size());
  a.insert(0, n - a.size(), '0');
  b.insert(0, n - b.size(), '0');
  ExactDecimal r;
  r.exponent = e;
  if (negative == o.negative) {
    r.negative = negative;
    r.digits = add_aligned(a, b);
  } else if (compare_aligned(a, b) >= 0) {
    r.negative = negative;
    r.digits = subtract_aligned(a, b);
  } else {
    r.negative = o.negative;
    r.digits = subtract_aligned(b, a);
  }
  normalise(r);
  return r;
}

ExactDecimal ExactDecimal::operator-(const ExactDecimal& o) const {
  ExactDecimal neg = o;
  if (!neg.is_zero()) neg.negative = !neg.negative;
  return *this + neg;
}

std::string ExactDecimal::fixed() const {
  if (is_zero()) return "0";
  std::string s = negative ? "-" : "";
  if (exponent >= 0) return s + digits + std::string(static_cast<std::size_t>(exponent), '0');
  const std::size_t frac = static_cast<std::size_t>(-exponent);
  if (frac >= digits.size()) return s + "0." + std::string(frac - digits.size(), '0') + digits;
  return s + digits.substr(0, digits.size() - frac) + "." + digits.substr(digits.size() - frac);
}

double ExactDecimal::to_double() const {
  if (is_zero()) return 0.0;
  const std::string text = (negative ? "-" : "") + digits + "e" + std::to_string(exponent);
  double v = 0.0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
  if (res.ec == std::errc::result_out_of_range) {
    // Beyond the doubles: from_chars leaves v alone; the caller's range checks see inf or 0.
    const bool huge = exponent + static_cast<int>(digits.size()) > 0;
    return (negative ? -1.0 : 1.0) * (huge ? HUGE_VAL : 0.0);
  }
  return v;
}

OffsetAxis::OffsetAxis(double origin) : zero_(origin == 0.0), origin_(origin) {
  if (!zero_) exact_ = ExactDecimal::of(origin);
}

void OffsetAxis::append_absolute(std::string& out, double local) const {
  char tmp[32];
  const auto res = std::to_chars(tmp, tmp + sizeof tmp, local);  // shortest round-trip form
  if (zero_ || !std::isfinite(local)) {
    out.append(tmp, res.ptr);
    return;
  }
  const ExactDecimal sum = exact_ + *ExactDecimal::parse(std::string_view(tmp, static_cast<std::size_t>(res.ptr - tmp)));
  out += sum.fixed();
}

std::optional<double> OffsetAxis::local_from_text(std::string_view text) const {
  const auto d = ExactDecimal::parse(text);
  if (!d) return std::nullopt;
  return zero_ ? d->to_double() : (*d - exact_).to_double();
}

}  // namespace fp
