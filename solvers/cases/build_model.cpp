// CaseSpec -> Model: mesh generation or import, node-set resolution, BCs and loads.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <tuple>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "cases/case_spec.hpp"
#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "mesh/gmsh_import.hpp"
#include "mesh/hex_block.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

void require_file(const fs::path& file, const SourceLocation& at) {
  if (!fs::is_regular_file(file)) throw InputError(fmt::format("{}: file not found: {}", at.where(), file.string()));
}

template <typename Fn>
void with_csv_errors(const fs::path& file, Fn fn) {
  try {
    fn();
  } catch (const io::error::base& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
}

// fccp's has_column() only knows the requested columns, so the header is read here.
bool header_has_column(const fs::path& file, const std::string& column) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      const auto first = cell.find_first_not_of(" \t\r"), last = cell.find_last_not_of(" \t\r");
      if (first != std::string::npos && cell.substr(first, last - first + 1) == column) return true;
    }
    return false;
  }
  return false;
}

// Shoelace area of the element polygon; <= 0 means clockwise or degenerate.
double signed_area(const Mesh& mesh, const int* c, int nn) {
  double twice = 0.0;
  for (int a = 0; a < nn; ++a) {
    const int p = c[a], q = c[(a + 1) % nn];
    twice += mesh.coords(p, 0) * mesh.coords(q, 1) - mesh.coords(q, 0) * mesh.coords(p, 1);
  }
  return 0.5 * twice;
}

// Reads `N` columns named by `names` into an array per row; fn(row, line) for each row.
template <unsigned N, typename Fn>
void read_columns(const fs::path& file, const std::array<std::string, N>& names, Fn fn) {
  with_csv_errors(file, [&] {
    CsvReader<N> in(file.string());
    std::apply([&](const auto&... n) { in.read_header(io::ignore_extra_column, n...); }, names);
    std::array<std::string, N> row;
    while (std::apply([&](auto&... v) { return in.read_row(v...); }, row)) fn(row, in.get_file_line());
  });
}

template <typename T>
T parse_cell(const std::string& text, const fs::path& file, unsigned line, const char* what) {
  T v{};
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size())
    throw InputError(fmt::format("{}:{}: '{}' is not a valid {}", file.string(), line, text, what));
  return v;
}

template <unsigned N>
std::array<std::string, N> node_columns(const char* prefix) {
  std::array<std::string, N> names;
  names[0] = "id";
  for (unsigned i = 1; i < N; ++i) names[i] = fmt::format("{}{}", prefix, i);
  return names;
}

template <unsigned NN>
void read_elements(const MeshSpec& spec, Mesh& mesh, ElementBlock& block) {
  std::unordered_set<long> seen;
  std::vector<std::array<int, NN>> conn;
  read_columns<NN + 1>(spec.elements_csv, node_columns<NN + 1>("n"), [&](const auto& row, unsigned line) {
    const long id = parse_cell<long>(row[0], spec.elements_csv, line, "element id");
    if (!seen.insert(id).second) throw InputError(fmt::format("{}:{}: duplicate element id {}", spec.elements_csv.string(), line, id));
    std::array<int, NN> c{};
    for (unsigned a = 0; a < NN; ++a) {
      const long node = parse_cell<long>(row[a + 1], spec.elements_csv, line, "node id");
      c[a] = mesh.index_of(node);
      if (c[a] < 0)
        throw InputError(fmt::format("{}:{}: element {} uses node {}, which is not in {}", spec.elements_csv.string(),
                                     line, id, node, spec.nodes_csv.filename().string()));
    }
    if (mesh.dim == 2 && signed_area(mesh, c.data(), static_cast<int>(NN)) <= 0.0)
      throw InputError(fmt::format("{}:{}: element {} is inverted or degenerate (list its nodes counterclockwise)",
                                   spec.elements_csv.string(), line, id));
    block.ids.push_back(id);
    conn.push_back(c);
  });
  if (conn.empty()) throw InputError(fmt::format("{}: the mesh has no elements", spec.elements_csv.string()));
  block.conn.resize(static_cast<Eigen::Index>(conn.size()), NN);
  for (size_t e = 0; e < conn.size(); ++e)
    for (unsigned a = 0; a < NN; ++a) block.conn(static_cast<Eigen::Index>(e), a) = conn[e][a];
}

