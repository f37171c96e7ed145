// Stresses of a displacement field over a whole mesh: at the integration points of every element
// (fe/initial_stress), extrapolated to each element's nodes (fe/stress_recovery) and averaged over
// the elements that share a node. The gather counterpart of assembly. SI units (Pa).
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <vector>

#include "fe/plane_stress.hpp"
#include "mesh/mesh.hpp"

namespace bb {

// The unaveraged values at the integration points (points of the stiffness rule, in the order of
// fe/initial_stress.hpp), one row per point.
struct IntegrationPointStresses {
  std::vector<long> element;  // user element id
  std::vector<int> point;     // 1-based index of the point in its element
  Eigen::MatrixXd coords;     // [m], n x dim
  Eigen::MatrixXd stress;     // [Pa], n x components
};

struct StressField {
  int components = 3;     // 3: plane stress (sxx, syy, sxy); 6: solid, Voigt (xx, yy, zz, xy, yz, zx)
  Eigen::MatrixXd nodal;  // n_nodes x components, the average over the elements at each node [Pa]
  // Per node, the largest von Mises stress of (one element's extrapolated value - the average): how
  // far the elements around the node disagree, a local estimate of the discretization error
  // (Zienkiewicz & Zhu 1987 build theirs on the same difference).
  Eigen::VectorXd scatter;
  Eigen::VectorXi elements;  // elements sharing each node (0: no element uses it, its stress is 0)
  std::optional<IntegrationPointStresses> points;
  double seconds = 0.0;  // wall time of the recovery
};

struct StressRecoveryOptions {
  bool integration_points = false;  // also keep the unaveraged integration-point values
};

// `displacements`: n_nodes x dim [m] (a static solution or a mode shape). Throws InputError naming an
// element whose geometry is invalid.
StressField recover_stresses(const Mesh& mesh, const fe::PlaneSection& section, const Eigen::MatrixXd& displacements,
                             const StressRecoveryOptions& options = {});

// Von Mises stress of one row of a field (plane stress or solid, by its number of components).
double von_mises(const Eigen::Ref<const Eigen::RowVectorXd>& stress);

}  // namespace bb
