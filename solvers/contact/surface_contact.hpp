// Penalty contact between facing facets of a solid mesh (Model::contact_pairs), integrated at the
// Gauss points of the contact facets: at each point the gap is
//   g = g0 + n . (u_target - u_contact),
// n the contact facet's outward unit normal, g0 the initial gap (< 0: an interference), and a closed
// point carries the pressure p = -kn g and, sticking, the shear traction -kt (I - n n^T)(u_t - u_c).
// That is the energy 1/2 integral (kn <-g>^2 + kt |slip|^2) dA of a penalty (Ansys's pure penalty,
// or augmented Lagrange with one augmentation); on matching facets it is the segment-to-segment
// form, which passes the constant-pressure patch test exactly (Wriggers, Computational Contact
// Mechanics, 2nd ed., sec. 9.5). Small displacements: n and the pairing stay those of the mesh.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

#include "model/model.hpp"

namespace bb {

struct ContactPoint {
  int pair = 0;                                      // index into the model's contact pairs
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // outward from the contact surface, into the target
  double area = 0.0;                                  // Gauss weight times the surface Jacobian [m^2]
  double facet_size = 0.0;                            // sqrt of the facet's area [m]
  const ContactFacetPair* facet = nullptr;            // nodes of both sides (owned by the Model)
  Eigen::VectorXd shape;                              // the facet's shape functions at the point
};

// 2x2 Gauss points on 4-node facets, 3x3 on 8-node ones.
std::vector<ContactPoint> contact_points(const Mesh& mesh, const std::vector<ContactPair>& pairs);

// u_target - u_contact at the point, from the displacement of every DOF (node * 3 + direction).
Eigen::Vector3d relative_displacement(const ContactPoint& p, const Eigen::VectorXd& u);

// The gap g = g0 + n . du and the tangential slip (I - n n^T) du of a point at u.
struct PointMotion {
  double gap = 0.0;
  Eigen::Vector3d slip = Eigen::Vector3d::Zero();
};
PointMotion point_motion(const ContactPoint& p, double initial_gap, const Eigen::VectorXd& u);

// Penalty stiffnesses of each point [N/m^3 = Pa/m], and the normal law. With roughness sigma = 0 the
// law is linear, p = -kn g. With sigma > 0 it stiffens with the pressure as a rough interface does,
// dp/d(-g) = kn + p / sigma, i.e. p = kn sigma (exp(-g / sigma) - 1): the penalty kn at first touch,
// and beyond a few sigma of penetration the stiffness p / sigma of Greenwood & Williamson's contact of
// rough surfaces with exponentially distributed asperity heights (Proc. R. Soc. A 295, 1966).
struct ContactPenalty {
  Eigen::VectorXd normal;
  Eigen::VectorXd tangential;  // 0: frictionless
  double roughness = 0.0;      // sigma [m]
};

// The penalty of a point for the normal penalty factor FKN: kn = FKN E / h, h the contact face's size
// (Ansys scales its default contact stiffness with the underlying modulus and element size).
inline double penalty_from_factor(double fkn, double youngs_modulus, double facet_size) {
  return fkn * youngs_modulus / facet_size;
}

// The normal law at a gap g of a point with penalty kn: pressure [Pa], tangent stiffness
// dp/d(-g) [Pa/m] and the stored energy per area [J/m^2] (zero at g = 0, convex in g).
double normal_pressure(double kn, double roughness, double gap);
double normal_tangent(double kn, double roughness, double gap);
double normal_energy(double kn, double roughness, double gap);

// Stiffness of the closed points on every DOF (n_dofs = nodes * 3).
Eigen::SparseMatrix<double> contact_stiffness(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                                              const ContactPenalty& penalty, int n_dofs);

// The force the initial gaps of the closed points exert: -sum area kn g0 G^T n (every DOF).
Eigen::VectorXd initial_gap_force(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                                  const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap, int n_dofs);

// The energy stored in the closed points at u: the normal law's and 1/2 kt |slip|^2, over the areas.
double contact_energy(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                      const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& u);

// The force the closed points exert on the bodies at the displacement u, sum area G^T (p n - kt slip)
// (every DOF), under the normal law: the contact's share of the internal force, with a minus sign.
Eigen::VectorXd contact_force(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                              const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap,
                              const Eigen::VectorXd& u);

}  // namespace bb
