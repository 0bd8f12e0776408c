#pragma once
// The seeded, deterministic mutations of mutation_driver.cpp: what libFuzzer's mutator does,
// without its coverage feedback, plus mutations that know the inputs are mostly text with
// numbers in it (a number replaced by 1e308, nan, -0, 4294967296, ...; a keyword of the target's
// dictionary inserted or put in place of a word; a line duplicated, dropped or swapped).
// The same seed, corpus and dictionary give the same inputs on every machine (own generator,
// no std:: distributions).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fp::fuzz {

/// splitmix64: small, fast, fully specified.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n); n > 0 (the modulo bias is irrelevant here).
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
  bool one_in(std::size_t n) { return below(n) == 0; }

 private:
  std::uint64_t state_;
};

class Mutator {
 public:
  /// `corpus`: the seed inputs (at least one); `dictionary`: tokens of the target; inputs are
  /// kept to at most `max_bytes`.
  Mutator(std::uint64_t seed, std::vector<std::string> corpus, std::vector<std::string> dictionary, std::size_t max_bytes);

  /// The next input: a corpus file (or, sometimes, the previous input) with 1 to 8 mutations.
  std::string next();

  /// The extreme numbers a number of the input may be replaced by.
  static const std::vector<std::string>& extreme_numbers();

 private:
  void mutate_once(std::string& s);
  // One method per kind of mutation; each changes s in place (or leaves it when not applicable).
  void flip_bit(std::string& s);
  void set_byte(std::string& s);
  void insert_bytes(std::string& s);
  void erase_range(std::string& s);
  void duplicate_chunk(std::string& s);
  void splice(std::string& s);
  /// `plausible`: only values that keep the input well formed (another of its numbers, a sign,
  /// a nearby value), not the extremes.
  void replace_number(std::string& s, bool plausible = false);
  void insert_token(std::string& s);
  void replace_word(std::string& s);
  void edit_lines(std::string& s);
  void overwrite_integer(std::string& s);
  void truncate(std::string& s);

  char interesting_byte();
  std::size_t position(const std::string& s) { return rng_.below(s.size() + 1); }

  Random rng_;
  std::vector<std::string> corpus_;
  std::vector<std::string> dictionary_;
  std::size_t max_bytes_;
  std::string previous_;
};

}  // namespace fp::fuzz
