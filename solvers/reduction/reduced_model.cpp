#include "reduction/reduced_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

constexpr char kAxes[] = {'x', 'y', 'z'};

// A label is what the exporter calls the node ("T2", "N1034", "root.7"). It becomes CSV column
// names and plot titles ("T2.x_amp_m"), so it is a name (common/user_text.hpp) that may hold dots:
// no whitespace (the sidecar's names would be ambiguous), no comma, quote, path or control byte.
bool valid_label(const std::string& label) { return dotted_name_problem(label).empty(); }

// "K(2, 3) ('T2.y', 'mode 1')" for messages; 1-based like the matrix files.
std::string entry(const char* matrix, const ReducedModel& model, Eigen::Index i, Eigen::Index j) {
  return fmt::format("{}({}, {}) ('{}', '{}')", matrix, i + 1, j + 1, model.dofs[static_cast<size_t>(i)].name(),
                     model.dofs[static_cast<size_t>(j)].name());
}

void check_finite_and_symmetric(const Eigen::MatrixXd& a, const char* matrix, const ReducedModel& model,
                                const std::string& source) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!std::isfinite(a(i, j)))
        throw InputError(fmt::format("{}: {} = {} is not finite", source, entry(matrix, model, i, j), a(i, j)));
  const double scale = a.cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = j + 1; i < a.rows(); ++i)
      if (std::abs(a(i, j) - a(j, i)) > 1e-8 * scale)
        throw InputError(fmt::format("{}: {} is not symmetric: {} = {:.17g} but the transposed entry is {:.17g}",
                                     source, matrix, entry(matrix, model, i, j), a(i, j), a(j, i)));
}

}  // namespace

std::string ReducedDof::name() const {
  if (direction >= 0 && direction < 3) return fmt::format("{}.{}", label, kAxes[direction]);
  return fmt::format("mode {}", mode);
}

std::optional<ReducedDof> ReducedDof::parse(const std::string& name) {
  static const std::string prefix = "mode ";
  if (name.starts_with(prefix)) {
    const char* first = name.data() + prefix.size();
    const char* last = name.data() + name.size();
    int mode = 0;
    // from_chars accepts a leading '-' only; a '+' or blank fails, so "mode  3" and "mode +3" are refused.
    const auto [end, ec] = std::from_chars(first, last, mode);
    if (ec != std::errc() || end != last || first == last || mode < 1) return std::nullopt;
    return ReducedDof{"", -1, mode};
  }
  const auto dot = name.rfind('.');
  if (dot == std::string::npos || dot + 2 != name.size()) return std::nullopt;
  const char* axis = std::find(std::begin(kAxes), std::end(kAxes), name.back());
  std::string label = name.substr(0, dot);
  if (axis == std::end(kAxes) || !valid_label(label)) return std::nullopt;
  return ReducedDof{std::move(label), static_cast<int>(axis - std::begin(kAxes)), 0};
}

std::optional<int> ReducedModel::index_of(const std::string& label, int direction) const {
  for (size_t i = 0; i < dofs.size(); ++i)
    if (dofs[i].mode == 0 && dofs[i].direction == direction && dofs[i].label == label) return static_cast<int>(i);
  return std::nullopt;
}

std::string damping_matrix_problem(const Eigen::MatrixXd& c) {
  if (c.size() == 0) return {};
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-8 * c.cwiseAbs().maxCoeff()) return "must be symmetric";
  const Eigen::VectorXd eig = symmetric_eigen(c, false).values;
  if (eig.minCoeff() < -1e-12 * std::max(eig.cwiseAbs().maxCoeff(), 1e-300))
    return fmt::format("must be positive semi-definite (negative damping); its smallest eigenvalue is {:.6g}",
                       eig.minCoeff());
  return {};
}

void validate_reduced_model(const ReducedModel& model, const std::string& source) {
  const Eigen::Index n = model.size();
  if (n == 0) throw InputError(fmt::format("{}: the reduced model has no DOFs", source));
  std::map<std::string, size_t> seen;
  for (size_t i = 0; i < model.dofs.size(); ++i) {
    const ReducedDof& d = model.dofs[i];
    const bool nodal = d.direction >= 0 && d.direction < 3 && d.mode == 0 && valid_label(d.label);
    const bool modal = d.direction == -1 && d.mode >= 1 && d.label.empty();
    if (!nodal && !modal)
      throw InputError(
          fmt::format("{}: DOF {} ('{}') is neither a nodal direction nor a mode", source, i + 1, d.name()));
    const auto [it, inserted] = seen.emplace(d.name(), i);
    if (!inserted)
      throw InputError(
          fmt::format("{}: DOF '{}' appears twice (DOFs {} and {})", source, d.name(), it->second + 1, i + 1));
  }
  for (const auto& [matrix, a] : {std::pair<const char*, const Eigen::MatrixXd*>{"K", &model.stiffness},
                                  std::pair<const char*, const Eigen::MatrixXd*>{"M", &model.mass}}) {
    if (a->rows() != n || a->cols() != n)
      throw InputError(fmt::format("{}: {} is {} x {} but there are {} DOFs", source, matrix, a->rows(), a->cols(), n));
    check_finite_and_symmetric(*a, matrix, model, source);
  }
  // Definiteness from the eigenvalues of the symmetric part: the models are small (tens to a few
  // hundred DOFs) and the smallest eigenvalue is the number a user can act on.
  const Eigen::VectorXd m_values =
      symmetric_eigen(Eigen::MatrixXd(0.5 * (model.mass + model.mass.transpose())), false).values;
  const double m_max = m_values.cwiseAbs().maxCoeff();
  // Positive definite in working precision: the smallest eigenvalue clears the round-off of the
  // largest (the numerical-rank threshold n eps |lambda|_max).
  if (!(m_values[0] > static_cast<double>(n) * std::numeric_limits<double>::epsilon() * m_max))
    throw InputError(fmt::format("{}: M is not positive definite (smallest eigenvalue {:.6g}, largest {:.6g})", source,
                                 m_values[0], m_values[n - 1]));
  const Eigen::VectorXd k_values =
      symmetric_eigen(Eigen::MatrixXd(0.5 * (model.stiffness + model.stiffness.transpose())), false).values;
  const double k_max = k_values.cwiseAbs().maxCoeff();
  // Rigid-body modes make K singular, which is fine; a clearly negative eigenvalue is not.
  if (k_values[0] < -1e-8 * k_max)
    throw InputError(fmt::format("{}: K is indefinite (smallest eigenvalue {:.6g}, largest {:.6g})", source,
                                 k_values[0], k_values[n - 1]));
}

}  // namespace bb
