#include "mesh/csv_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <tuple>
#include <unordered_set>
#include <vector>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

template <typename Fn>
void with_csv_errors(const fs::path& file, Fn fn) {
  try {
    fn();
  } catch (const io::error::base& e) {
    throw InputError(fmt::format("{}: {}", file.string(), e.what()));
  }
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
  require_readable_file(file);
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
void read_elements(const fs::path& nodes_csv, const fs::path& elements_csv, Mesh& mesh, ElementBlock& block) {
  std::unordered_set<long> seen;
  std::vector<std::array<int, NN>> conn;
  read_columns<NN + 1>(elements_csv, node_columns<NN + 1>("n"), [&](const auto& row, unsigned line) {
    const long id = parse_cell<long>(row[0], elements_csv, line, "element id");
    if (!seen.insert(id).second)
      throw InputError(fmt::format("{}:{}: duplicate element id {}", elements_csv.string(), line, id));
    std::array<int, NN> c{};
    for (unsigned a = 0; a < NN; ++a) {
      const long node = parse_cell<long>(row[a + 1], elements_csv, line, "node id");
      c[a] = mesh.index_of(node);
      if (c[a] < 0)
        throw InputError(fmt::format("{}:{}: element {} uses node {}, which is not in {}", elements_csv.string(), line,
                                     id, node, nodes_csv.filename().string()));
    }
    if (mesh.dim == 2 && signed_area(mesh, c.data(), static_cast<int>(NN)) <= 0.0)
      throw InputError(fmt::format("{}:{}: element {} is inverted or degenerate (list its nodes counterclockwise)",
                                   elements_csv.string(), line, id));
    block.ids.push_back(id);
    conn.push_back(c);
  });
  if (conn.empty()) throw InputError(fmt::format("{}: the mesh has no elements", elements_csv.string()));
  block.conn.resize(static_cast<Eigen::Index>(conn.size()), NN);
  for (size_t e = 0; e < conn.size(); ++e)
    for (unsigned a = 0; a < NN; ++a) block.conn(static_cast<Eigen::Index>(e), a) = conn[e][a];
}

}  // namespace

Mesh read_csv_mesh(const fs::path& nodes_csv, const fs::path& elements_csv, ElementType element) {
  Mesh mesh;
  mesh.dim = element_dimension(element);
  std::vector<Eigen::Vector3d> xyz;
  std::unordered_set<long> seen;
  auto add_node = [&](const std::string& id_text, const std::array<double, 3>& p, unsigned line) {
    const long id = parse_cell<long>(id_text, nodes_csv, line, "node id");
    for (double c : p)
      if (!std::isfinite(c))
        throw InputError(fmt::format("{}:{}: node {} has a non-finite coordinate", nodes_csv.string(), line, id));
    if (!seen.insert(id).second)
      throw InputError(fmt::format("{}:{}: duplicate node id {}", nodes_csv.string(), line, id));
    mesh.node_ids.push_back(id);
    xyz.emplace_back(p[0], p[1], p[2]);
  };
  if (mesh.dim == 2) {
    read_columns<3>(nodes_csv, {"id", "x", "y"}, [&](const auto& row, unsigned line) {
      add_node(row[0],
               {parse_cell<double>(row[1], nodes_csv, line, "coordinate"),
                parse_cell<double>(row[2], nodes_csv, line, "coordinate"), 0.0},
               line);
    });
  } else {
    read_columns<4>(nodes_csv, {"id", "x", "y", "z"}, [&](const auto& row, unsigned line) {
      add_node(row[0],
               {parse_cell<double>(row[1], nodes_csv, line, "coordinate"),
                parse_cell<double>(row[2], nodes_csv, line, "coordinate"),
                parse_cell<double>(row[3], nodes_csv, line, "coordinate")},
               line);
    });
  }
  if (mesh.node_ids.empty()) throw InputError(fmt::format("{}: the mesh has no nodes", nodes_csv.string()));
  mesh.coords.resize(static_cast<Eigen::Index>(xyz.size()), mesh.dim);
  for (size_t i = 0; i < xyz.size(); ++i)
    mesh.coords.row(static_cast<Eigen::Index>(i)) = xyz[i].head(mesh.dim).transpose();
  mesh.rebuild_index();

  const int nn = nodes_per_element(element);
  const std::string extra = fmt::format("n{}", nn + 1);
  if (const auto header = read_csv_header(elements_csv); std::find(header.begin(), header.end(), extra) != header.end())
    throw InputError(fmt::format("{}: column '{}' found, but element \"{}\" takes {} nodes (check mesh.element)",
                                 elements_csv.string(), extra, element_name(element), nn));
  ElementBlock block;
  block.type = element;
  switch (nn) {
    case 3:
      read_elements<3>(nodes_csv, elements_csv, mesh, block);
      break;
    case 4:
      read_elements<4>(nodes_csv, elements_csv, mesh, block);
      break;
    case 8:
      read_elements<8>(nodes_csv, elements_csv, mesh, block);
      break;
    case 20:
      read_elements<20>(nodes_csv, elements_csv, mesh, block);
      break;
    default:
      throw InputError("unsupported element for CSV meshes");
  }
  mesh.blocks.push_back(std::move(block));
  return mesh;
}

}  // namespace bb
