#include "core/metrics/ks_result.hpp"

#include <cmath>

#include "core/sampling/ks_test.hpp"

namespace fp {

KsResult ks_one_sample(std::vector<double> samples, const std::function<double(double)>& cdf) {
  KsResult out;
  if (samples.empty()) return out;
  out.n = samples.size();
  out.d = ks_statistic(std::move(samples), cdf);
  out.sqrt_n_d = std::sqrt(static_cast<double>(out.n)) * out.d;
  out.p = ks_pvalue(out.d, out.n);
  return out;
}

}  // namespace fp
