#include "report/plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <vector>

#include "mesh/boundary.hpp"
#include "mesh/element_topology.hpp"
#include "report/gnuplot.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Above this many elements only the boundary is drawn: every edge would bloat the SVG to megabytes.
constexpr int kMaxDrawnElements = 2000;

void write_boundary(std::ofstream& out, const Mesh& mesh, const Eigen::MatrixXd& xy) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& b : mesh.blocks)
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (const auto& [i, j] : topology(b.type).edges) {
        const int p = b.conn(e, i), q = b.conn(e, j);
        ++uses[{std::min(p, q), std::max(p, q)}];
      }
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    out << xy(edge.first, 0) << ' ' << xy(edge.first, 1) << '\n'
        << xy(edge.second, 0) << ' ' << xy(edge.second, 1) << "\n\n";
  }
}

void write_edges(std::ofstream& out, const Mesh& mesh, const Eigen::MatrixXd& xy) {
  if (mesh.n_elements() > kMaxDrawnElements) {
    write_boundary(out, mesh, xy);
    return;
  }
  for (const auto& b : mesh.blocks) {
    const int nn = nodes_per_element(b.type);
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      for (int a = 0; a <= nn; ++a) {
        const int n = b.conn(e, a % nn);
        out << xy(n, 0) << ' ' << xy(n, 1) << '\n';
      }
      out << "\n";
    }
  }
}

}  // namespace

namespace {

// Corner-node faces of every solid element that no other element shares (the skin).
std::vector<std::array<int, 4>> boundary_faces(const Mesh& mesh) {
  std::vector<std::array<int, 4>> out;
  for (const Facet& f : boundary_facets(mesh)) out.push_back({f.nodes[0], f.nodes[1], f.nodes[2], f.nodes[3]});
  return out;
}

// Edges of the skin faces that face `axis` (+x, +y or +z) and belong to only one such face: the
// outline of the solid seen from that side, bodies and openings included, with no interior lines.
std::vector<std::pair<int, int>> facing_outline(const Mesh& mesh, const std::vector<std::array<int, 4>>& faces,
                                                int axis) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : faces) {
    const Eigen::Vector3d d1 = mesh.coords.row(f[2]) - mesh.coords.row(f[0]);
    const Eigen::Vector3d d2 = mesh.coords.row(f[3]) - mesh.coords.row(f[1]);
    const Eigen::Vector3d n = d1.cross(d2);
    if (n[axis] <= 0.5 * n.norm()) continue;
    for (int a = 0; a < 4; ++a) ++uses[{std::min(f[a], f[(a + 1) % 4]), std::max(f[a], f[(a + 1) % 4])}];
  }
  std::vector<std::pair<int, int>> out;
  for (const auto& [edge, count] : uses)
    if (count == 1) out.push_back(edge);
  return out;
}

// Two views of the solid's outline: front (x-y, seen from +z) and side (z-y, seen from +x).
Plot plot_deformed_solid(const Mesh& mesh, const Eigen::MatrixXd& displacements, const fs::path& out_dir,
                         const std::string& stem, const std::string& title) {
  const auto faces = boundary_faces(mesh);
  const double size = (mesh.coords.colwise().maxCoeff() - mesh.coords.colwise().minCoeff()).norm();
  const double umax = displacements.rowwise().norm().maxCoeff();
  const double scale = umax > 0 ? 0.1 * size / umax : 1.0;
  const Eigen::MatrixXd deformed = mesh.coords + scale * displacements;
  const std::array<std::array<int, 3>, 2> views{{{2, 0, 1}, {0, 2, 1}}};  // facing axis, horizontal, vertical
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (const auto& v : views) {
      const auto edges = facing_outline(mesh, faces, v[0]);
      for (const Eigen::MatrixXd* xyz : {&mesh.coords, &deformed}) {
        for (const auto& [p, q] : edges)
          out << (*xyz)(p, v[1]) << ' ' << (*xyz)(p, v[2]) << '\n'
              << (*xyz)(q, v[1]) << ' ' << (*xyz)(q, v[2]) << "\n\n";
        out << "\n";
      }
    }
  }
  const std::string script = fmt::format(
      "set multiplot layout 1,2 title '{} (displacements x {:.3g})'\nset size ratio -1\nset key off\n"
      "set title 'front (x-y)'\nset xlabel 'x [m]'\nset ylabel 'y [m]'\n"
      "plot '{}.dat' index 0 with lines lc rgb '#bbbbbb', '{}.dat' index 1 with lines lc rgb '#1f5fbf'\n"
      "set title 'side (z-y)'\nset xlabel 'z [m]'\nset xtics rotate by 90 right\n"
      "plot '{}.dat' index 2 with lines lc rgb '#bbbbbb', '{}.dat' index 3 with lines lc rgb '#1f5fbf'\n"
      "unset multiplot\n",
      gnuplot_quote(title), scale, stem, stem, stem, stem);
  return draw(out_dir, stem, title, script);
}

}  // namespace

