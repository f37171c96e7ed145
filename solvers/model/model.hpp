// The validated model a solver sees: mesh, section, node sets, constraints and loads.
// Built from a case file by cases/build_model; solvers never see TOML.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "fe/plane_stress.hpp"
#include "mesh/mesh.hpp"

namespace bb {

// Direction index of a nodal DOF: 0 = x, 1 = y, 2 = z.
using Direction = int;

struct Constraint {
  std::string set;
  std::vector<Direction> directions;
  double value = 0.0;  // prescribed displacement [m]
};

enum class LoadSplit {
  equal,            // total / number of nodes
  consistent_edge,  // work-equivalent nodal forces of a uniform traction on the set's element edges
};

struct NodalLoad {
  std::string set;
  Direction direction = 0;
  double total = 0.0;  // [N]
  LoadSplit split = LoadSplit::equal;
};

// A distributed load on the boundary facets (2D: element edges, 3D: element faces) whose nodes all
// lie in a node set, integrated with the element's shape functions (fe/surface_load.hpp): a plane
// element's edge carries it over its length times the thickness, a hex20 face over its 8 nodes.
struct SurfaceLoad {
  enum class Kind { pressure, traction };
  std::string set;
  Kind kind = Kind::pressure;
  double pressure = 0.0;                               // [Pa], > 0 pushes into the body (along -n, n outward)
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();  // [Pa], force per area in global axes (2D: x, y)
};

// A load on every element per unit mass, consistent with the element mass (f_e = M_e b, exact for
// an acceleration linear in x on isoparametric elements): gravity, or the centrifugal acceleration
// Omega^2 P (x - origin), P = I - a a^T, of a rotation at a fixed speed about an axis (a pure load:
// no spin softening or stress stiffening, as a static analysis of a spinning part without them).
struct BodyLoad {
  enum class Kind { gravity, centrifugal };
  Kind kind = Kind::gravity;
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // gravity [m/s^2]
  double speed = 0.0;                                      // centrifugal: Omega [rad/s]
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();         // unit vector
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();        // a point of the axis [m] (2D: z = 0)
};

// Two surfaces of a solid mesh that may touch without being glued (contact/surface_contact.hpp):
// every facet of the contact surface faces a coincident facet of the target surface (conforming
// meshes, as where bodies were meshed together and left unmerged).
struct ContactFacetPair {
  std::vector<int> contact;  // nodes of the contact surface's facet (order of facet_nodes)
  std::vector<int> target;   // the coincident nodes of the target's facet, in the same order
};

struct ContactPair {
  std::string name;
  std::string contact_set, target_set;
  // The analysis's interference (an initial overlap along the normal) acts on this pair: e.g. the
  // wedge pushed up into the root. Other pairs start touching with no gap.
  bool interference = false;
  std::vector<ContactFacetPair> facets;
};

struct Model {
  Mesh mesh;
  fe::PlaneSection section;
  std::map<std::string, std::vector<int>> node_sets;  // internal node indices, sorted
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;
  std::vector<SurfaceLoad> surface_loads;
  std::vector<BodyLoad> body_loads;
  std::vector<ContactPair> contact_pairs;
  std::vector<std::string> import_notes;  // what a deck reader read differently from the file's own solver
};

}  // namespace bb
