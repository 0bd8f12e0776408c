#include "core/io/vtu_appended.hpp"

#include <bit>
#include <stdexcept>

namespace fp {

void append_vertex_cells(std::vector<VtuArray>& arrays, std::uint64_t n) {
  using S = VtuArray;
  arrays.push_back({S::Cells, "Int64", "connectivity", 1, n, 8, [n](VtuRawOut& o) {
                      for (std::uint64_t i = 0; i < n; ++i) o.put<std::int64_t>(static_cast<std::int64_t>(i));
                    }});
  arrays.push_back({S::Cells, "Int64", "offsets", 1, n, 8, [n](VtuRawOut& o) {
                      for (std::uint64_t i = 0; i < n; ++i) o.put<std::int64_t>(static_cast<std::int64_t>(i + 1));
                    }});
  arrays.push_back({S::Cells, "UInt8", "types", 1, n, 1, [n](VtuRawOut& o) {
                      for (std::uint64_t i = 0; i < n; ++i) o.put<std::uint8_t>(kVtkVertex);
                    }});
}

void write_vtu_appended(std::ostream& out, const std::string& path, std::uint64_t n_points, std::uint64_t n_cells,
                        const std::string& point_attributes, const std::vector<VtuArray>& arrays,
                        const std::string& field_data) {
  std::vector<std::uint64_t> offsets;
  std::uint64_t offset = 0;
  bool cell_data = false;
  for (const auto& a : arrays) {
    offsets.push_back(offset);
    offset += sizeof(std::uint64_t) + a.bytes();
    cell_data = cell_data || a.section == VtuArray::CellData;
  }
  auto section = [&](VtuArray::Section s, const std::string& indent) {
    std::string x;
    for (std::size_t k = 0; k < arrays.size(); ++k) {
      const auto& a = arrays[k];
      if (a.section != s) continue;
      x += indent + "<DataArray type=\"" + a.type + "\" Name=\"" + a.name + "\"";
      if (a.components > 1) x += " NumberOfComponents=\"" + std::to_string(a.components) + "\"";
      x += " format=\"appended\" offset=\"" + std::to_string(offsets[k]) + "\"/>\n";
    }
    return x;
  };
  std::string h;
  h += "<?xml version=\"1.0\"?>\n";
  h += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  h += std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  h += "\" header_type=\"UInt64\">\n";
  h += "  <UnstructuredGrid>\n";
  h += field_data;
  h += "    <Piece NumberOfPoints=\"" + std::to_string(n_points) + "\" NumberOfCells=\"" + std::to_string(n_cells) +
       "\">\n";
  h += "      <PointData" + point_attributes + ">\n" + section(VtuArray::PointData, "        ") + "      </PointData>\n";
  if (cell_data) h += "      <CellData>\n" + section(VtuArray::CellData, "        ") + "      </CellData>\n";
  h += "      <Points>\n" + section(VtuArray::Points, "        ") + "      </Points>\n";
  h += "      <Cells>\n" + section(VtuArray::Cells, "        ") + "      </Cells>\n";
  h += "    </Piece>\n";
  h += "  </UnstructuredGrid>\n";
  h += "  <AppendedData encoding=\"raw\">\n   _";
  out.write(h.data(), static_cast<std::streamsize>(h.size()));

  VtuRawOut raw(out);
  for (const auto& a : arrays) {
    const std::uint64_t before = raw.bytes();
    raw.put<std::uint64_t>(a.bytes());
    a.emit(raw);
    if (raw.bytes() - before != sizeof(std::uint64_t) + a.bytes())
      throw std::runtime_error("cannot write '" + path + "': internal error: VTU array '" + a.name + "' has " +
                               std::to_string(raw.bytes() - before - 8) + " bytes, announced " + std::to_string(a.bytes()));
  }
  raw.flush();
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
}

}  // namespace fp
