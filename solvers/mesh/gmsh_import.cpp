// Gmsh MSH 4.1 ASCII reader. The format is the one of the Gmsh reference manual, section "MSH file
// format" (version 4.1); node order inside elements from its section "Node ordering".
// Coordinates are taken as they are in the file, which our cases write in SI units (m).
#include "mesh/gmsh_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

// Nodes per element of the Gmsh types a mesh is likely to carry (reference manual, "MSH file
// format", elm-type); other types are read with whatever nodes their line holds.
std::optional<int> gmsh_node_count(int type) {
  static constexpr std::array<int, 20> counts = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  if (type >= 1 && type < static_cast<int>(counts.size())) return counts[static_cast<size_t>(type)];
  return std::nullopt;
}

// Our element type for a Gmsh type in the mesh dimension (mesh/element_topology.hpp), or nothing
// when we have no such element; `linear_hex` chooses between the types that share Gmsh's hexahedron.
std::optional<ElementType> mesh_element(int gmsh_type, int dim, ElementType linear_hex) {
  std::optional<ElementType> found;
  for (ElementType t : element_types()) {
    const ElementTopology& e = topology(t);
    if (e.gmsh_type != gmsh_type || e.dimension != dim) continue;
    if (!found || t == linear_hex) found = t;
  }
  return found;
}

// Whitespace-separated tokens (a double-quoted string is one token) with the line each came from.
class MshLexer {
 public:
  explicit MshLexer(std::filesystem::path file) : file_(std::move(file)) {
    require_readable_file(file_, false);
    std::ifstream in(file_, std::ios::binary);
    if (!in) throw InputError(fmt::format("{}: cannot open the Gmsh mesh file", file_.string()));
    for (std::string line; std::getline(in, line);) lines_.push_back(std::move(line));
    rest_.assign(lines_.size() + 1, 0);
    for (size_t i = lines_.size(); i-- > 0;) rest_[i] = rest_[i + 1] + lines_[i].size() + 1;
  }

  [[noreturn]] void fail(int line, std::string_view message) const {
    throw InputError(fmt::format("{}:{}: {}", file_.string(), line, message));
  }
  [[noreturn]] void fail(std::string_view message) const { fail(line_, message); }

  // Line of the last token read (1-based).
  int line() const { return line_; }

  // The next token, or nothing at the end of the file.
  std::optional<std::string_view> try_next() {
    while (row_ < lines_.size()) {
      const std::string& text = lines_[row_];
      while (col_ < text.size() && is_space(text[col_])) ++col_;
      if (col_ == text.size()) {
        ++row_;
        col_ = 0;
        continue;
      }
      line_ = static_cast<int>(row_) + 1;
      const size_t start = col_;
      if (text[col_] == '"') {
        const size_t close = text.find('"', col_ + 1);
        if (close == std::string::npos) fail("unterminated quoted string");
        col_ = close + 1;
      } else {
        while (col_ < text.size() && !is_space(text[col_])) ++col_;
      }
      return std::string_view(text).substr(start, col_ - start);
    }
    return std::nullopt;
  }

  std::string_view next(std::string_view what) {
    const auto token = try_next();
    if (!token) fail(static_cast<int>(lines_.size()), fmt::format("unexpected end of file, expected {}", what));
    return *token;
  }

  // True when nothing but whitespace is left on the line of the last token.
  bool at_line_end() const {
    if (row_ >= lines_.size() || static_cast<int>(row_) + 1 != line_) return true;
    const std::string& text = lines_[row_];
    for (size_t c = col_; c < text.size(); ++c)
      if (!is_space(text[c])) return false;
    return true;
  }

