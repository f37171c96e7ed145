#include "analysis/operating_deflection.hpp"

#include "common/constants.hpp"
#include "forced/linear_model.hpp"
#include "frf/receptance.hpp"

namespace bb {

Eigen::VectorXd modal_zetas(const FrfDamping& d, const Eigen::VectorXd& omega) {
  if (d.kind == FrfDamping::Kind::modal) return d.modal_ratios(omega.size());
  const RayleighCoefficients c = rayleigh_of(d);
  return (c.alpha / (2 * omega.array().max(1e-300)) + 0.5 * c.beta * omega.array()).matrix();
}

std::vector<Eigen::MatrixXcd> operating_deflections(const Model& model, const FrfSpec& spec, const ModalResult& modal,
                                                    const std::vector<double>& frequencies_hz) {
  const Mesh& mesh = model.mesh;
  const int dim = mesh.dim;
  const auto n_modes = static_cast<Eigen::Index>(modal.shapes.size());
  const auto n_in = static_cast<Eigen::Index>(spec.forces.size());
  ModalReceptance r;
  r.omega = kTwoPi * modal.frequencies_hz;
  r.zeta = modal_zetas(spec.damping, r.omega);
  r.shapes_out.resize(mesh.n_nodes() * dim, n_modes);
  r.shapes_in.resize(n_in, n_modes);
  Eigen::VectorXd force(n_in);
  for (Eigen::Index k = 0; k < n_modes; ++k) {
    const Eigen::MatrixXd& shape = modal.shapes[static_cast<size_t>(k)];
    for (int n = 0; n < mesh.n_nodes(); ++n)
      for (int d = 0; d < dim; ++d) r.shapes_out(n * dim + d, k) = shape(n, d);
  }
  for (Eigen::Index j = 0; j < n_in; ++j) {
    const FrfForce& f = spec.forces[static_cast<size_t>(j)];
    const int node = model.node_sets.at(f.dof.point).front();
    for (Eigen::Index k = 0; k < n_modes; ++k)
      r.shapes_in(j, k) = modal.shapes[static_cast<size_t>(k)](node, f.dof.direction);
    force[j] = f.amplitude;
  }
  std::vector<Eigen::MatrixXcd> out;
  for (const double hz : frequencies_hz) {
    const Eigen::VectorXcd u = r.at(kTwoPi * hz) * force;
    Eigen::MatrixXcd nodal(mesh.n_nodes(), dim);
    for (int n = 0; n < mesh.n_nodes(); ++n)
      for (int d = 0; d < dim; ++d) nodal(n, d) = u[n * dim + d];
    out.push_back(std::move(nodal));
  }
  return out;
}

}  // namespace bb
