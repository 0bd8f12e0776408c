// Fuzz harness of the packing readers (core/io/packing_readers.hpp), as `frontpack validate` and
// `analyze` call them: every input is read as each format (vtu, yade, lammps, csv, json), in 2D
// and 3D, in the zero frame, in a far frame (exact decimal subtraction, core/io/exact_decimal.hpp)
// and in its own frame; and its dimension is sniffed.
// Property: a read succeeds or throws the documented std::runtime_error naming the file, without
// C++ internals in its message. A packing read has as many centres as radii, in the frame asked
// for; read in its own frame it has the same radii as in the zero frame. (Non-finite numbers are
// read as such on purpose: the validator reports them.)
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/io/packing_readers.hpp"
#include "fuzz_support.hpp"

namespace {

using fp::fuzz::require;

constexpr fp::OutputFormat kFormats[] = {fp::OutputFormat::Vtu, fp::OutputFormat::Yade, fp::OutputFormat::Lammps,
                                         fp::OutputFormat::Csv, fp::OutputFormat::Json};

/// Same doubles, NaN equal to NaN.
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

/// Runs one read; true if it succeeded. A failure must be the documented one.
template <typename Read>
bool attempt(Read&& read, const std::string& path, std::string_view input, const std::string& context) {
  try {
    read();
    return true;
  } catch (const std::runtime_error& e) {
    fp::fuzz::check_error_message(e.what(), input, context);
    require(std::string_view(e.what()).find(path) != std::string_view::npos,
            context + ": the error does not name the file: " + e.what());
  } catch (...) {
    fp::fuzz::unexpected_exception(context);
  }
  return false;
}

template <int D>
void check_packing(const fp::Packing<D>& p, const fp::Vec<D>& origin, const std::string& context) {
  require(p.centers.size() == p.radii.size(), context + ": " + std::to_string(p.centers.size()) + " centres for " +
                                                  std::to_string(p.radii.size()) + " radii");
  for (int a = 0; a < D; ++a) require(same(p.origin[a], origin[a]), context + ": not in the frame asked for");
}

template <int D>
void read_all(fp::OutputFormat format, const std::string& path, std::string_view input) {
  const std::string name = std::string(fp::output_format_name(format)) + " " + std::to_string(D) + "D";
  fp::Packing<D> zero, own;
  const bool zero_ok = attempt([&] { zero = fp::read_packing<D>(format, path); }, path, input, "read_packing " + name);
  if (zero_ok) check_packing<D>(zero, fp::Vec<D>::Zero(), "read_packing " + name);

  // A frame as far scenes have (a multiple of a power of two): the exact decimal path.
  fp::Vec<D> far;
  for (int a = 0; a < D; ++a) far[a] = a == 0 ? 1e9 : (a == 1 ? -0x1p40 : 0.5);
  fp::Packing<D> shifted;
  if (attempt([&] { shifted = fp::read_packing<D>(format, path, far); }, path, input, "read_packing far " + name)) {
    check_packing<D>(shifted, far, "read_packing far " + name);
    if (zero_ok) require(shifted.size() == zero.size(), "read_packing far " + name + ": another particle count");
  }

  if (attempt([&] { own = fp::read_packing_in_own_frame<D>(format, path); }, path, input, "read_packing_in_own_frame " + name)) {
    check_packing<D>(own, own.origin, "read_packing_in_own_frame " + name);
    require(own.origin.allFinite(), "read_packing_in_own_frame " + name + ": a non-finite frame origin");
    if (zero_ok) {
      require(own.size() == zero.size(), "read_packing_in_own_frame " + name + ": another particle count");
      for (std::size_t i = 0; i < own.size(); ++i)
        require(same(own.radii[i], zero.radii[i]), "read_packing_in_own_frame " + name + ": radius " + std::to_string(i) +
                                                        " differs from the zero frame's");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > fp::fuzz::kMaxInputBytes) size = fp::fuzz::kMaxInputBytes;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string path = fp::fuzz::write_scratch_file("packing.in", data, size);
  for (const fp::OutputFormat format : kFormats) {
    read_all<2>(format, path, input);
    read_all<3>(format, path, input);
    int dimension = 0;
    if (attempt([&] { dimension = fp::packing_file_dimension(format, path); }, path, input,
                std::string("packing_file_dimension ") + fp::output_format_name(format)))
      require(dimension == 2 || dimension == 3, "packing_file_dimension gave " + std::to_string(dimension));
  }
  return 0;
}