  long next_long(std::string_view what) {
    const std::string_view token = next(what);
    long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size())
      fail(fmt::format("expected {} (an integer), found '{}'", what, token));
    return value;
  }

  int next_int(std::string_view what) {
    const long value = next_long(what);
    if (value < -2147483647L || value > 2147483647L) fail(fmt::format("{} {} is out of range", what, value));
    return static_cast<int>(value);
  }

  // A count of things that follow, each `tokens_each` tokens at least. A count the rest of the file
  // cannot hold is refused here, before anything is reserved for it (4294967295 elements would
  // otherwise end in std::bad_alloc).
  size_t next_count(std::string_view what, size_t tokens_each = 1) {
    const long value = next_long(what);
    if (value < 0) fail(fmt::format("{} must not be negative, found {}", what, value));
    const size_t most = tokens_left() / tokens_each;
    if (static_cast<unsigned long>(value) > most)
      fail(fmt::format("{} is {}, more than the rest of the file can hold (at most {})", what, value, most));
    return static_cast<size_t>(value);
  }

  double next_double(std::string_view what) {
    const std::string_view token = next(what);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
      fail(fmt::format("expected {} (a number), found '{}'", what, token));
    return value;
  }

  void expect(std::string_view keyword) {
    const std::string_view token = next(keyword);
    if (token != keyword) fail(fmt::format("expected {}, found '{}'", keyword, token));
  }

  // Skips the body of a section whose header was the last token, up to and including its end marker.
  void skip_section(std::string_view name) {
    const int header = line_;
    const std::string end = "$End" + std::string(name);
    for (++row_; row_ < lines_.size(); ++row_) {
      std::string_view text = lines_[row_];
      while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
      while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
      if (text == end) {
        line_ = static_cast<int>(row_) + 1;
        ++row_;
        col_ = 0;
        return;
      }
    }
    fail(header, fmt::format("section ${} has no {}", name, end));
  }

 private:
  // An upper bound on the tokens after the read position: each takes a character and a separator.
  size_t tokens_left() const {
    if (row_ >= lines_.size()) return 0;
    return (rest_[row_] - std::min(col_, lines_[row_].size()) + 1) / 2;
  }

  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

  std::filesystem::path file_;
  std::vector<std::string> lines_;
  std::vector<size_t> rest_;  // characters (with line ends) from the start of each line to the end
  size_t row_ = 0;            // position of the next character to read
  size_t col_ = 0;
  int line_ = 1;
};

struct RawElement {
  long tag = 0;
  int line = 0;
  std::vector<long> nodes;  // Gmsh node tags, Gmsh order
};

struct RawBlock {
  int entity_dim = 0;
  int entity_tag = 0;
  int type = 0;
  int line = 0;  // of the block header
  std::vector<RawElement> elements;
};

struct RawNodes {
  std::vector<long> tags;  // file order
  std::vector<Eigen::Vector3d> coords;
  std::vector<int> lines;               // line of each node's coordinates
  std::unordered_map<long, int> index;  // tag -> position in file order
};

using EntityKey = std::pair<int, int>;  // (dimension, tag)

void read_mesh_format(MshLexer& lex) {
  const std::string_view version = lex.next("the MSH version");
  const int version_line = lex.line();
  if (version != "4.1")
    lex.fail(version_line, fmt::format("MSH version {} is not supported; write the mesh as MSH 4.1 "
                                       "(gmsh -format msh41, or Mesh.MshFileVersion = 4.1)",
                                       version));
  const int file_type = lex.next_int("the MSH file type");
  if (file_type != 0) lex.fail("binary MSH files are not supported; write the mesh as ASCII (Mesh.Binary = 0)");
  lex.next_int("the MSH data size");
  lex.expect("$EndMeshFormat");
}

void read_physical_names(MshLexer& lex, std::map<EntityKey, std::string>& names) {
  const size_t n = lex.next_count("the number of physical names", 3);
  for (size_t i = 0; i < n; ++i) {
    const int dim = lex.next_int("a physical group dimension");
    const int tag = lex.next_int("a physical group tag");
    const std::string_view quoted = lex.next("a physical group name");
    if (quoted.size() < 2 || quoted.front() != '"' || quoted.back() != '"')
      lex.fail(fmt::format("expected a double-quoted physical group name, found '{}'", quoted));
    names[{dim, tag}] = std::string(quoted.substr(1, quoted.size() - 2));
  }
  lex.expect("$EndPhysicalNames");
}