Mesh read_csv_mesh(const MeshSpec& spec) {
  require_file(spec.nodes_csv, spec.at);
  require_file(spec.elements_csv, spec.at);
  Mesh mesh;
  mesh.dim = spec.dim();
  std::vector<Eigen::Vector3d> xyz;
  std::unordered_set<long> seen;
  auto add_node = [&](const std::string& id_text, const std::array<double, 3>& p, unsigned line) {
    const long id = parse_cell<long>(id_text, spec.nodes_csv, line, "node id");
    for (double c : p)
      if (!std::isfinite(c)) throw InputError(fmt::format("{}:{}: node {} has a non-finite coordinate", spec.nodes_csv.string(), line, id));
    if (!seen.insert(id).second) throw InputError(fmt::format("{}:{}: duplicate node id {}", spec.nodes_csv.string(), line, id));
    mesh.node_ids.push_back(id);
    xyz.emplace_back(p[0], p[1], p[2]);
  };
  if (mesh.dim == 2) {
    read_columns<3>(spec.nodes_csv, {"id", "x", "y"}, [&](const auto& row, unsigned line) {
      add_node(row[0], {parse_cell<double>(row[1], spec.nodes_csv, line, "coordinate"),
                        parse_cell<double>(row[2], spec.nodes_csv, line, "coordinate"), 0.0}, line);
    });
  } else {
    read_columns<4>(spec.nodes_csv, {"id", "x", "y", "z"}, [&](const auto& row, unsigned line) {
      add_node(row[0], {parse_cell<double>(row[1], spec.nodes_csv, line, "coordinate"),
                        parse_cell<double>(row[2], spec.nodes_csv, line, "coordinate"),
                        parse_cell<double>(row[3], spec.nodes_csv, line, "coordinate")}, line);
    });
  }
  if (mesh.node_ids.empty()) throw InputError(fmt::format("{}: the mesh has no nodes", spec.nodes_csv.string()));
  mesh.coords.resize(static_cast<Eigen::Index>(xyz.size()), mesh.dim);
  for (size_t i = 0; i < xyz.size(); ++i) mesh.coords.row(static_cast<Eigen::Index>(i)) = xyz[i].head(mesh.dim).transpose();
  mesh.rebuild_index();

  const int nn = nodes_per_element(spec.element);
  const std::string extra = fmt::format("n{}", nn + 1);
  if (header_has_column(spec.elements_csv, extra))
    throw InputError(fmt::format("{}: column '{}' found, but element \"{}\" takes {} nodes (check mesh.element)",
                                 spec.elements_csv.string(), extra, element_name(spec.element), nn));
  ElementBlock block;
  block.type = spec.element;
  switch (nn) {
    case 3: read_elements<3>(spec, mesh, block); break;
    case 4: read_elements<4>(spec, mesh, block); break;
    case 8: read_elements<8>(spec, mesh, block); break;
    case 20: read_elements<20>(spec, mesh, block); break;
    default: throw InputError("unsupported element for CSV meshes");
  }
  mesh.blocks.push_back(std::move(block));
  return mesh;
}

// Merged mesh of the two-blade article and the node sets it defines itself (the names of
// two_blade_set_names()): every master point must be a node, since the thesis's reduced
// models and forces sit on nodes.
Mesh build_two_blade(const MeshSpec& spec, std::map<std::string, std::vector<int>>& sets) {
  const TwoBladeArticle article = two_blade_article(spec.two_blade, spec.element);
  Mesh mesh;
  try {
    std::vector<Mesh> parts;
    for (const HexBlockSpec& b : article.blocks) parts.push_back(generate_hex_block(b));
    mesh = merge_meshes(parts, spec.merge_tolerance);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("{}: two_blade mesh: {}", spec.at.where(), e.what()));
  }
  constexpr double kOnNode = 1e-6;  // [m] farther than this, the point has no node
  for (const auto& [name, point] : article.points) {
    int best = -1;
    double best_distance = INFINITY;
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      const double distance = (mesh.coords.row(n).transpose() - point).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = n;
      }
    }
    if (best_distance > kOnNode)
      throw InputError(fmt::format("{}: two_blade mesh: point {} ({:.6g}, {:.6g}, {:.6g}) has no node (nearest {:.3g} m away)",
                                   spec.at.where(), name, point.x(), point.y(), point.z(), best_distance));
    sets[name] = {best};
  }
  constexpr double kOnFace = 1e-9;  // [m]
  auto select = [&](const std::string& name, auto&& on) {
    std::vector<int>& nodes = sets[name];
    for (int n = 0; n < mesh.n_nodes(); ++n)
      if (on(mesh.coords(n, 0), mesh.coords(n, 1))) nodes.push_back(n);
    if (nodes.empty()) throw InputError(fmt::format("{}: two_blade mesh: set '{}' matches no node", spec.at.where(), name));
  };
  select("fixture_base", [&](double, double y) { return std::abs(y - article.fixture_base_y) <= kOnFace; });
  select("fixture_left", [&](double x, double) { return std::abs(x - article.fixture_left_x) <= kOnFace; });
  select("fixture_right", [&](double x, double) { return std::abs(x - article.fixture_right_x) <= kOnFace; });
  for (size_t b = 0; b < 2; ++b) {
    const TipFace& tip = article.tips[b];
    select(fmt::format("tip{}", b + 1), [&](double x, double y) {
      return std::abs(y - tip.y) <= kOnFace && x >= tip.x_min - kOnFace && x <= tip.x_max + kOnFace;
    });
  }
  return mesh;
}

}  // namespace

