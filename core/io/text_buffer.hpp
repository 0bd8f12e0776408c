#pragma once
// Text output built in memory in blocks and handed to the stream: one virtual call per block
// instead of per number. Numbers in the shortest form that reads back to the same double.
// Shared by the writers of sphere packings (core/io) and of shape packings (shapes/io).
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdio>
#include <ostream>
#include <string>
#include <string_view>

#include "core/io/exact_decimal.hpp"

namespace fp {

// Builds text in memory in blocks and hands them to the stream (one virtual call per block).
class TextBuffer {
 public:
  explicit TextBuffer(std::ostream& out) : out_(out) { buf_.reserve(kBlock + 256); }

  TextBuffer& number(double v) {
    char tmp[32];
    const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);  // shortest round-trip form
    buf_.append(tmp, res.ptr);
    return *this;
  }
  /// An absolute coordinate: the exact decimal of axis origin + local (core/io/exact_decimal.hpp);
  /// the plain number when the origin is 0.
  TextBuffer& coordinate(double local, const OffsetAxis& axis) {
    if (axis.zero()) return number(local);
    axis.append_absolute(buf_, local);
    return *this;
  }
  /// JSON has no spelling for NaN and infinities: null.
  TextBuffer& json_number(double v) {
    if (!std::isfinite(v)) return text("null");
    return number(v);
  }
  template <std::integral I>
  TextBuffer& integer(I v) {
    char tmp[24];
    const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, res.ptr);
    return *this;
  }
  TextBuffer& text(std::string_view s) {
    buf_.append(s);
    return *this;
  }
  TextBuffer& json_string(std::string_view s) {
    buf_ += '"';
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (c == '"' || c == '\\') {
        buf_ += '\\';
        buf_ += c;
      } else if (u < 0x20) {
        char esc[8];
        std::snprintf(esc, sizeof esc, "\\u%04x", u);
        buf_ += esc;
      } else {
        buf_ += c;
      }
    }
    buf_ += '"';
    return *this;
  }
  TextBuffer& ch(char c) {
    buf_ += c;
    if (c == '\n' && buf_.size() >= kBlock) flush();
    return *this;
  }
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kBlock = 1 << 16;
  std::ostream& out_;
  std::string buf_;
};

}  // namespace fp