void read_entities(MshLexer& lex, std::map<EntityKey, std::vector<int>>& physicals) {
  std::array<size_t, 4> counts{};
  for (int d = 0; d < 4; ++d) counts[static_cast<size_t>(d)] = lex.next_count("the number of entities");
  for (int d = 0; d < 4; ++d) {
    for (size_t i = 0; i < counts[static_cast<size_t>(d)]; ++i) {
      const int tag = lex.next_int("an entity tag");
      const int n_box = d == 0 ? 3 : 6;  // a point's coordinates, or a bounding box
      for (int k = 0; k < n_box; ++k) lex.next_double("an entity coordinate");
      std::vector<int>& groups = physicals[{d, tag}];
      const size_t n_physical = lex.next_count("the number of physical tags");
      for (size_t k = 0; k < n_physical; ++k) groups.push_back(lex.next_int("a physical tag"));
      if (d > 0) {
        const size_t n_bounding = lex.next_count("the number of bounding entities");
        for (size_t k = 0; k < n_bounding; ++k) lex.next_int("a bounding entity tag");
      }
    }
  }
  lex.expect("$EndEntities");
}

void read_nodes(MshLexer& lex, RawNodes& nodes) {
  if (!nodes.tags.empty()) lex.fail("a second $Nodes section");
  const size_t n_blocks = lex.next_count("the number of node blocks", 4);
  const size_t n_nodes = lex.next_count("the number of nodes", 4);  // a tag and three coordinates
  lex.next_long("the smallest node tag");
  lex.next_long("the largest node tag");
  nodes.tags.reserve(n_nodes);
  nodes.coords.reserve(n_nodes);
  nodes.lines.reserve(n_nodes);
  nodes.index.reserve(n_nodes);
  for (size_t b = 0; b < n_blocks; ++b) {
    const int entity_dim = lex.next_int("an entity dimension");
    if (entity_dim < 0 || entity_dim > 3) lex.fail(fmt::format("entity dimension {} is not 0 to 3", entity_dim));
    lex.next_int("an entity tag");
    const int parametric = lex.next_int("the parametric flag");
    const size_t in_block = lex.next_count("the number of nodes in the block", 4);
    const size_t first = nodes.tags.size();
    for (size_t i = 0; i < in_block; ++i) {
      const long tag = lex.next_long("a node tag");
      if (!nodes.index.emplace(tag, static_cast<int>(nodes.tags.size())).second)
        lex.fail(fmt::format("node tag {} is defined twice", tag));
      nodes.tags.push_back(tag);
    }
    for (size_t i = 0; i < in_block; ++i) {
      Eigen::Vector3d x;
      for (int k = 0; k < 3; ++k) x(k) = lex.next_double("a node coordinate");
      nodes.coords.push_back(x);
      nodes.lines.push_back(lex.line());
      if (parametric != 0)
        for (int k = 0; k < entity_dim; ++k) lex.next_double("a parametric coordinate");
    }
    if (nodes.coords.size() != first + in_block) lex.fail("node block is incomplete");
  }
  if (nodes.tags.size() != n_nodes)
    lex.fail(fmt::format("$Nodes announces {} nodes but its blocks hold {}", n_nodes, nodes.tags.size()));
  lex.expect("$EndNodes");
}

void read_elements(MshLexer& lex, std::vector<RawBlock>& blocks) {
  if (!blocks.empty()) lex.fail("a second $Elements section");
  const size_t n_blocks = lex.next_count("the number of element blocks", 4);
  const size_t n_elements = lex.next_count("the number of elements", 2);  // a tag and a node at least
  lex.next_long("the smallest element tag");
  lex.next_long("the largest element tag");
  size_t total = 0;
  for (size_t b = 0; b < n_blocks; ++b) {
    RawBlock block;
    block.entity_dim = lex.next_int("an entity dimension");
    block.line = lex.line();
    if (block.entity_dim < 0 || block.entity_dim > 3)
      lex.fail(fmt::format("entity dimension {} is not 0 to 3", block.entity_dim));
    block.entity_tag = lex.next_int("an entity tag");
    block.type = lex.next_int("an element type");
    const size_t in_block = lex.next_count("the number of elements in the block", 2);
    const std::optional<int> expected = gmsh_node_count(block.type);
    block.elements.reserve(in_block);
    for (size_t i = 0; i < in_block; ++i) {
      RawElement e;
      e.tag = lex.next_long("an element tag");
      e.line = lex.line();
      // One element per line: its nodes are the rest of the line.
      while (!lex.at_line_end()) e.nodes.push_back(lex.next_long("a node tag"));
      if (expected && static_cast<int>(e.nodes.size()) != *expected)
        lex.fail(e.line, fmt::format("element {} of type {} has {} nodes, expected {}", e.tag, block.type,
                                     e.nodes.size(), *expected));
      if (e.nodes.empty()) lex.fail(e.line, fmt::format("element {} has no nodes", e.tag));
      block.elements.push_back(std::move(e));
    }
    total += in_block;
    blocks.push_back(std::move(block));
  }
  if (total != n_elements)
    lex.fail(fmt::format("$Elements announces {} elements but its blocks hold {}", n_elements, total));
  lex.expect("$EndElements");
}