std::vector<int> select_nodes(const Mesh& mesh, const NodeSetSpec& set, const NodeGroups* groups) {
  std::vector<int> nodes;
  if (!set.group.empty()) {
    auto it = groups ? groups->find(set.group) : NodeGroups::const_iterator{};
    if (!groups || it == groups->end()) {
      std::string known;
      if (groups)
        for (const auto& [name, members] : *groups) known += (known.empty() ? "" : ", ") + name;
      throw InputError(fmt::format("{}: node set '{}': the mesh has no physical group '{}'{}", set.at.where(), set.name,
                                   set.group, known.empty() ? "" : " (groups: " + known + ")"));
    }
    nodes = it->second;
  } else if (!set.ids.empty()) {
    for (long id : set.ids) {
      const int n = mesh.index_of(id);
      if (n < 0) throw InputError(fmt::format("{}: node set '{}' names node {}, which is not in the mesh", set.at.where(), set.name, id));
      nodes.push_back(n);
    }
  } else {
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      bool match = true;
      for (int a = 0; a < 3 && match; ++a) {
        const double c = a < mesh.dim ? mesh.coords(n, a) : 0.0;
        if (set.equals[a] && std::abs(c - *set.equals[a]) > set.tol) match = false;
        if (set.range[a] && (c < set.range[a]->first - set.tol || c > set.range[a]->second + set.tol)) match = false;
      }
      if (match) nodes.push_back(n);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.empty()) throw InputError(fmt::format("{}: node set '{}' matches no node", set.at.where(), set.name));
  return nodes;
}

Model build_model(const CaseSpec& spec) {
  Model model;
  NodeGroups groups;
  switch (spec.mesh.kind) {
    case MeshSpec::Kind::csv: model.mesh = read_csv_mesh(spec.mesh); break;
    case MeshSpec::Kind::mapped_quad: model.mesh = generate_mapped_quad(spec.mesh.mapped); break;
    case MeshSpec::Kind::hex_blocks: {
      std::vector<Mesh> parts;
      for (const HexBlockSpec& b : spec.mesh.blocks) parts.push_back(generate_hex_block(b));
      model.mesh = parts.size() == 1 ? std::move(parts.front()) : merge_meshes(parts, spec.mesh.merge_tolerance);
      break;
    }
    case MeshSpec::Kind::two_blade: model.mesh = build_two_blade(spec.mesh, model.node_sets); break;
    case MeshSpec::Kind::none: return model;  // the analysis brings its own matrices
    case MeshSpec::Kind::gmsh: {
      require_file(spec.mesh.gmsh_file, spec.mesh.at);
      const ElementType linear = spec.mesh.element == ElementType::hex20 ? ElementType::hex8 : spec.mesh.element;
      GmshMesh g = read_gmsh_msh41(spec.mesh.gmsh_file, linear);
      for (const auto& b : g.mesh.blocks)
        if (b.type != spec.mesh.element)
          throw InputError(fmt::format("{}: the Gmsh file holds {} elements, the case says mesh.element = \"{}\"",
                                       spec.mesh.at.where(), element_name(b.type), element_name(spec.mesh.element)));
      model.mesh = std::move(g.mesh);
      groups = std::move(g.node_groups);
      break;
    }
  }
  model.section = spec.section;
  for (const NodeSetSpec& s : spec.sets) model.node_sets[s.name] = select_nodes(model.mesh, s, &groups);
  auto require_set = [&](const std::string& name, const SourceLocation& at) {
    if (!model.node_sets.count(name)) throw InputError(fmt::format("{}: unknown node set '{}'", at.where(), name));
  };
  for (const ConstraintSpec& c : spec.constraints) {
    require_set(c.constraint.set, c.at);
    for (Direction d : c.constraint.directions)
      if (d >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", c.at.where()));
    model.constraints.push_back(c.constraint);
  }
  if (const auto& pairs = spec.analysis.pairs) {
    if (model.mesh.dim != 3) throw InputError(fmt::format("{}: [analysis.pairs] needs a solid (3D) mesh", spec.analysis.pairs_at.where()));
    for (const std::string* name : {&pairs->left, &pairs->right, &pairs->left_tip, &pairs->right_tip})
      require_set(*name, spec.analysis.pairs_at);
    for (const std::string* name : {&pairs->left, &pairs->right})
      if (model.node_sets.at(*name).size() != 1)
        throw InputError(fmt::format("{}: [analysis.pairs]: set '{}' must hold exactly one node, it holds {}",
                                     spec.analysis.pairs_at.where(), *name, model.node_sets.at(*name).size()));
  }
  for (const LoadSpec& l : spec.loads) {
    require_set(l.load.set, l.at);
    if (l.load.direction >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", l.at.where()));
    model.loads.push_back(l.load);
  }
  return model;
}

}  // namespace bb