Plot plot_deformed_mesh(const Mesh& mesh, const Eigen::MatrixXd& displacements, const fs::path& out_dir,
                        const std::string& stem, const std::string& title) {
  if (mesh.dim == 3) return plot_deformed_solid(mesh, displacements, out_dir, stem, title);
  const Eigen::MatrixXd xy = mesh.coords.leftCols(2);
  const double size = (xy.colwise().maxCoeff() - xy.colwise().minCoeff()).norm();
  const double umax = displacements.leftCols(2).rowwise().norm().maxCoeff();
  const double scale = umax > 0 ? 0.1 * size / umax : 1.0;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    write_edges(out, mesh, xy);
    out << "\n";
    write_edges(out, mesh, xy + scale * displacements.leftCols(2));
  }
  const std::string script = fmt::format(
      "set title '{} (displacements x {:.3g})'\nset size ratio -1\nset xlabel 'x [m]'\nset ylabel 'y [m]'\n"
      "set key outside right\nplot '{}.dat' index 0 with lines lc rgb '#999999' dt 2 title 'undeformed', \\\n"
      "     '{}.dat' index 1 with lines lc rgb '#1f5fbf' lw 1.5 title 'deformed'\n",
      gnuplot_quote(title), scale, stem, stem);
  return draw(out_dir, stem, title, script);
}

Plot plot_check(const std::vector<CheckEntry>& entries, const std::string& group, const fs::path& out_dir,
                const std::string& stem) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# index computed reference tolerance\n";
    int i = 0;
    for (const CheckEntry& e : entries)
      if (e.group == group) out << ++i << ' ' << e.computed << ' ' << e.reference << ' ' << e.tolerance << '\n';
  }
  const std::string title = "Check: " + group;
  const std::string script = fmt::format(
      "set title '{}'\nset xlabel 'entry (order of the report table)'\nset ylabel 'value'\nset key outside right\n"
      "set grid\nplot '{}.dat' using 1:3:4 with yerrorbars lc rgb '#999999' title 'reference +- tolerance', \\\n"
      "     '{}.dat' using 1:2 with points pt 7 ps 0.6 lc rgb '#1f5fbf' title 'computed'\n",
      gnuplot_quote(title), stem, stem);
  return draw(out_dir, stem, title, script);
}

Plot plot_refinement_error(const RefinementResult& study, const fs::path& out_dir, const std::string& stem) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# free_dofs |error vs Timoshenko| |error vs Richardson limit|\n";
    for (const RefinementRow& r : study.rows)
      out << r.n_free_dofs << ' ' << std::abs(r.error_vs_beam) << ' ' << std::abs(r.error_vs_limit) << '\n';
  }
  const std::string title = "Tip deflection error vs DOFs";
  const std::string script = fmt::format(
      "set title '{}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'free DOFs'\n"
      "set ylabel 'relative error'\nset grid\nset key outside right\n"
      "plot '{}.dat' using 1:2 with linespoints pt 7 lc rgb '#bf1f1f' title 'vs Timoshenko beam', \\\n"
      "     '{}.dat' using 1:($3 > 0 ? $3 : 1/0) with linespoints pt 5 lc rgb '#1f5fbf' title 'vs Richardson limit'\n",
      title, stem, stem);
  return draw(out_dir, stem, title, script);
}

Plot plot_refinement_cost(const RefinementResult& study, const fs::path& out_dir, const std::string& stem) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# free_dofs assembly_s solve_s\n";
    for (const RefinementRow& r : study.rows)
      out << r.n_free_dofs << ' ' << std::max(r.assembly_seconds, 1e-6) << ' ' << std::max(r.solve_seconds, 1e-6)
          << '\n';
  }
  const std::string title = "Cost vs DOFs";
  const std::string script = fmt::format(
      "set title '{}'\nset logscale xy\nset xlabel 'free DOFs'\nset ylabel 'wall time [s]'\nset grid\n"
      "set key outside right\nplot '{}.dat' using 1:2 with linespoints pt 7 title 'assembly', \\\n"
      "     '{}.dat' using 1:3 with linespoints pt 5 title 'factorization + solve'\n",
      title, stem, stem);
  return draw(out_dir, stem, title, script);
}

Plot plot_modal_refinement(const ModalRefinementResult& study, const fs::path& out_dir, const std::string& stem) {
  std::vector<ElementType> elements;
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    for (const ModalRefinementRow& r : study.rows) {
      if (elements.empty() || elements.back() != r.element) {
        if (!elements.empty()) out << "\n\n";
        elements.push_back(r.element);
        out << "# " << element_name(r.element) << ": free_dofs max_error eigensolve_s\n";
      }
      if (r.max_error > 0) out << r.n_free_dofs << ' ' << r.max_error << ' ' << r.solve_seconds << '\n';
    }
  }
  std::string plot = "plot ";
  for (size_t i = 0; i < elements.size(); ++i)
    plot += fmt::format("{}'{}.dat' index {} using 1:2 with linespoints pt 7 title '{}'", i ? ", " : "", stem, i,
                        element_name(elements[i]));
  const std::string title = "First-frequency error vs DOFs";
  const std::string script = fmt::format(
      "set title '{}'\nset logscale xy\nset format y '10^{{%L}}'\nset xlabel 'free DOFs'\n"
      "set ylabel 'max relative error (vs finest hex20)'\nset grid\nset key outside right\n{}\n",
      title, plot);
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
