#pragma once
// Runs one step of an analysis and appends (name, seconds) to its timings.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace fp {

template <class F>
void timed_step(std::vector<std::pair<std::string, double>>& timings, const char* name, F&& step) {
  const auto t0 = std::chrono::steady_clock::now();
  step();
  timings.emplace_back(name, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace fp
