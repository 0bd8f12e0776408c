#pragma once
// The VTU layout every frontpack VTU file uses (spheres, shapes' centres, shapes' surfaces):
// an UnstructuredGrid whose arrays are appended as raw binary after the XML (exact doubles,
// native byte order, each block a UInt64 byte count then the bytes). A writer lists its arrays
// (section, type, name, components, what to emit); this file lays out the header, the offsets
// and the data, and checks that each array emitted the bytes it announced.
#include <cstdint>
#include <cstring>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// Buffered raw output of the appended data; counts the bytes written.
class VtuRawOut {
 public:
  explicit VtuRawOut(std::ostream& out) : out_(out) { buf_.reserve(kBlock + 64); }
  template <typename T>
  void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    buf_.append(b, sizeof(T));
    bytes_ += sizeof(T);
    if (buf_.size() >= kBlock) flush();
  }
  void put3(const Vec3& v) {
    put(v.x());
    put(v.y());
    put(v.z());
  }
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }
  std::uint64_t bytes() const { return bytes_; }

 private:
  static constexpr std::size_t kBlock = 1 << 16;
  std::ostream& out_;
  std::string buf_;
  std::uint64_t bytes_ = 0;
};

struct VtuArray {
  enum Section { PointData, CellData, Points, Cells } section;
  const char* type;  // "Float64", "Int64", "UInt8"
  std::string name;
  int components;
  std::uint64_t values;  // scalars in the array (tuples * components)
  std::size_t value_size;
  std::function<void(VtuRawOut&)> emit;  // writes exactly `values` scalars

  std::uint64_t bytes() const { return values * value_size; }
};

inline constexpr std::uint8_t kVtkVertex = 1;
inline constexpr std::uint8_t kVtkPolyLine = 4;
inline constexpr std::uint8_t kVtkTriangle = 5;
inline constexpr std::uint8_t kVtkPolygon = 7;

/// The Cells arrays of n points shown as n VTK_VERTEX cells (point i is cell i).
void append_vertex_cells(std::vector<VtuArray>& arrays, std::uint64_t n);

/// Writes the file: the arrays' data follow in the order of `arrays`; the header lists each
/// section's arrays in that order (CellData only when it has some). `point_attributes` goes
/// into the PointData tag (e.g. ` Scalars="radius"`), `field_data` before the Piece.
/// Throws std::runtime_error naming `path` if an array emits other than its announced bytes.
void write_vtu_appended(std::ostream& out, const std::string& path, std::uint64_t n_points, std::uint64_t n_cells,
                        const std::string& point_attributes, const std::vector<VtuArray>& arrays,
                        const std::string& field_data = "");

}  // namespace fp
