// Labels for the modes of two identical bodies side by side (the thesis's two blades, Table VI):
// whether the two bodies move in phase (IP) or out of phase (OOP), and what kind of motion the
// tip of a blade makes (flexure in x or z, or torsion about the blade axis y). The thesis says
// the modes come "in couples of an in-phase and out-of-phase motion" and are "all flexural or
// torsional" (section 3.1) without naming them; these labels make the comparison with Table VI
// row by row readable. Units: SI.
#pragma once
#include <string>
#include <vector>

#include "analysis/modal_analysis.hpp"
#include "analysis/modal_spec.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

// Throws InputError (at spec.at) unless the mesh is 3D, every named set exists and left and right
// hold one node each.
void check_mode_pair_sets(const Model& model, const ModePairSpec& spec);

struct ModeLabel {
  std::string pair;  // "IP", "OOP" or "-" (the two reference nodes at rest, or only one moving)
  std::string type;  // "flexure-x", "flexure-z", "torsion" or "-" (both tip faces at rest)
};

// A motion below this fraction of the mode's largest nodal displacement counts as rest.
inline constexpr double kModeLabelRest = 0.01;

// One label per mode of `modal`. IP / OOP: the signs of the two nodes' displacement along
// `direction` (or along the axis in which they move most, when `direction` carries less than a
// tenth of that motion). Type: the right tip face's displacement split into its mean x and z
// translation and the least-squares rigid rotation theta about y through the face's centroid;
// the largest of |mean ux|, |mean uz| and |theta| times half the face's diagonal names it. When
// the right tip is at rest (a mode of the left blade alone) the left tip is used.
// Needs a 3D mesh and the sets named by `spec` in model.node_sets; throws InputError otherwise.
std::vector<ModeLabel> label_mode_pairs(const Model& model, const ModalResult& modal, const ModePairSpec& spec);

// Appends the labels to a frequency table (one row per mode) as text columns "pair" and "type".
void add_mode_labels(ResultTable& frequencies, const std::vector<ModeLabel>& labels);

}  // namespace bb
