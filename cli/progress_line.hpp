#pragma once
// The progress line of `frontpack pack --progress` (stderr, rewritten in place).
#include <cstdint>
#include <cstdio>

namespace fp {

class ProgressLine {
 public:
  explicit ProgressLine(bool on) : on_(on) {}
  void operator()(std::uint64_t n, double t, double vf) {
    std::fprintf(stderr, "\r  packed %12llu   %10.0f /s   VF %.4f   %6.1f s ", static_cast<unsigned long long>(n),
                 t > 0 ? static_cast<double>(n) / t : 0.0, vf, t);
    std::fflush(stderr);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }
  bool on() const { return on_; }

 private:
  bool on_;
  bool shown_ = false;
};

}  // namespace fp
