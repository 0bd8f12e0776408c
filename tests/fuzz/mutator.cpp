#include "mutator.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace fp::fuzz {
namespace {

struct Span {
  std::size_t begin, end;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Every number written in s: [+-]digits[.digits][e[+-]digits] (or .digits), not inside a word.
std::vector<Span> numbers_in(const std::string& s) {
  std::vector<Span> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const bool starts = (is_digit(s[i]) || ((s[i] == '-' || s[i] == '+' || s[i] == '.') && i + 1 < s.size() &&
                                            (is_digit(s[i + 1]) || s[i + 1] == '.'))) &&
                        (i == 0 || (!is_word_char(s[i - 1]) && s[i - 1] != '.'));
    if (!starts) {
      ++i;
      continue;
    }
    const std::size_t begin = i;
    if (s[i] == '-' || s[i] == '+') ++i;
    std::size_t digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
      ++i;
      while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    }
    if (digits > 0 && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
      if (j < s.size() && is_digit(s[j])) {
        while (j < s.size() && is_digit(s[j])) ++j;
        i = j;
      }
    }
    if (digits > 0) out.push_back({begin, i});
    else i = begin + 1;
  }
  return out;
}

/// Every word (letters, digits, '_') of s that starts with a letter.
std::vector<Span> words_in(const std::string& s) {
  std::vector<Span> out;
  for (std::size_t i = 0; i < s.size();) {
    if (!std::isalpha(static_cast<unsigned char>(s[i]))) {
      ++i;
      continue;
    }
    const std::size_t begin = i;
    while (i < s.size() && is_word_char(s[i])) ++i;
    out.push_back({begin, i});
  }
  return out;
}

/// Start offsets of the lines of s (the first line starts at 0).
std::vector<std::size_t> line_starts(const std::string& s) {
  std::vector<std::size_t> out{0};
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == '\n' && i + 1 < s.size()) out.push_back(i + 1);
  return out;
}

}  // namespace

const std::vector<std::string>& Mutator::extreme_numbers() {
  static const std::vector<std::string> values = {
      // beyond, at and near the ends of the doubles
      "1e308", "-1e308", "1.7976931348623157e308", "1e309", "1e999", "-1e999", "4.9e-324", "2.2250738585072014e-308",
      "1e-320", "1e-999", "1e999999999", "1e-999999999", "1e2147483648",
      // zeros, signs, the values that are not numbers (C and YAML spellings)
      "0", "-0", "+0", "0.0", "-0.0", "nan", "-nan", "NaN", "inf", "-inf", "infinity", ".inf", "-.inf", ".nan", "1e", "--1", ".",
      // integers at the limits of 32 and 64 bits, and counts no file can hold
      "2e9", "2147483647", "2147483648", "-2147483648", "-2147483649", "4294967295", "4294967296", "9007199254740993",
      "9223372036854775807", "9223372036854775808", "-9223372036854775808", "-9223372036854775809",
      "18446744073709551615", "18446744073709551616", "99999999999999999999999999999", "1000000000000",
      // small integers and values a schema treats specially
      "1", "-1", "2", "3", "4", "7", "100", "0.5", "1e-12", "1e12", "0x10", "1_000", "1,5", "00012"};
  return values;
}

Mutator::Mutator(std::uint64_t seed, std::vector<std::string> corpus, std::vector<std::string> dictionary, std::size_t max_bytes)
    : rng_(seed), corpus_(std::move(corpus)), dictionary_(std::move(dictionary)), max_bytes_(max_bytes) {
  if (corpus_.empty()) throw std::invalid_argument("the mutator needs at least one corpus input");
}

std::string Mutator::next() {
  // Mostly a fresh corpus file; sometimes the previous mutant again, so that mutations stack deep.
  std::string s = !previous_.empty() && rng_.one_in(4) ? previous_ : corpus_[rng_.below(corpus_.size())];
  if (rng_.one_in(4)) {
    // Numbers only: the syntax stays valid, so the input gets past the reader to what uses the
    // numbers (a mesh's geometry, a container, a distribution, counts and indices).
    const std::size_t count = 1 + rng_.below(4);
    const bool plausible = rng_.one_in(2);
    for (std::size_t k = 0; k < count; ++k) replace_number(s, plausible);
  } else {
    const std::size_t count = 1 + rng_.below(rng_.one_in(3) ? 8 : 3);
    for (std::size_t k = 0; k < count; ++k) mutate_once(s);
  }
  if (s.size() > max_bytes_) s.resize(max_bytes_);
  previous_ = s;
  return s;
}

