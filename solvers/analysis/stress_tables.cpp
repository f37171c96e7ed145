#include "analysis/stress_tables.hpp"

#include <stdexcept>

#include "fe/stress_recovery.hpp"

namespace bb {
namespace {

// Column order of the stresses in every table: the in-plane ones first, so that 2D and 3D tables
// share their leading columns. Index into a field's row (plane: sxx, syy, sxy; Voigt: xx, yy, zz, xy, yz, zx).
std::vector<std::pair<std::string, int>> stress_columns(int components) {
  if (components == 3) return {{"sxx", 0}, {"syy", 1}, {"sxy", 2}};
  return {{"sxx", 0}, {"syy", 1}, {"sxy", 3}, {"szz", 2}, {"syz", 4}, {"szx", 5}};
}

}  // namespace

ResultTable nodal_stress_table(const std::string& name, const Mesh& mesh, const StressField& field) {
  ResultTable t;
  t.name = name;
  t.columns = {"node"};
  const auto components = stress_columns(field.components);
  for (const auto& [column, index] : components) t.columns.push_back(column);
  t.columns.push_back("von_mises");
  for (const char* p :
       field.components == 3 ? std::vector<const char*>{"s1", "s2"} : std::vector<const char*>{"s1", "s2", "s3"})
    t.columns.push_back(p);
  t.columns.push_back("von_mises_scatter");
  t.values.resize(mesh.n_nodes(), static_cast<Eigen::Index>(t.columns.size()));
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    Eigen::Index c = 0;
    t.values(n, c++) = static_cast<double>(mesh.node_ids[static_cast<size_t>(n)]);
    for (const auto& [column, index] : components) t.values(n, c++) = field.nodal(n, index);
    t.values(n, c++) = von_mises(field.nodal.row(n));
    if (field.components == 3) {
      const Eigen::Vector2d p = fe::principal_plane(field.nodal.row(n).transpose());
      t.values.row(n).segment(c, 2) = p.transpose();
      c += 2;
    } else {
      const Eigen::Vector3d p = fe::principal_solid(field.nodal.row(n).transpose());
      t.values.row(n).segment(c, 3) = p.transpose();
      c += 3;
    }
    t.values(n, c) = field.scatter[n];
  }
  return t;
}

ResultTable nodal_strain_table(const std::string& name, const Mesh& mesh, const StressField& field,
                               const fe::PlaneSection& material) {
  ResultTable t;
  t.name = name;
  const double e = material.youngs_modulus, nu = material.poisson_ratio;
  if (field.components == 3)
    t.columns = {"node", "exx", "eyy", "gxy", "ezz"};
  else
    t.columns = {"node", "exx", "eyy", "gxy", "ezz", "gyz", "gzx"};
  t.values.resize(mesh.n_nodes(), static_cast<Eigen::Index>(t.columns.size()));
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    t.values(n, 0) = static_cast<double>(mesh.node_ids[static_cast<size_t>(n)]);
    if (field.components == 3) {
      t.values.row(n).tail(4) = fe::plane_stress_strains(field.nodal.row(n).transpose(), e, nu).transpose();
    } else {
      const fe::Vector6 eps = fe::solid_strains(field.nodal.row(n).transpose(), e, nu);  // Voigt xx yy zz xy yz zx
      t.values.row(n).tail(6) << eps[0], eps[1], eps[3], eps[2], eps[4], eps[5];
    }
  }
  return t;
}

ResultTable integration_point_stress_table(const std::string& name, const StressField& field) {
  if (!field.points)
    throw std::invalid_argument("integration_point_stress_table: the field kept no integration points");
  const IntegrationPointStresses& p = *field.points;
  const int dim = static_cast<int>(p.coords.cols());
  ResultTable t;
  t.name = name;
  t.columns = {"point", "element", "gauss_point", "x", "y"};
  if (dim == 3) t.columns.push_back("z");
  const auto components = stress_columns(field.components);
  for (const auto& [column, index] : components) t.columns.push_back(column);
  t.columns.push_back("von_mises");
  const Eigen::Index n = static_cast<Eigen::Index>(p.element.size());
  t.values.resize(n, static_cast<Eigen::Index>(t.columns.size()));
  for (Eigen::Index r = 0; r < n; ++r) {
    Eigen::Index c = 0;
    t.values(r, c++) = static_cast<double>(r + 1);
    t.values(r, c++) = static_cast<double>(p.element[static_cast<size_t>(r)]);
    t.values(r, c++) = p.point[static_cast<size_t>(r)];
    for (int d = 0; d < dim; ++d) t.values(r, c++) = p.coords(r, d);
    for (const auto& [column, index] : components) t.values(r, c++) = p.stress(r, index);
    t.values(r, c) = von_mises(p.stress.row(r));
  }
  return t;
}

}  // namespace bb
