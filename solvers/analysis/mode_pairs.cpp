#include "analysis/mode_pairs.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "common/errors.hpp"

namespace bb {
namespace {

const std::vector<int>& named_set(const Model& model, const std::string& name) {
  auto it = model.node_sets.find(name);
  if (it == model.node_sets.end()) throw InputError(fmt::format("'analysis.pairs': unknown node set '{}'", name));
  return it->second;
}

int single_node(const Model& model, const std::string& name) {
  const std::vector<int>& nodes = named_set(model, name);
  if (nodes.size() != 1)
    throw InputError(
        fmt::format("'analysis.pairs': set '{}' must hold exactly one node, it holds {}", name, nodes.size()));
  return nodes.front();
}

// Largest of |mean ux|, |mean uz| and |theta| * half diagonal of the face, and its name.
struct TipMotion {
  double size = 0.0;
  const char* type = "-";
};

TipMotion tip_motion(const Mesh& mesh, const std::vector<int>& face, const Eigen::MatrixXd& shape) {
  const auto n = static_cast<double>(face.size());
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero(), mean_u = Eigen::Vector2d::Zero();  // (x, z)
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = Eigen::Vector2d::Constant(-INFINITY);
  for (int node : face) {
    const Eigen::Vector2d xz(mesh.coords(node, 0), mesh.coords(node, 2));
    centroid += xz / n;
    mean_u += Eigen::Vector2d(shape(node, 0), shape(node, 2)) / n;
    lo = lo.cwiseMin(xz);
    hi = hi.cwiseMax(xz);
  }
  // u = a + theta e_y x r, r = (rx, 0, rz) from the centroid: ux = ax + theta rz, uz = az - theta rx.
  // With sum r = 0 the least-squares theta decouples from the translation.
  double num = 0.0, den = 0.0;
  for (int node : face) {
    const double rx = mesh.coords(node, 0) - centroid.x(), rz = mesh.coords(node, 2) - centroid.y();
    num += shape(node, 0) * rz - shape(node, 2) * rx;
    den += rx * rx + rz * rz;
  }
  const double theta = den > 0 ? num / den : 0.0;
  const std::array<double, 3> size = {std::abs(mean_u.x()), std::abs(mean_u.y()),
                                      std::abs(theta) * 0.5 * (hi - lo).norm()};
  static const char* names[] = {"flexure-x", "flexure-z", "torsion"};
  TipMotion m;
  for (size_t k = 0; k < 3; ++k)
    if (size[k] > m.size) m = {size[k], names[k]};
  return m;
}

std::string in_or_out_of_phase(const Eigen::Vector3d& left, const Eigen::Vector3d& right, Direction direction,
                               double rest) {
  if (std::max(left.norm(), right.norm()) < rest) return "-";
  const Eigen::Vector3d both = left.cwiseAbs().cwiseMax(right.cwiseAbs());
  Eigen::Index axis = direction;
  if (both[direction] < 0.1 * both.maxCoeff()) both.maxCoeff(&axis);
  const double a = left[axis], b = right[axis];
  // One body at rest: a mode of one blade alone (a degenerate pair may split that way).
  if (std::min(std::abs(a), std::abs(b)) < kModeLabelRest * std::max(std::abs(a), std::abs(b))) return "-";
  return a * b > 0 ? "IP" : "OOP";
}

}  // namespace

void check_mode_pair_sets(const Model& model, const ModePairSpec& spec) {
  if (model.mesh.dim != 3)
    throw InputError(fmt::format("{}: [analysis.pairs] needs a solid (3D) mesh", spec.at.where()));
  for (const std::string* name : {&spec.left, &spec.right, &spec.left_tip, &spec.right_tip})
    if (!model.node_sets.count(*name))
      throw InputError(fmt::format("{}: unknown node set '{}'", spec.at.where(), *name));
  for (const std::string* name : {&spec.left, &spec.right})
    if (model.node_sets.at(*name).size() != 1)
      throw InputError(fmt::format("{}: [analysis.pairs]: set '{}' must hold exactly one node, it holds {}",
                                   spec.at.where(), *name, model.node_sets.at(*name).size()));
}

std::vector<ModeLabel> label_mode_pairs(const Model& model, const ModalResult& modal, const ModePairSpec& spec) {
  const Mesh& mesh = model.mesh;
  if (mesh.dim != 3) throw InputError("'analysis.pairs' needs a solid (3D) mesh");
  if (spec.direction < 0 || spec.direction > 2) throw InputError("'analysis.pairs.direction' must be x, y or z");
  const int left = single_node(model, spec.left), right = single_node(model, spec.right);
  const std::vector<int>& left_tip = named_set(model, spec.left_tip);
  const std::vector<int>& right_tip = named_set(model, spec.right_tip);
  std::vector<ModeLabel> labels;
  for (const Eigen::MatrixXd& shape : modal.shapes) {
    const double rest = kModeLabelRest * shape.rowwise().norm().maxCoeff();
    ModeLabel label;
    label.pair = in_or_out_of_phase(shape.row(left).transpose(), shape.row(right).transpose(), spec.direction, rest);
    TipMotion tip = tip_motion(mesh, right_tip, shape);
    if (tip.size < rest) tip = tip_motion(mesh, left_tip, shape);
    label.type = tip.size < rest ? "-" : tip.type;
    labels.push_back(label);
  }
  return labels;
}

void add_mode_labels(ResultTable& frequencies, const std::vector<ModeLabel>& labels) {
  std::vector<std::string> pair, type;
  for (const ModeLabel& l : labels) {
    pair.push_back(l.pair);
    type.push_back(l.type);
  }
  frequencies.add_text_column("pair", std::move(pair));
  frequencies.add_text_column("type", std::move(type));
}

}  // namespace bb