void Mutator::mutate_once(std::string& s) {
  // Weights: the text-aware mutations (numbers, tokens, lines) find most; the byte-level ones
  // reach what no token describes (binary STL and VTU headers, encodings, separators).
  switch (rng_.below(20)) {
    case 0: flip_bit(s); break;
    case 1: set_byte(s); break;
    case 2: insert_bytes(s); break;
    case 3: erase_range(s); break;
    case 4: duplicate_chunk(s); break;
    case 5: splice(s); break;
    case 6: case 7: case 8: case 9: replace_number(s); break;
    case 10: case 11: case 12: insert_token(s); break;
    case 13: case 14: replace_word(s); break;
    case 15: case 16: edit_lines(s); break;
    case 17: case 18: overwrite_integer(s); break;
    default: truncate(s); break;
  }
}

char Mutator::interesting_byte() {
  static const char bytes[] = {'\0', '\n', '\r', '\t', ' ', '-', '+', '.', ',', ':', '[', ']', '{', '}', '#', '"',
                               '\'', '&', '*', '!', '|', '>', '?', '%', '@', '`', 'e', 'E', '0', '1', '9', '\\',
                               '<', '/', '=', '_', '\x7f', '\xff', '\x80', '\xc3'};
  if (rng_.one_in(3)) return static_cast<char>(rng_.below(256));
  return bytes[rng_.below(sizeof bytes)];
}

void Mutator::flip_bit(std::string& s) {
  if (s.empty()) return;
  s[rng_.below(s.size())] ^= static_cast<char>(1u << rng_.below(8));
}

void Mutator::set_byte(std::string& s) {
  if (s.empty()) return;
  s[rng_.below(s.size())] = interesting_byte();
}

void Mutator::insert_bytes(std::string& s) {
  const std::size_t n = 1 + rng_.below(8);
  std::string bytes;
  for (std::size_t k = 0; k < n; ++k) bytes += interesting_byte();
  s.insert(position(s), bytes);
}

void Mutator::erase_range(std::string& s) {
  if (s.empty()) return;
  const std::size_t at = rng_.below(s.size());
  s.erase(at, 1 + rng_.below(rng_.one_in(4) ? 256 : 16));
}

void Mutator::duplicate_chunk(std::string& s) {
  if (s.empty()) return;
  const std::size_t at = rng_.below(s.size());
  const std::string chunk = s.substr(at, 1 + rng_.below(rng_.one_in(4) ? 512 : 64));
  // Sometimes many copies: long lists, deep nesting, repeated sections.
  const std::size_t copies = rng_.one_in(8) ? 2 + rng_.below(200) : 1;
  std::string repeated;
  for (std::size_t k = 0; k < copies && repeated.size() < max_bytes_; ++k) repeated += chunk;
  s.insert(position(s), repeated);
}

void Mutator::splice(std::string& s) {
  const std::string& other = corpus_[rng_.below(corpus_.size())];
  if (other.empty()) return;
  if (rng_.one_in(2)) {  // this input's head, the other's tail
    s = s.substr(0, position(s)) + other.substr(rng_.below(other.size()));
  } else {  // a chunk of the other inserted
    const std::size_t at = rng_.below(other.size());
    s.insert(position(s), other.substr(at, 1 + rng_.below(256)));
  }
}

