// Rigid underplatform damper between two blade platforms (thesis section 3.3.2.2 and 3.4.2,
// eq 3.43, Figs 3.72-3.73): a rigid body in the plane with three DOFs, translations x, y and the
// rotation theta about its centre of mass G, a flat face against the left blade's platform (two
// contact points, L1 and L2) and a cylindrical face against the right blade's platform (one point,
// R). The centrifugal force CF acts at G and presses the damper onto the platforms. Units: SI
// (m, kg, kg m^2, N, rad; angles given in degrees where the name says _deg).
//
// Frame: that of articles/two_blade.hpp, x tangential (blade 1 -> blade 2), y radial (root ->
// tip). The platform contact faces overhang the damper: blade 1's right face rises at +beta_L from
// the x axis, blade 2's left face at -beta_R (it falls towards +x), so the two faces converge
// towards +y and CF (+y, radially outwards) wedges the damper between them.
//
// Sign conventions (one set, used everywhere below):
//  - n, the unit normal of a contact, points FROM the blade platform INTO the damper. For the left
//    face n_L = (sin beta_L, -cos beta_L), for the right face n_R = (-sin beta_R, -cos beta_R).
//  - t = n rotated by +90 degrees, t = (-n_y, n_x); on the left face t runs up the face, along
//    (cos beta_L, sin beta_L).
//  - Relative displacement = platform (blade) point - damper point: u = t . (d_blade - d_damper),
//    v = n . (d_blade - d_damper). v > 0 PRESSES the bodies together (the platform moves into the
//    damper, or the damper moves against n into the platform): friction/jenkins.hpp's
//    convention, so a row pair (a_t, a_n) below feeds jenkins_step directly.
//  - Contact forces (T, N) act on the DAMPER as T t + N n and on the blade as -(T t + N n). With
//    Jenkins' T = kt (u - w) this is the force that drags the damper along with the platform, and
//    N >= 0 pushes the damper away from the platform.
//  - Small rotations: a damper point at r from G moves by (x - theta r_y, y + theta r_x).
//  - Generalized contact force on the DOF vector q: -(A_t^T T + A_n^T N) (virtual work:
//    -sum (T du + N dv)); its damper part is B [T1 N1 T2 N2 ...] (eq 3.43).
#pragma once
#include <Eigen/Dense>

#include <string>
#include <utility>
#include <vector>

#include "reduction/reduced_model.hpp"

namespace bb::damper {

// One point of contact between the damper and a blade platform.
struct DamperContact {
  std::string name;                                    // "L1", "L2", "R"
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // r = contact point - G [m]
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();    // unit, platform -> damper
  // Indices, in the DOF vector q = [blade DOFs..., damper x, y, theta], of the platform point's x
  // and y translations; -1 for both means a rigid, fixed platform (no blade DOF).
  int blade_x = -1;
  int blade_y = -1;

