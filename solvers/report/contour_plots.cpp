#include "report/contour_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "mesh/boundary.hpp"
#include "mesh/element_topology.hpp"
#include "report/gnuplot.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// Sub-cells drawn in all: enough for smooth colours on small meshes, a few MB of SVG at most.
constexpr double kMaxCells = 6000.0;

// One pm3d patch: two scan lines of two points (x y z value); gnuplot colours it by the mean. All
// patches form one data set: a scan of undefined points between two patches keeps pm3d from
// bridging them (it skips a quadrangle with an undefined corner), and one data set is one SVG group.
void patch(std::ofstream& out, const Eigen::Vector4d& p00, const Eigen::Vector4d& p10, const Eigen::Vector4d& p01,
           const Eigen::Vector4d& p11) {
  out << p00[0] << ' ' << p00[1] << ' ' << p00[2] << ' ' << p00[3] << '\n'
      << p10[0] << ' ' << p10[1] << ' ' << p10[2] << ' ' << p10[3] << "\n\n"
      << p01[0] << ' ' << p01[1] << ' ' << p01[2] << ' ' << p01[3] << '\n'
      << p11[0] << ' ' << p11[1] << ' ' << p11[2] << ' ' << p11[3] << "\n\n"
      << "NaN NaN NaN NaN\nNaN NaN NaN NaN\n\n";
}

// (x, y, 0, value) of an element at natural coordinates: bilinear on a q4, linear on a triangle.
Eigen::Vector4d plane_point(const Mesh& mesh, const Eigen::VectorXd& values, const int* nodes, bool quad, double r,
                            double s) {
  Eigen::Vector4d n = Eigen::Vector4d::Zero();
  if (quad)
    n << 0.25 * (1 - r) * (1 - s), 0.25 * (1 + r) * (1 - s), 0.25 * (1 + r) * (1 + s), 0.25 * (1 - r) * (1 + s);
  else
    n << 1 - r - s, r, s, 0;
  Eigen::Vector4d p = Eigen::Vector4d::Zero();
  for (int a = 0; a < (quad ? 4 : 3); ++a) {
    p[0] += n[a] * mesh.coords(nodes[a], 0);
    p[1] += n[a] * mesh.coords(nodes[a], 1);
    p[3] += n[a] * values[nodes[a]];
  }
  return p;
}

void write_plane(std::ofstream& out, const Mesh& mesh, const Eigen::VectorXd& values) {
  const int k = std::clamp(static_cast<int>(std::sqrt(kMaxCells / std::max(1, mesh.n_elements()))), 1, 6);
  for (const ElementBlock& b : mesh.blocks) {
    const bool quad = topology(b.type).corners == 4;
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      const int* nodes = b.conn.row(e).data();
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          if (quad) {
            auto at = [&](int a, int c) {
              return plane_point(mesh, values, nodes, true, -1.0 + 2.0 * a / k, -1.0 + 2.0 * c / k);
            };
            patch(out, at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
          } else if (i + j < k) {
            // The barycentric grid's two triangles in the cell (i, j), each a patch with a repeated corner.
            auto at = [&](int a, int c) {
              return plane_point(mesh, values, nodes, false, static_cast<double>(a) / k, static_cast<double>(c) / k);
            };
            patch(out, at(i, j), at(i + 1, j), at(i, j + 1), at(i, j + 1));
            if (i + j + 1 < k) patch(out, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), at(i, j + 1));
          }
        }
    }
  }
}

void write_skin(std::ofstream& out, const Mesh& mesh, const Eigen::VectorXd& values) {
  auto corner = [&](int n) {
    return Eigen::Vector4d(mesh.coords(n, 0), mesh.coords(n, 1), mesh.coords(n, 2), values[n]);
  };
  for (const Facet& f : boundary_facets(mesh))
    patch(out, corner(f.nodes[0]), corner(f.nodes[1]), corner(f.nodes[3]), corner(f.nodes[2]));
}

}  // namespace

Plot plot_nodal_contour(const Mesh& mesh, const Eigen::VectorXd& values, const std::string& unit,
                        const fs::path& out_dir, const std::string& stem, const std::string& title) {
  {
    std::ofstream out = open_plot_data(out_dir, stem);
    out << "# x y z value: pm3d patches of two scans each, separated by a scan of undefined points\n";
    if (mesh.dim == 2)
      write_plane(out, mesh, values);
    else
      write_skin(out, mesh, values);
  }
  std::string view =
      mesh.dim == 2 ? "set view map\nset size ratio -1\nunset ztics\nunset zlabel\nset format x '%.3g'\n"
                      "set format y '%.3g'\nset xtics nomirror rotate by 90 right\nset ytics nomirror\n"
                    : "set view 55, 35, 1.4\nset view equal xyz\nset xyplane 0\nset zlabel 'z [m]' rotate parallel\n"
                      "set pm3d depthorder\n";
  if (mesh.dim == 2) {
    // Two or three x tics: a slender part (a blade standing up) would crowd its narrow axis.
    const double width = mesh.coords.col(0).maxCoeff() - mesh.coords.col(0).minCoeff();
    if (width > 0) {
      const double raw = width / 2, decade = std::pow(10.0, std::floor(std::log10(raw)));
      const double m = raw / decade, step = (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * decade;
      view += fmt::format("set xtics {}\n", step);
    }
  }
  if (mesh.dim == 3) {
    // A thin part in z (a plate) would stack its z tic labels on top of each other.
    const Eigen::RowVectorXd extent = mesh.coords.colwise().maxCoeff() - mesh.coords.colwise().minCoeff();
    if (extent[2] < 0.1 * std::max(extent[0], extent[1])) view += "unset ztics\nunset zlabel\n";
  }
  const std::string script = fmt::format(
      "set title '{} [{}]'\n{}set xlabel 'x [m]'\nset ylabel 'y [m]'\nset pm3d corners2color mean\nset style fill "
      "solid noborder\n"
      "set palette rgbformulae 22,13,-31\nset format cb '%.3g'\nunset key\n"
      "splot '{}.dat' using 1:2:3:4 with pm3d\n",
      gnuplot_quote(title), gnuplot_quote(unit), view, stem);
  return draw(out_dir, stem, title, script);
}

}  // namespace bb