void Mutator::replace_number(std::string& s, bool plausible) {
  const std::vector<Span> spans = numbers_in(s);
  if (spans.empty()) return insert_bytes(s);
  const Span span = spans[rng_.below(spans.size())];
  const std::string old = s.substr(span.begin, span.end - span.begin);
  std::string value;
  switch (plausible ? rng_.below(5) : rng_.below(8)) {
    case 0: value = "-" + old; break;                                       // a sign flipped in
    case 1: value = old + "e" + std::to_string(rng_.below(700)); break;     // far larger
    case 2: value = std::to_string(rng_.next() >> rng_.below(64)); break;   // any integer size
    case 3: {  // another number of the input: coincident points, repeated indices, equal bounds
      const Span other = spans[rng_.below(spans.size())];
      value = s.substr(other.begin, other.end - other.begin);
      break;
    }
    case 4: {  // nearly the same: digits added to the mantissa
      const std::size_t e = std::min(old.find_first_of("eE"), old.size());
      value = old.substr(0, e) + (old.substr(0, e).find('.') == std::string::npos ? ".000001" : "000001") + old.substr(e);
      break;
    }
    default: value = extreme_numbers()[rng_.below(extreme_numbers().size())]; break;
  }
  s.replace(span.begin, span.end - span.begin, value);
}

void Mutator::insert_token(std::string& s) {
  if (dictionary_.empty()) return insert_bytes(s);
  const std::string& token = dictionary_[rng_.below(dictionary_.size())];
  if (rng_.one_in(2)) {  // at the start of a line, where keys and keywords go
    const std::vector<std::size_t> starts = line_starts(s);
    s.insert(starts[rng_.below(starts.size())], token + (rng_.one_in(2) ? " " : ""));
  } else {
    s.insert(position(s), token);
  }
}

void Mutator::replace_word(std::string& s) {
  const std::vector<Span> spans = words_in(s);
  if (spans.empty() || dictionary_.empty()) return insert_token(s);
  const Span span = spans[rng_.below(spans.size())];
  s.replace(span.begin, span.end - span.begin, dictionary_[rng_.below(dictionary_.size())]);
}

void Mutator::edit_lines(std::string& s) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < s.size();) {
    const std::size_t end = s.find('\n', start);
    const std::size_t stop = end == std::string::npos ? s.size() : end + 1;
    lines.push_back(s.substr(start, stop - start));
    start = stop;
  }
  if (lines.empty()) return;
  const std::size_t a = rng_.below(lines.size()), b = rng_.below(lines.size());
  switch (rng_.below(4)) {
    case 0: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(b), lines[a]); break;  // duplicate
    case 1: lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(a)); break;               // drop
    case 2: std::swap(lines[a], lines[b]); break;                                            // swap
    default: {  // indent or dedent: moves a YAML key to another mapping
      std::string& l = lines[a];
      if (rng_.one_in(2)) l.insert(0, std::string(1 + rng_.below(4), ' '));
      else l.erase(0, std::min<std::size_t>(l.find_first_not_of(' '), 1 + rng_.below(4)));
    }
  }
  s.clear();
  for (const auto& l : lines) s += l;
}

void Mutator::overwrite_integer(std::string& s) {
  // Little-endian integers at the limits: the triangle count of a binary STL (offset 80), the
  // byte counts of VTU blocks.
  static const std::uint64_t values[] = {0, 1, 2, 0x7f, 0x80, 0xff, 0x7fff, 0x8000, 0xffff, 0x7fffffff, 0x80000000,
                                         0xffffffff, 0x100000000ULL, 0x7fffffffffffffffULL, 0x8000000000000000ULL,
                                         0xffffffffffffffffULL, 0x3ff0000000000000ULL /* 1.0 */,
                                         0x7ff8000000000000ULL /* nan */, 0x7ff0000000000000ULL /* inf */};
  if (s.empty()) return;
  const std::size_t width = std::size_t(1) << rng_.below(4);  // 1, 2, 4 or 8 bytes
  const std::size_t at = rng_.one_in(4) && s.size() >= 84 ? 80 : rng_.below(s.size());
  std::uint64_t v = values[rng_.below(sizeof values / sizeof values[0])];
  if (rng_.one_in(4)) v += rng_.below(3) - 1;  // off by one either way
  for (std::size_t k = 0; k < width && at + k < s.size(); ++k) s[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
}

void Mutator::truncate(std::string& s) {
  if (s.empty()) return;
  s.resize(rng_.below(s.size()));
}

}  // namespace fp::fuzz
