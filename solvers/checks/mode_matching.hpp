// Pairing the modes of two runs by their shapes (the Modal Assurance Criterion, Allemang & Brown
// 1982; Allemang, "The modal assurance criterion - twenty years of use and abuse", Sound and
// Vibration 37(8), 2003), so that a check compares a mode with the same mode of the reference run
// even when a refined mesh or another element orders the modes differently.
//
//   MAC(a, b) = (a^T b)^2 / ((a^T a)(b^T b))
//
// over the displacements at the nodes the two meshes share (coincident within a tolerance: a
// refinement by an integer factor, or hex8 corners inside a hex20 mesh). A repeated eigenvalue has
// no preferred basis: its modes are paired as a subspace (the MAC of a reference mode with the
// orthonormalized span of the cluster), then in frequency order inside it.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "analysis/modal_analysis.hpp"
#include "mesh/mesh.hpp"
#include "results/table.hpp"

namespace bb {

// Frequencies within this relative distance form one repeated eigenvalue (the two lateral bending
// modes of a square bar agree to 1e-10; the in-phase and out-of-phase modes of two identical
// blades differ by 6e-5, are different shapes and must stay apart).
inline constexpr double kRepeatedFrequency = 1e-6;

struct ModeMatch {
  int common_nodes = 0;
  Eigen::MatrixXd mac;                     // computed modes x reference modes, pairwise
  std::vector<int> computed_of_reference;  // per reference mode (0-based index), its computed mode (0-based), -1 none
  std::vector<double> match_mac;           // per reference mode, the MAC of its pairing (subspace MAC in a cluster)
};

// Throws InputError when the meshes have different dimensions or share fewer nodes than the
// reference has modes (the MAC could not tell the modes apart).
ModeMatch match_modes_by_shape(const Mesh& mesh, const ModalResult& modes, const Mesh& reference_mesh,
                               const ModalResult& reference_modes);

// Key `mode` (the reference mode): reference_frequency_hz, matched_mode (0 = none), frequency_hz of
// the matched mode, mac of the pairing, then mac_<k>, the pairwise MAC with every computed mode k.
ResultTable mode_match_table(const std::string& name, const ModeMatch& match, const ModalResult& modes,
                             const ModalResult& reference_modes);

}  // namespace bb
