#include "ffrf/rotating_body.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "ffrf/body_assembly.hpp"
#include "linalg/spd_factor.hpp"

namespace bb::ffrf {
namespace {

void validate(const Model& model, const RotationAxis& axis) {
  const Eigen::Vector3d& a = axis.direction;
  if (!a.allFinite() || !axis.point.allFinite()) throw InputError("rotation axis: direction and point must be finite");
  if (std::abs(a.norm() - 1.0) > 1e-9)
    throw InputError(fmt::format("rotation axis direction must be a unit vector, |a| = {:.9g}", a.norm()));
  if (model.mesh.dim == 2 && std::abs(std::abs(a.z()) - 1.0) > 1e-9)
    throw InputError("rotation axis of a 2D (plane) body must be +z or -z: the body rotates in its plane");
  if (!(model.section.density > 0.0))
    throw InputError(fmt::format("rotating body needs a positive density, got rho = {}", model.section.density));
  for (const Constraint& c : model.constraints)
    if (c.value != 0.0)
      throw InputError(
          fmt::format("rotating body: constraint on set '{}' prescribes {} m; the root is clamped to "
                      "the rotor, so only zero prescribed displacements are allowed",
                      c.set, c.value));
}

// Rigid translations of every node, all DOFs x dim.
Eigen::MatrixXd translations(int n_nodes, int dim) {
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n_nodes) * dim, dim);
  for (int n = 0; n < n_nodes; ++n)
    for (int d = 0; d < dim; ++d) e(static_cast<Eigen::Index>(n) * dim + d, d) = 1.0;
  return e;
}

Eigen::MatrixXd axis_skew(const RotatingBody& body) {
  const Eigen::Vector3d& a = body.axis.direction;
  if (body.dim == 2) return a.z() * (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  return (Eigen::Matrix3d() << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0).finished();
}

// K u1 = f_c on the free DOFs (Cholesky); InputError when K is singular (body not held).
Eigen::VectorXd unit_speed_deflection(const RotatingBody& body) {
  SpdFactorization factor(ordering_for_dimension(body.dim));
  const FactorStatus status = factor.factorize(body.stiffness);
  if (!status.ok)
    throw InputError(
        fmt::format("rotating body: the constraints do not hold the body (stiffness singular: {}); "
                    "clamp the root nodes in every direction",
                    status.message));
  return factor.solve(body.centrifugal_load);
}

}  // namespace

RotatingBody build_rotating_body(const Model& model, const RotationAxis& axis) {
  validate(model, axis);
  const Mesh& mesh = model.mesh;
  RotatingBody body;
  body.dim = mesh.dim;
  body.axis = axis;
  body.dofs = number_dofs(model);
  if (body.dofs.n_free == 0) throw InputError("rotating body: every DOF is constrained, nothing can deform");

  const int dim = body.dim, n_nodes = mesh.n_nodes();
  body.positions.resize(static_cast<Eigen::Index>(n_nodes) * dim);
  Eigen::VectorXd relative(body.positions.size());  // x - p
  for (int n = 0; n < n_nodes; ++n)
    for (int d = 0; d < dim; ++d) {
      const Eigen::Index g = static_cast<Eigen::Index>(n) * dim + d;
      body.positions[g] = mesh.coords(n, d);
      relative[g] = mesh.coords(n, d) - axis.point[d];
    }
  const Eigen::ArrayXd lo = mesh.coords.colwise().minCoeff(), hi = mesh.coords.colwise().maxCoeff();
  body.size = (hi - lo).matrix().norm();

  const InertiaOperators inertia = assemble_inertia(mesh, model.section, axis.direction);
  const SparseMatrix k_all = assemble(mesh, model.section, {.stiffness = true, .mass = false}).stiffness;
  body.mass = partition(inertia.mass, body.dofs).ff;
  body.projected_mass = partition(inertia.projected_mass, body.dofs).ff;
  body.gyroscopic = partition(inertia.gyroscopic, body.dofs).ff;
  body.stiffness = partition(k_all, body.dofs).ff;

  // f_c = integral rho S^T P (x - p): exact for isoparametric elements, S interpolating x.
  const Eigen::VectorXd mp_x = inertia.projected_mass * relative;
  body.centrifugal_load = free_part(body.dofs, mp_x);
  body.euler_load = -free_part(body.dofs, inertia.gyroscopic * relative);
  const Eigen::MatrixXd e = translations(n_nodes, dim);
  const Eigen::MatrixXd me = inertia.mass * e;  // integral rho S^T dV per direction
  body.gravity_load.resize(body.dofs.n_free, dim);
  for (int d = 0; d < dim; ++d) body.gravity_load.col(d) = free_part(body.dofs, me.col(d));

  body.mass_properties.mass = e.col(0).dot(me.col(0));
  body.mass_properties.first_moment = me.transpose() * relative;
  body.mass_properties.axis_inertia = relative.dot(mp_x);

  body.unit_speed_deflection = unit_speed_deflection(body);
  body.geometric_stiffness =
      partition(assemble_geometric_stiffness(mesh, model.section, expand_to_global(body, body.unit_speed_deflection)),
                body.dofs)
          .ff;
  return body;
}

Eigen::MatrixXd axis_rotation(const RotatingBody& body, double theta) {
  const Eigen::MatrixXd s = axis_skew(body);
  return Eigen::MatrixXd::Identity(body.dim, body.dim) + std::sin(theta) * s + (1.0 - std::cos(theta)) * s * s;
}

Eigen::MatrixXd axis_rotation_derivative(const RotatingBody& body, double theta, int order) {
  const Eigen::MatrixXd s = axis_skew(body);
  if (order == 1) return std::cos(theta) * s + std::sin(theta) * s * s;
  if (order == 2) return -std::sin(theta) * s + std::cos(theta) * s * s;
  throw std::invalid_argument("axis_rotation_derivative: order must be 1 or 2");
}

Eigen::VectorXd expand_to_global(const RotatingBody& body, const Eigen::VectorXd& free_values) {
  return to_global(body.dofs, free_values, false);
}

Eigen::VectorXd restrict_to_free(const RotatingBody& body, const Eigen::VectorXd& global_values) {
  if (global_values.size() != body.dofs.n_global())
    throw std::invalid_argument("restrict_to_free: vector size is not the number of nodal DOFs");
  return free_part(body.dofs, global_values);
}

}  // namespace bb::ffrf