  Eigen::Vector2d tangent() const { return {-normal.y(), normal.x()}; }
};

// n_L = (sin beta_L, -cos beta_L): blade 1's right contact face, rising at +beta_L from x.
Eigen::Vector2d left_face_normal(double beta_left_deg);
// n_R = (-sin beta_R, -cos beta_R): blade 2's left contact face, at -beta_R from x.
Eigen::Vector2d right_face_normal(double beta_right_deg);

struct RigidDamper {
  double mass = 0.0;     // m [kg], > 0
  double inertia = 0.0;  // J about G, out of plane [kg m^2], > 0
  std::vector<DamperContact> contacts;
};

// Throws std::invalid_argument naming the offending value: non-positive or non-finite m, J, a
// normal that is not unit (1e-12), a non-finite position, no contact, repeated names, a blade
// index out of [0, blade_dofs) or given for only one direction.
void validate(const RigidDamper& damper, int blade_dofs);

// The thesis's damper (Fig 3.72): flat face on the left platform with points L1, L2, cylindrical
// face on the right platform with point R. Positions relative to G; blade indices default to rigid
// platforms.
struct AsymmetricDamperGeometry {
  double mass = 0.0;
  double inertia = 0.0;
  double beta_left_deg = 45.0;                   // left face angle from x [deg], in (0, 90)
  double beta_right_deg = 45.0;                  // right face angle from x [deg], in (0, 90)
  Eigen::Vector2d l1 = Eigen::Vector2d::Zero();  // on the flat face, lower point [m]
  Eigen::Vector2d l2 = Eigen::Vector2d::Zero();  // on the flat face, upper point [m]
  Eigen::Vector2d r = Eigen::Vector2d::Zero();   // line contact of the cylindrical face [m]
  // Blade DOF indices (x, y) of the platform points L1, L2, R; -1 = rigid platform.
  int l1_x = -1, l1_y = -1, l2_x = -1, l2_y = -1, r_x = -1, r_y = -1;
};
// Throws std::invalid_argument if an angle is outside (0, 90) or L1 -> L2 is not along the flat
// face (relative 1e-9), i.e. the three points do not describe the geometry the normals assume.
RigidDamper asymmetric_damper(const AsymmetricDamperGeometry& g);

// Indices (x, y) of master node `label`'s in-plane translations in a blade reduced model (its z
// DOF, if any, plays no part in the planar damper): the blade side of a contact on elastic
// platforms, e.g. platform_dofs(model, "L1") for the thesis's masters L1, L2, R. Throws InputError
// naming the label when the model has no such DOF.
std::pair<int, int> platform_dofs(const ReducedModel& blades, const std::string& label);

// Damper DOF indices in q for a model with blade_dofs blade DOFs.
inline int damper_x(int blade_dofs) { return blade_dofs; }
inline int damper_y(int blade_dofs) { return blade_dofs + 1; }
inline int damper_theta(int blade_dofs) { return blade_dofs + 2; }

// (x - theta r_y, y + theta r_x): displacement of the damper point at r from G for q_d = (x, y, theta).
Eigen::Vector2d damper_point_displacement(const Eigen::Vector3d& damper_dofs, const Eigen::Vector2d& r);

// Row c of `tangential` (normal) is a_t (a_n) of contact c: u_c = a_t . q, v_c = a_n . q over
// q = [blade DOFs, x, y, theta], size blade_dofs + 3.
struct ContactKinematics {
  Eigen::MatrixXd tangential;  // contacts x (blade_dofs + 3)
  Eigen::MatrixXd normal;      // contacts x (blade_dofs + 3)
};
ContactKinematics contact_kinematics(const RigidDamper& damper, int blade_dofs);

// Eq 3.43: B (3 x 2 contacts) maps the contact forces f = [T1, N1, T2, N2, ...] to the force
// (Fx, Fy) and the moment about G (Mz) they exert on the damper: column 2c is (t, r x t), column
// 2c + 1 is (n, r x n). B = -(damper columns of the interleaved rows [a_t; a_n])^T.
Eigen::Matrix<double, 3, Eigen::Dynamic> contact_force_to_damper(const RigidDamper& damper);

// Linear part of the coupled system over q = [blade DOFs, x, y, theta]: M = diag(M_b, m, m, J),
// K = diag(K_b, 0, 0, 0). The damper has no stiffness of its own: only the contacts hold it.
struct CoupledSystem {
  Eigen::MatrixXd mass;
  Eigen::MatrixXd stiffness;
  int blade_dofs = 0;
};
// Throws std::invalid_argument if M_b and K_b are not square of the same size or validate() fails.
CoupledSystem assemble_coupled_system(const Eigen::MatrixXd& blade_mass, const Eigen::MatrixXd& blade_stiffness,
                                      const RigidDamper& damper);

// Static load: the centrifugal force `cf` [N] at G along +y (radially outwards), the direction that
// presses the damper onto the platforms of the frame above; cf < 0 pulls it away. Zero on the blades
// (add their own loads to the vector).
Eigen::VectorXd centrifugal_load(int blade_dofs, double cf);

struct DamperStaticOptions {
  double kn = 0.0;          // normal contact stiffness of every contact [N/m], finite, > 0
  int max_iterations = 50;  // active-set iterations
  // A closed contact opens when N < -opening_tolerance * ||f||; an open one closes when
  // v > opening_tolerance * ||f|| / kn. Keeps round-off from flipping a contact loaded exactly to 0.
  double opening_tolerance = 1e-12;
};

// Static pre-solve (thesis eq 3.49): K q + A_n^T N = f with the unilateral law N = max(kn v, 0),
// v = A_n q measured from the state where every contact just touches (no initial gap, no preload).
// Friction is NEGLECTED in the static state: tangential preloads are 0, the damper slides freely
// into its seat. Solved by a primal-dual active set: for each set of closed contacts the mixed
// system [K A^T; A -I/kn] [q; N] = [f; 0] (symmetric diagonal equilibration, full-pivot LU, one
// step of iterative refinement), so N comes out as a force and not as kn times a tiny difference
// of displacements: its accuracy does not depend on kn.
struct DamperStaticState {
  Eigen::VectorXd q;                                 // blade and damper displacements [m, rad]; zero on failure
  Eigen::Vector3d damper = Eigen::Vector3d::Zero();  // (x, y, theta) of G [m, m, rad]
  Eigen::VectorXd normal_preload;                    // N0 per contact [N], >= 0, zero where open
  Eigen::VectorXd normal_displacement;               // v per contact [m]
  std::vector<bool> open;                            // contact c carries no load
  int iterations = 0;
  double force_residual = 0.0;   // |f_d + sum N n| on the damper [N]
  double moment_residual = 0.0;  // |M_d + sum r x N n| about G [N m]
  bool converged = false;
  std::string failure;  // why not converged; empty when converged
};

// Throws std::invalid_argument on invalid inputs (sizes, non-finite values, kn <= 0, validate()),
// never on a physical failure: a load that pulls the damper off the platforms (every contact
// opens), a set of closed contacts that leaves the damper a mechanism (cannot balance the load),
// a singular blade stiffness or active-set cycling come back with converged == false, a message,
// `open` set and no NaN anywhere.
[[nodiscard]] DamperStaticState solve_damper_static(const Eigen::MatrixXd& blade_stiffness, const RigidDamper& damper,
                                                    const Eigen::VectorXd& load, const DamperStaticOptions& options);

}  // namespace bb::damper