// Every section of the file, checked for order ($MeshFormat first, $Nodes before $Elements);
// sections the reader does not use are skipped.
struct RawFile {
  bool have_entities = false;
  std::map<EntityKey, std::string> names;
  std::map<EntityKey, std::vector<int>> physicals;
  RawNodes nodes;
  std::vector<RawBlock> blocks;
};

RawFile read_sections(MshLexer& lex) {
  RawFile f;
  bool have_format = false;
  while (const auto token = lex.try_next()) {
    const std::string_view header = *token;
    if (header.empty() || header.front() != '$') lex.fail(fmt::format("expected a section header, found '{}'", header));
    const std::string_view name = header.substr(1);
    if (!have_format && name != "MeshFormat") lex.fail("the file does not start with $MeshFormat (not a Gmsh mesh?)");
    if (name == "MeshFormat") {
      if (have_format) lex.fail("a second $MeshFormat section");
      read_mesh_format(lex);
      have_format = true;
    } else if (name == "PhysicalNames") {
      read_physical_names(lex, f.names);
    } else if (name == "Entities") {
      read_entities(lex, f.physicals);
      f.have_entities = true;
    } else if (name == "Nodes") {
      read_nodes(lex, f.nodes);
    } else if (name == "Elements") {
      if (f.nodes.tags.empty()) lex.fail("$Elements before $Nodes");
      read_elements(lex, f.blocks);
    } else {
      lex.skip_section(name);  // $PartitionedEntities, $Periodic, $NodeData, comments, ...
    }
  }
  if (!have_format) lex.fail(1, "empty file (not a Gmsh mesh?)");
  return f;
}

}  // namespace

