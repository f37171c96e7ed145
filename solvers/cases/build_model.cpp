// CaseSpec -> Model: mesh generation or import, node-set resolution, BCs and loads.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "cases/case_spec.hpp"
#include "common/csv_reader.hpp"
#include "common/errors.hpp"

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
double signed_area(const Mesh& mesh, const std::array<int, 4>& c, int nn) {
  double twice = 0.0;
  for (int a = 0; a < nn; ++a) {
    const int p = c[a], q = c[(a + 1) % nn];
    twice += mesh.coords(p, 0) * mesh.coords(q, 1) - mesh.coords(q, 0) * mesh.coords(p, 1);
  }
  return 0.5 * twice;
}

Mesh read_csv_mesh(const MeshSpec& spec) {
  require_file(spec.nodes_csv, spec.at);
  require_file(spec.elements_csv, spec.at);
  Mesh mesh;
  mesh.dim = 2;
  std::vector<std::array<double, 2>> xy;
  std::unordered_set<long> seen;
  with_csv_errors(spec.nodes_csv, [&] {
    CsvReader<3> in(spec.nodes_csv.string());
    in.read_header(io::ignore_extra_column, "id", "x", "y");
    long id;
    double x, y;
    while (in.read_row(id, x, y)) {
      if (!std::isfinite(x) || !std::isfinite(y))
        throw InputError(fmt::format("{}:{}: node {} has a non-finite coordinate", spec.nodes_csv.string(), in.get_file_line(), id));
      if (!seen.insert(id).second)
        throw InputError(fmt::format("{}:{}: duplicate node id {}", spec.nodes_csv.string(), in.get_file_line(), id));
      mesh.node_ids.push_back(id);
      xy.push_back({x, y});
    }
  });
  if (mesh.node_ids.empty()) throw InputError(fmt::format("{}: the mesh has no nodes", spec.nodes_csv.string()));
  mesh.coords.resize(static_cast<Eigen::Index>(xy.size()), 2);
  for (size_t i = 0; i < xy.size(); ++i) mesh.coords.row(static_cast<Eigen::Index>(i)) << xy[i][0], xy[i][1];
  mesh.rebuild_index();

  ElementBlock block;
  block.type = spec.element;
  const int nn = nodes_per_element(spec.element);
  std::vector<std::array<int, 4>> conn;
  std::unordered_set<long> seen_elements;
  auto add = [&](long id, const std::array<long, 4>& ids, unsigned line) {
    if (!seen_elements.insert(id).second)
      throw InputError(fmt::format("{}:{}: duplicate element id {}", spec.elements_csv.string(), line, id));
    std::array<int, 4> c{-1, -1, -1, -1};
    for (int a = 0; a < nn; ++a) {
      c[a] = mesh.index_of(ids[a]);
      if (c[a] < 0)
        throw InputError(fmt::format("{}:{}: element {} uses node {}, which is not in {}", spec.elements_csv.string(),
                                     line, id, ids[a], spec.nodes_csv.filename().string()));
    }
    if (signed_area(mesh, c, nn) <= 0.0)
      throw InputError(fmt::format("{}:{}: element {} is inverted or degenerate (list its nodes counterclockwise)",
                                   spec.elements_csv.string(), line, id));
    block.ids.push_back(id);
    conn.push_back(c);
  };
  with_csv_errors(spec.elements_csv, [&] {
    long id;
    std::array<long, 4> n{};
    if (nn == 4) {
      CsvReader<5> in(spec.elements_csv.string());
      in.read_header(io::ignore_extra_column, "id", "n1", "n2", "n3", "n4");
      while (in.read_row(id, n[0], n[1], n[2], n[3])) add(id, n, in.get_file_line());
    } else {
      CsvReader<4> in(spec.elements_csv.string());
      in.read_header(io::ignore_extra_column, "id", "n1", "n2", "n3");
      if (header_has_column(spec.elements_csv, "n4"))
        throw InputError(fmt::format("{}: column 'n4' found, but element \"{}\" takes 3 nodes (check mesh.element)",
                                     spec.elements_csv.string(), element_name(spec.element)));
      while (in.read_row(id, n[0], n[1], n[2])) add(id, n, in.get_file_line());
    }
  });
  if (conn.empty()) throw InputError(fmt::format("{}: the mesh has no elements", spec.elements_csv.string()));
  block.conn.resize(static_cast<Eigen::Index>(conn.size()), nn);
  for (size_t e = 0; e < conn.size(); ++e)
    for (int a = 0; a < nn; ++a) block.conn(static_cast<Eigen::Index>(e), a) = conn[e][a];
  mesh.blocks.push_back(std::move(block));
  return mesh;
}

}  // namespace

std::vector<int> select_nodes(const Mesh& mesh, const NodeSetSpec& set) {
  std::vector<int> nodes;
  if (!set.ids.empty()) {
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
  if (spec.mesh.kind == MeshSpec::Kind::csv) {
    model.mesh = read_csv_mesh(spec.mesh);
  } else {
    model.mesh = generate_mapped_quad(spec.mesh.mapped);
  }
  model.section = spec.section;
  for (const NodeSetSpec& s : spec.sets) model.node_sets[s.name] = select_nodes(model.mesh, s);
  auto require_set = [&](const std::string& name, const SourceLocation& at) {
    if (!model.node_sets.count(name)) throw InputError(fmt::format("{}: unknown node set '{}'", at.where(), name));
  };
  for (const ConstraintSpec& c : spec.constraints) {
    require_set(c.constraint.set, c.at);
    for (Direction d : c.constraint.directions)
      if (d >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", c.at.where()));
    model.constraints.push_back(c.constraint);
  }
  for (const LoadSpec& l : spec.loads) {
    require_set(l.load.set, l.at);
    if (l.load.direction >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", l.at.where()));
    model.loads.push_back(l.load);
  }
  return model;
}

}  // namespace bb
