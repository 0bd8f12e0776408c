#include "core/geometry/msh_reader.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fp {
namespace {

struct MshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Nodes of each element type Gmsh numbers (its documentation's list); 0: unknown.
int nodes_of_type(long long type) {
  static const int kNodes[] = {0,  2,  3,  4,  4,  8,  6,  5,  3,  6,  9,  10, 27, 18, 14, 1,
                               8,  20, 15, 13, 9,  10, 12, 15, 15, 21, 4,  5,  6,  20, 35, 56};
  if (type >= 1 && type < static_cast<long long>(std::size(kNodes))) return kNodes[type];
  if (type == 92) return 64;
  if (type == 93) return 125;
  return 0;
}
constexpr long long kTriangle = 2, kTetrahedron = 4;

// The file's bytes with a read position. ASCII reads count lines; an error names the line in an
// ASCII file and the byte offset in a binary one (whose data may hold any byte).
class Cursor {
 public:
  explicit Cursor(std::string bytes) : s_(std::move(bytes)) {}
  void set_binary() { binary_ = true; }
  bool binary() const { return binary_; }

  [[noreturn]] void fail(const std::string& what) const {
    throw MshError((binary_ ? "byte " + std::to_string(pos_) : "line " + std::to_string(line_)) + ": " + what);
  }
  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  std::string word(const char* what) {
    skip_space();
    if (pos_ >= s_.size()) fail("the file ends where " + std::string(what) + " was expected");
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  long long integer(const char* what) {
    const std::string w = word(what);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if (errno != 0 || end != w.c_str() + w.size()) fail(std::string(what) + " must be an integer, got '" + w + "'");
    return v;
  }
  std::uint64_t count(const char* what) {
    const long long v = integer(what);
    if (v < 0) fail(std::string(what) + " must be >= 0, got " + std::to_string(v));
    return static_cast<std::uint64_t>(v);
  }
  double real(const char* what) {
    const std::string w = word(what);
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end != w.c_str() + w.size() || !std::isfinite(v)) fail(std::string(what) + " must be a finite number, got '" + w + "'");
    return v;
  }
  /// A double-quoted name, on the rest of the line.
  std::string quoted(const char* what) {
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != '"') fail(std::string(what) + " must be a double-quoted name");
    const std::size_t close = s_.find('"', pos_ + 1);
    if (close == std::string::npos || s_.find('\n', pos_) < close) fail(std::string(what) + ": the name's quote is not closed");
    std::string name = s_.substr(pos_ + 1, close - pos_ - 1);
    pos_ = close + 1;
    return name;
  }
  void expect(const std::string& keyword) {
    const std::string w = word(keyword.c_str());
    if (w != keyword) fail("expected " + keyword + ", got '" + w.substr(0, 40) + "'");
  }
  /// Binary data starts after the newline that ends the current line.
  void to_next_line() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if (pos_ >= s_.size()) fail("the file ends before its binary data");
    ++pos_;
    ++line_;
  }
  template <class T>
  T raw(const char* what) {
    if (s_.size() - pos_ < sizeof(T)) fail("the file ends inside " + std::string(what));
    T v;
    std::memcpy(&v, s_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // Version 4.1's fields, text or binary by the file type: size_t, int, double.
  std::uint64_t size(const char* what) { return binary_ ? raw<std::uint64_t>(what) : count(what); }
  long long small(const char* what) { return binary_ ? raw<int>(what) : integer(what); }
  double number(const char* what) { return binary_ ? raw<double>(what) : real(what); }

  /// Refuses a count of items the rest of the file cannot hold (at least `bytes_each` each),
  /// before anything is allocated for them.
  void check_room(std::uint64_t n, std::size_t bytes_each, const char* what) const {
    if (n > (s_.size() - pos_) / bytes_each)
      fail(std::to_string(n) + " " + what + " cannot fit in the " + std::to_string(s_.size() - pos_) +
           " bytes left in the file");
  }
  /// Skips an unknown section: to the line "$End<name>".
  void skip_section(const std::string& name) {
    const std::string end = "\n$End" + name;
    const std::size_t at = s_.find(end, pos_);
    if (at == std::string::npos) fail("section $" + name + " has no end line");
    for (std::size_t k = pos_; k < at + 1; ++k) line_ += s_[k] == '\n';
    pos_ = at + 1;
    expect("$End" + name);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  void skip_space() {
    while (pos_ < s_.size() && is_space(s_[pos_])) line_ += s_[pos_++] == '\n';
  }
  std::string s_;
  std::size_t pos_ = 0, line_ = 1;
  bool binary_ = false;
};

// What the sections give, node tags unresolved until every section is read.
struct Raw {
  int major = 0;  // 2 or 4
  std::vector<std::uint64_t> node_tags;
  std::vector<Vec3> nodes;
  std::vector<std::array<std::uint64_t, 4>> tets;
  std::vector<int> tet_group;
  std::vector<std::array<std::uint64_t, 3>> triangles;
  std::vector<int> triangle_group;
  std::map<std::pair<int, int>, int> entity_group;  // v4: (dim, entity tag) -> first physical tag
  std::map<std::pair<int, int>, std::string> names;
};

void read_format(Cursor& c, Raw& r) {
  c.expect("$MeshFormat");
  const std::string version = c.word("the version");
  if (version == "2.2") r.major = 2;
  else if (version == "4.1") r.major = 4;
  else c.fail("MSH version " + version + " is not supported (2.2 and 4.1 are; Gmsh writes them with -format msh22 / msh41)");
  const long long type = c.integer("the file type");
  if (type != 0 && type != 1) c.fail("the file type must be 0 (ASCII) or 1 (binary), got " + std::to_string(type));
  const long long size = c.integer("the data size");
  if (size != 8) c.fail("the data size must be 8, got " + std::to_string(size));
  if (type == 1) {
    c.to_next_line();
    c.set_binary();
    if (c.raw<int>("the byte-order check") != 1) c.fail("the byte-order check is not 1: not a little-endian binary MSH file");
  }
  c.expect("$EndMeshFormat");
}

void read_names(Cursor& c, Raw& r) {
  const std::uint64_t n = c.count("the number of physical names");
  c.check_room(n, 6, "physical names");
  for (std::uint64_t k = 0; k < n; ++k) {
    const int dim = static_cast<int>(c.integer("a physical name's dimension"));
    const int tag = static_cast<int>(c.integer("a physical name's tag"));
    r.names[{dim, tag}] = c.quoted("a physical name");
  }
}

// $Entities of version 4.1: the first physical tag of each surface and volume.
void read_entities(Cursor& c, Raw& r) {
  const bool bin = c.binary();
  if (bin) c.to_next_line();
  std::uint64_t counts[4];
  for (std::uint64_t& n : counts) n = c.size("an entity count");
  for (int dim = 0; dim < 4; ++dim) {
    c.check_room(counts[dim], bin ? 4 + 8 * 3 + 8 : 8, "entities");
    for (std::uint64_t k = 0; k < counts[dim]; ++k) {
      const int tag = static_cast<int>(c.small("an entity tag"));
      for (int q = 0; q < (dim == 0 ? 3 : 6); ++q) c.number("an entity's box");
      const std::uint64_t physicals = c.size("a physical tag count");
      c.check_room(physicals, 1, "physical tags");
      for (std::uint64_t p = 0; p < physicals; ++p) {
        const int physical = static_cast<int>(c.small("a physical tag"));
        if (p == 0) r.entity_group[{dim, tag}] = physical;
      }
      if (dim == 0) continue;
      const std::uint64_t bounding = c.size("a bounding entity count");
      c.check_room(bounding, 1, "bounding entities");
      for (std::uint64_t b = 0; b < bounding; ++b) c.small("a bounding entity");
    }
  }
}

// Version 4.1's header of $Nodes and $Elements: the numbers of blocks and of items (the
// smallest and largest tags are read past), each checked against the bytes left (an item takes
// at least `binary_bytes` or `text_bytes`; a block header 20 or 8).
std::pair<std::uint64_t, std::uint64_t> read_v4_header(Cursor& c, const std::string& item, std::size_t binary_bytes,
                                                      std::size_t text_bytes) {
  if (c.binary()) c.to_next_line();
  const std::uint64_t blocks = c.size(("the number of " + item + " blocks").c_str());
  const std::uint64_t total = c.size(("the number of " + item + "s").c_str());
  c.size(("the smallest " + item + " tag").c_str());
  c.size(("the largest " + item + " tag").c_str());
  c.check_room(total, c.binary() ? binary_bytes : text_bytes, (item + "s").c_str());
  c.check_room(blocks, c.binary() ? 20 : 8, (item + " blocks").c_str());
  return {blocks, total};
}

void add_node(Cursor& c, Raw& r, std::uint64_t tag, const Vec3& x) {
  if (!x.allFinite()) c.fail("node " + std::to_string(tag) + " has a coordinate that is not finite");
  r.node_tags.push_back(tag);
  r.nodes.push_back(x);
}

void read_nodes(Cursor& c, Raw& r) {
  const bool bin = c.binary();
  if (r.major == 2) {
    const std::uint64_t n = c.count("the number of nodes");
    if (bin) c.to_next_line();
    c.check_room(n, bin ? 4 + 24 : 8, "nodes");
    r.nodes.reserve(n);
    for (std::uint64_t k = 0; k < n; ++k) {
      if (bin) {
        const int tag = c.raw<int>("a node tag");
        Vec3 x;
        for (int a = 0; a < 3; ++a) x[a] = c.raw<double>("a node's coordinates");
        if (tag <= 0) c.fail("node tag " + std::to_string(tag) + " is not positive");
        add_node(c, r, static_cast<std::uint64_t>(tag), x);
      } else {
        const long long tag = c.integer("a node tag");
        if (tag <= 0) c.fail("node tag " + std::to_string(tag) + " is not positive");
        Vec3 x;
        for (int a = 0; a < 3; ++a) x[a] = c.real("a node coordinate");
        add_node(c, r, static_cast<std::uint64_t>(tag), x);
      }
    }
    return;
  }
  const auto [blocks, total] = read_v4_header(c, "node", 8 + 24, 8);
  r.nodes.reserve(total);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const long long dim = c.small("a node block's dimension");
    c.small("a node block's entity");
    const long long parametric = c.small("a node block's parametric flag");
    const std::uint64_t n = c.size("a node block's size");
    if (dim < 0 || dim > 3) c.fail("a node block's dimension must be 0 to 3, got " + std::to_string(dim));
    const int extra = parametric ? static_cast<int>(dim) : 0;
    c.check_room(n, bin ? 8 + 8 * (3 + extra) : 8, "nodes");
    std::vector<std::uint64_t> tags(n);
    for (std::uint64_t& t : tags) {
      t = c.size("a node tag");
      if (t == 0) c.fail("node tag 0 is not positive");
    }
    for (const std::uint64_t t : tags) {
      Vec3 x;
      for (int a = 0; a < 3; ++a) x[a] = c.number("a node coordinate");
      for (int a = 0; a < extra; ++a) c.number("a parametric coordinate");
      add_node(c, r, t, x);
    }
  }
  if (r.nodes.size() != total)
    c.fail("the node blocks hold " + std::to_string(r.nodes.size()) + " nodes, the section header says " + std::to_string(total));
}

// One element: keeps tetrahedra and triangles (with their group), reads past the rest.
void keep_element(Raw& r, long long type, const std::vector<std::uint64_t>& nodes, int group) {
  if (type == kTetrahedron) {
    r.tets.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
    r.tet_group.push_back(group);
  } else if (type == kTriangle) {
    r.triangles.push_back({nodes[0], nodes[1], nodes[2]});
    r.triangle_group.push_back(group);
  }
}

int known_nodes(Cursor& c, long long type) {
  const int k = nodes_of_type(type);
  if (k == 0) c.fail("element type " + std::to_string(type) + " is not one Gmsh documents");
  return k;
}

void read_elements(Cursor& c, Raw& r) {
  const bool bin = c.binary();
  std::vector<std::uint64_t> nodes;
  if (r.major == 2) {
    const std::uint64_t n = c.count("the number of elements");
    if (bin) c.to_next_line();
    c.check_room(n, bin ? 12 : 8, "elements");
    for (std::uint64_t k = 0; k < n;) {
      if (bin) {
        const long long type = c.raw<int>("an element block's type");
        const int in_block = c.raw<int>("an element block's size");
        const int tags = c.raw<int>("an element block's tag count");
        if (in_block <= 0 || static_cast<std::uint64_t>(in_block) > n - k || tags < 0)
          c.fail("an element block of " + std::to_string(in_block) + " elements with " + std::to_string(tags) +
                 " tags does not fit the " + std::to_string(n - k) + " elements left");
        const int per = known_nodes(c, type);
        c.check_room(static_cast<std::uint64_t>(in_block), 4u * (1 + static_cast<std::size_t>(tags) + static_cast<std::size_t>(per)), "elements");
        for (int e = 0; e < in_block; ++e, ++k) {
          c.raw<int>("an element tag");
          int group = 0;
          for (int t = 0; t < tags; ++t) {
            const int v = c.raw<int>("an element's tags");
            if (t == 0) group = v;
          }
          nodes.resize(static_cast<std::size_t>(per));
          for (std::uint64_t& v : nodes) {
            const int tag = c.raw<int>("an element's nodes");
            if (tag <= 0) c.fail("an element names node " + std::to_string(tag));
            v = static_cast<std::uint64_t>(tag);
          }
          keep_element(r, type, nodes, group);
        }
      } else {
        c.integer("an element tag");
        const long long type = c.integer("an element type");
        const int per = known_nodes(c, type);
        const std::uint64_t tags = c.count("an element's tag count");
        c.check_room(tags, 2, "element tags");
        int group = 0;
        for (std::uint64_t t = 0; t < tags; ++t) {
          const long long v = c.integer("an element's tag");
          if (t == 0) group = static_cast<int>(v);
        }
        nodes.resize(static_cast<std::size_t>(per));
        for (std::uint64_t& v : nodes) {
          const long long tag = c.integer("an element's node");
          if (tag <= 0) c.fail("an element names node " + std::to_string(tag));
          v = static_cast<std::uint64_t>(tag);
        }
        keep_element(r, type, nodes, group);
        ++k;
      }
    }
    return;
  }
  const auto [blocks, total] = read_v4_header(c, "element", 16, 4);
  std::uint64_t seen = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const long long dim = c.small("an element block's dimension");
    const long long entity = c.small("an element block's entity");
    const long long type = c.small("an element block's type");
    const std::uint64_t n = c.size("an element block's size");
    const int per = known_nodes(c, type);
    c.check_room(n, bin ? 8u * (1 + static_cast<std::size_t>(per)) : 2u * (1 + static_cast<std::size_t>(per)), "elements");
    const auto g = r.entity_group.find({static_cast<int>(dim), static_cast<int>(entity)});
    const int group = g == r.entity_group.end() ? 0 : g->second;
    nodes.resize(static_cast<std::size_t>(per));
    for (std::uint64_t e = 0; e < n; ++e) {
      c.size("an element tag");
      for (std::uint64_t& v : nodes) {
        v = c.size("an element's node");
        if (v == 0) c.fail("an element names node 0");
      }
      keep_element(r, type, nodes, group);
    }
    seen += n;
  }
  if (seen != total)
    c.fail("the element blocks hold " + std::to_string(seen) + " elements, the section header says " + std::to_string(total));
}

// Node tags to indices; every element's nodes must exist.
void resolve(const Raw& r, TetMesh& mesh) {
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  index.reserve(r.node_tags.size());
  if (r.nodes.size() > UINT32_MAX) throw MshError("more than 2^32 - 1 nodes");
  for (std::size_t k = 0; k < r.node_tags.size(); ++k)
    if (!index.emplace(r.node_tags[k], static_cast<std::uint32_t>(k)).second)
      throw MshError("node tag " + std::to_string(r.node_tags[k]) + " is given twice");
  auto at = [&](std::uint64_t tag, const char* element, std::size_t k) {
    const auto it = index.find(tag);
    if (it == index.end())
      throw MshError(std::string(element) + " " + std::to_string(k + 1) + " names node " + std::to_string(tag) + ", which the file does not have");
    return it->second;
  };
  mesh = TetMesh{};
  mesh.nodes = r.nodes;
  mesh.tets.reserve(r.tets.size());
  for (std::size_t k = 0; k < r.tets.size(); ++k)
    mesh.tets.push_back({at(r.tets[k][0], "tetrahedron", k), at(r.tets[k][1], "tetrahedron", k),
                         at(r.tets[k][2], "tetrahedron", k), at(r.tets[k][3], "tetrahedron", k)});
  mesh.tet_group = r.tet_group;
  for (std::size_t k = 0; k < r.triangles.size(); ++k)
    mesh.triangles.push_back({at(r.triangles[k][0], "triangle", k), at(r.triangles[k][1], "triangle", k),
                              at(r.triangles[k][2], "triangle", k)});
  mesh.triangle_group = r.triangle_group;
  mesh.group_names = r.names;
}

}  // namespace

bool read_msh(const std::string& path, TetMesh& mesh, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::string("cannot be opened: ") + std::strerror(errno);
    return false;
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  try {
    Cursor c(std::move(bytes).str());
    Raw r;
    read_format(c, r);
    bool nodes = false, elements = false;
    while (!c.at_end()) {
      const std::string section = c.word("a section");
      if (section.size() < 2 || section[0] != '$') c.fail("expected a section ($Name), got '" + section.substr(0, 40) + "'");
      const std::string name = section.substr(1);
      if (name == "PhysicalNames") read_names(c, r);
      else if (name == "Entities" && r.major == 4) read_entities(c, r);
      else if (name == "Nodes" && !nodes) read_nodes(c, r), nodes = true;
      else if (name == "Elements" && !elements) read_elements(c, r), elements = true;
      else if (name == "Nodes" || name == "Elements") c.fail("a second $" + name + " section");
      else {
        c.skip_section(name);
        continue;
      }
      c.expect("$End" + name);
    }
    if (!nodes) throw MshError("the file has no $Nodes section");
    if (!elements) throw MshError("the file has no $Elements section");
    resolve(r, mesh);
  } catch (const MshError& e) {
    error = e.what();
    return false;
  }
  return true;
}

}  // namespace fp