GmshMesh read_gmsh_msh41(const std::filesystem::path& file, ElementType linear_hex) {
  if (topology(linear_hex).dimension != 3 || topology(linear_hex).quadratic())
    throw std::invalid_argument("read_gmsh_msh41: linear_hex must be a linear solid (hex8 or hex8i)");
  MshLexer lex(file);

  RawFile f = read_sections(lex);
  const auto& names = f.names;
  const auto& physicals = f.physicals;
  const RawNodes& nodes = f.nodes;
  const std::vector<RawBlock>& blocks = f.blocks;
  const bool have_entities = f.have_entities;

  int dim = 0;
  for (const RawBlock& b : blocks) dim = std::max(dim, b.entity_dim);
  if (dim < 2) lex.fail(1, "the file has no 2D or 3D elements");

  // Internal node indices: the nodes of the mesh elements, in the order of $Nodes.
  std::vector<int> internal(nodes.tags.size(), -1);
  auto node_position = [&](const RawElement& e, long tag) {
    const auto it = nodes.index.find(tag);
    if (it == nodes.index.end())
      lex.fail(e.line, fmt::format("element {} uses node {}, which is not defined in $Nodes", e.tag, tag));
    return it->second;
  };
  for (const RawBlock& b : blocks) {
    if (b.entity_dim != dim) continue;
    if (!mesh_element(b.type, dim, linear_hex))
      lex.fail(b.line,
               fmt::format(
                   "Gmsh element type {} is not supported in a {}D mesh (supported: {})", b.type, dim,
                   dim == 3 ? "5 = 8-node and 17 = 20-node hexahedra; for 20 nodes set Mesh.SecondOrderIncomplete = 1"
                            : "2 = 3-node triangles and 3 = 4-node quadrangles"));
    for (const RawElement& e : b.elements)
      for (long tag : e.nodes) internal[static_cast<size_t>(node_position(e, tag))] = 0;
  }
  GmshMesh out;
  Mesh& mesh = out.mesh;
  mesh.dim = dim;
  double extent = 0.0;
  for (size_t i = 0; i < nodes.tags.size(); ++i)
    if (internal[i] == 0) {
      internal[i] = mesh.n_nodes();
      mesh.node_ids.push_back(nodes.tags[i]);
      extent = std::max(extent, nodes.coords[i].cwiseAbs().maxCoeff());
    }
  mesh.coords.resize(mesh.n_nodes(), dim);
  for (size_t i = 0; i < nodes.tags.size(); ++i) {
    if (internal[i] < 0) continue;
    // A plane-stress mesh must be drawn in the plane z = 0; dropping z of a tilted or curved
    // surface mesh would silently change its geometry.
    if (dim == 2 && std::abs(nodes.coords[i].z()) > 1e-9 * std::max(extent, 1.0))
      lex.fail(nodes.lines[i], fmt::format("node {} of the 2D mesh has z = {}; a 2D mesh must lie in the plane z = 0",
                                           nodes.tags[i], nodes.coords[i].z()));
    mesh.coords.row(internal[i]) = nodes.coords[i].head(dim).transpose();
  }
  mesh.rebuild_index();

  // One block per element type, in order of first appearance.
  std::unordered_map<long, int> element_lines;  // tag -> line, to report duplicates
  for (const RawBlock& b : blocks) {
    if (b.entity_dim != dim) continue;
    const ElementType type = *mesh_element(b.type, dim, linear_hex);
    auto it = std::find_if(mesh.blocks.begin(), mesh.blocks.end(),
                           [type](const ElementBlock& eb) { return eb.type == type; });
    if (it == mesh.blocks.end()) {
      mesh.blocks.push_back(ElementBlock{type, {}, {}});
      it = std::prev(mesh.blocks.end());
    }
    ElementBlock& block = *it;
    const Eigen::Index first = block.conn.rows();
    block.conn.conservativeResize(first + static_cast<Eigen::Index>(b.elements.size()), nodes_per_element(type));
    for (size_t k = 0; k < b.elements.size(); ++k) {
      const RawElement& e = b.elements[k];
      if (const auto [it_line, fresh] = element_lines.emplace(e.tag, e.line); !fresh)
        lex.fail(e.line, fmt::format("element tag {} is used twice (also on line {})", e.tag, it_line->second));
      const Eigen::Index row = first + static_cast<Eigen::Index>(k);
      for (int a = 0; a < nodes_per_element(type); ++a) {
        const std::span<const int> order = topology(type).gmsh_order;
        const int gmsh_a = order.empty() ? a : order[static_cast<size_t>(a)];
        block.conn(row, a) = internal[static_cast<size_t>(node_position(e, e.nodes[static_cast<size_t>(gmsh_a)]))];
      }
      block.ids.push_back(e.tag);
    }
  }

  // Node groups from the physical groups of the elements' entities, any dimension.
  std::map<std::string, std::set<int>> groups;
  for (const RawBlock& b : blocks) {
    const auto entity = physicals.find({b.entity_dim, b.entity_tag});
    if (entity == physicals.end()) {
      if (have_entities)
        lex.fail(b.line, fmt::format("element block on {}D entity {}, which $Entities does not list", b.entity_dim,
                                     b.entity_tag));
      continue;
    }
    for (int physical : entity->second) {
      const auto named = names.find({b.entity_dim, physical});
      const std::string group = named != names.end() ? named->second : fmt::format("physical_{}", physical);
      std::set<int>& members = groups[group];
      for (const RawElement& e : b.elements)
        for (long tag : e.nodes) {
          const int n = internal[static_cast<size_t>(node_position(e, tag))];
          if (n < 0)
            lex.fail(e.line, fmt::format("node {} of physical group '{}' belongs to no {}D element of the mesh", tag,
                                         group, dim));
          members.insert(n);
        }
    }
  }
  for (auto& [group, members] : groups) out.node_groups[group] = std::vector<int>(members.begin(), members.end());
  return out;
}

}  // namespace bb
