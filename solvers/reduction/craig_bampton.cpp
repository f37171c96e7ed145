#include "reduction/craig_bampton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "linalg/dense_eigen.hpp"
#include "linalg/inertia.hpp"
#include "linalg/modal_solver.hpp"
#include "linalg/slepc_modes.hpp"

namespace bb {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

// Where each free DOF goes: its position among the masters (given order) or the slaves
// (ascending free index, so a slave block keeps the input's sorted row order).
struct Partition {
  std::vector<int> slaves;
  std::vector<int> local;  // per free DOF: index among masters or among slaves
  std::vector<bool> is_master;
};

Partition partition_dofs(int n, const std::vector<int>& masters, const std::vector<ReducedDof>& names) {
  Partition p;
  p.local.assign(static_cast<size_t>(n), -1);
  p.is_master.assign(static_cast<size_t>(n), false);
  for (size_t i = 0; i < masters.size(); ++i) {
    const int dof = masters[i];
    if (dof < 0 || dof >= n)
      throw InputError(fmt::format("Craig-Bampton: master {} ('{}') is free DOF {}, outside 0..{}", i + 1,
                                   names[i].name(), dof, n - 1));
    const auto u = static_cast<size_t>(dof);
    if (p.is_master[u])
      throw InputError(fmt::format("Craig-Bampton: master {} ('{}') repeats free DOF {} of master {} ('{}')", i + 1,
                                   names[i].name(), dof, p.local[u] + 1,
                                   names[static_cast<size_t>(p.local[u])].name()));
    p.is_master[u] = true;
    p.local[u] = static_cast<int>(i);
  }
  for (int dof = 0; dof < n; ++dof) {
    const auto u = static_cast<size_t>(dof);
    if (p.is_master[u]) continue;
    p.local[u] = static_cast<int>(p.slaves.size());
    p.slaves.push_back(dof);
  }
  return p;
}

// The slave-slave block, built column by column straight into compressed storage: at 280k DOFs
// a triplet list of K's ~50M entries would cost more memory than the factor.
Sparse slave_block(const Sparse& a, const Partition& p) {
  const auto ns = static_cast<Eigen::Index>(p.slaves.size());
  Eigen::Index nnz = 0;
  for (int dof : p.slaves)
    for (Sparse::InnerIterator it(a, dof); it; ++it) nnz += p.is_master[static_cast<size_t>(it.row())] ? 0 : 1;
  Sparse s(ns, ns);
  s.reserve(nnz);
  for (Eigen::Index j = 0; j < ns; ++j) {
    s.startVec(j);
    // Rows stay ascending: slaves are numbered in increasing free index.
    for (Sparse::InnerIterator it(a, p.slaves[static_cast<size_t>(j)]); it; ++it)
      if (!p.is_master[static_cast<size_t>(it.row())])
        s.insertBack(p.local[static_cast<size_t>(it.row())], j) = it.value();
  }
  s.finalize();
  return s;
}

// K_sm as a dense n_s x n_m block: it is the right-hand side of the constraint-mode solve anyway.
Eigen::MatrixXd slave_master_block(const Sparse& a, const std::vector<int>& masters, const Partition& p) {
  Eigen::MatrixXd b =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(p.slaves.size()), static_cast<Eigen::Index>(masters.size()));
  for (size_t i = 0; i < masters.size(); ++i)
    for (Sparse::InnerIterator it(a, masters[i]); it; ++it)
      if (!p.is_master[static_cast<size_t>(it.row())])
        b(p.local[static_cast<size_t>(it.row())], static_cast<Eigen::Index>(i)) = it.value();
  return b;
}

ModalOptions modal_options(const CraigBamptonOptions& options, int n_modes) {
  ModalOptions modal;
  modal.n_modes = n_modes;
  modal.shift_frequency_hz = options.shift_frequency_hz;
  modal.ordering = options.ordering;
  modal.eigensolver = options.eigensolver;
  return modal;
}

double eigenvalue_of(double frequency_hz) { return std::pow(2 * std::numbers::pi * frequency_hz, 2); }

// Lowest n fixed-interface modes of (K_ss, M_ss). Lanczos needs n < n_s; when every slave mode
// is kept the slave set is small enough for a dense solve, and the reduction is then exact.
ModalSolution fixed_interface_modes(const Sparse& k_ss, const Sparse& m_ss, int n_modes,
                                    const CraigBamptonOptions& options) {
  if (n_modes < k_ss.rows()) return lowest_modes(k_ss, m_ss, modal_options(options, n_modes));
  const DenseEigen<double> dense = symmetric_eigen(Eigen::MatrixXd(k_ss), Eigen::MatrixXd(m_ss));
  if (!dense.ok) throw SolverError("Craig-Bampton: dense fixed-interface eigensolve failed");
  ModalSolution sol;
  sol.eigenvalues = dense.values;
  sol.shapes = dense.vectors;  // M_ss-normalized by construction
  sol.converged_modes = static_cast<int>(sol.eigenvalues.size());
  return sol;
}

// Dense T^T A T by column chunks of A T, so the extra memory is n x chunk rather than n x r.
Eigen::MatrixXd project(const Sparse& a, const Eigen::MatrixXd& t) {
  constexpr Eigen::Index kChunk = 8;
  const Eigen::Index r = t.cols();
  Eigen::MatrixXd out(r, r);
  for (Eigen::Index j = 0; j < r; j += kChunk) {
    const Eigen::Index w = std::min(kChunk, r - j);
    const Eigen::MatrixXd at = a * t.middleCols(j, w);
    out.middleCols(j, w).noalias() = t.transpose() * at;
  }
  // Round-off leaves T^T A T asymmetric in the last bits; downstream checks and the
  // symmetric Matrix Market export expect exact symmetry.
  return 0.5 * (out + out.transpose());
}

// Psi = -K_ss^-1 K_sm (thesis eq 3.4). A K_ss that does not factor is the caller's input: slaves
// that the masters and constraints do not hold.
Eigen::MatrixXd constraint_modes(const Sparse& stiffness, const Sparse& k_ss, const std::vector<int>& masters,
                                 const Partition& p, const CraigBamptonOptions& options) {
  const std::string refusal = "Craig-Bampton: the slave stiffness K_ss cannot be factored: ";
  if (options.eigensolver == Eigensolver::slepc) {
    try {
      return -slepc_solve_spd(k_ss, slave_master_block(stiffness, masters, p));
    } catch (const NotPositiveDefinite& e) {
      throw InputError(refusal + e.what() + " (slave DOFs the masters and constraints do not hold)");
    }
  }
  SpdFactorization factor(options.ordering);
  const FactorStatus status = factor.factorize(k_ss);
  if (!status.ok) {
    const std::string where = status.weakest_column >= 0
                                  ? fmt::format("; free DOF {} is not held by the masters or constraints",
                                                p.slaves[static_cast<size_t>(status.weakest_column)])
                                  : std::string();
    throw InputError(refusal + status.message + where);
  }
  return -factor.solve(slave_master_block(stiffness, masters, p));
}

// The fixed-interface modes below cut_hz: the Sturm count of K_ss - (2 pi f)^2 M_ss.
int count_below(const Sparse& k_ss, const Sparse& m_ss, double cut_hz) {
  const InertiaCount c = eigenvalues_below(k_ss, m_ss, eigenvalue_of(cut_hz));
  if (!c.ok)
    throw SolverError(
        fmt::format("Craig-Bampton: the fixed-interface modes below {} Hz cannot be counted: {}", cut_hz, c.message));
  return c.negative;
}

// The fixed-interface modes kept: the lowest options.n_modes, or with modes_below_hz every one below
// it (on SLEPc by one slicing, whose inertias give the count; else a Sturm count first).
ModalSolution fixed_interface_band(const Sparse& k_ss, const Sparse& m_ss, const CraigBamptonOptions& options) {
  const bool band = options.modes_below_hz > 0.0;
  if (band && options.eigensolver == Eigensolver::slepc)
    return slepc_modes_below(k_ss, m_ss, eigenvalue_of(options.modes_below_hz), modal_options(options, 1));
  const int kept = band ? count_below(k_ss, m_ss, options.modes_below_hz) : options.n_modes;
  if (kept == 0) return ModalSolution{};
  ModalSolution modes = fixed_interface_modes(k_ss, m_ss, kept, options);
  modes.eigenvalues.conservativeResize(kept);  // a cluster straddling the last kept mode is cut there
  modes.shapes.conservativeResize(Eigen::NoChange, kept);
  return modes;
}

}  // namespace

ReducedModel craig_bampton(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                           const std::vector<int>& masters, const std::vector<ReducedDof>& master_names,
                           const CraigBamptonOptions& options, CraigBamptonTiming* timing) {
  const auto n = static_cast<int>(stiffness.rows());
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::invalid_argument("craig_bampton: K and M must be square and of one size");
  if (masters.size() != master_names.size())
    throw std::invalid_argument("craig_bampton: one name per master is required");
  if (options.n_modes < 0)
    throw InputError(
        fmt::format("Craig-Bampton: the number of fixed-interface modes must be >= 0, found {}", options.n_modes));
  const bool band = options.modes_below_hz > 0.0;
  auto t0 = Clock::now();
  const Partition p = partition_dofs(n, masters, master_names);
  const auto nm = static_cast<Eigen::Index>(masters.size());
  const auto ns = static_cast<Eigen::Index>(p.slaves.size());
  if (!band && options.n_modes > ns)
    throw InputError(fmt::format("Craig-Bampton: asked for {} fixed-interface modes but there are only {} slave DOFs",
                                 options.n_modes, ns));
  if (!band && nm + options.n_modes == 0) throw InputError("Craig-Bampton: no masters and no modes: nothing to keep");

  Eigen::MatrixXd psi(ns, nm);  // static constraint modes, thesis eq 3.4
  Sparse k_ss;
  if (ns > 0) {
    k_ss = slave_block(stiffness, p);
    if (nm > 0) psi = constraint_modes(stiffness, k_ss, masters, p, options);
  }
  if (timing) timing->constraint_modes_seconds = seconds_since(t0);

  t0 = Clock::now();
  ModalSolution modes;
  if (ns > 0) modes = fixed_interface_band(k_ss, slave_block(mass, p), options);
  const auto n_modes = static_cast<int>(modes.eigenvalues.size());
  if (nm + n_modes == 0)
    throw InputError(fmt::format("Craig-Bampton: no masters and no fixed-interface mode below {} Hz: nothing to keep",
                                 options.modes_below_hz));
  k_ss = Sparse();  // no longer needed; free it before the n x r products
  if (timing) timing->fixed_interface_seconds = seconds_since(t0);

  t0 = Clock::now();
  const Eigen::Index r = nm + n_modes;
  ReducedModel model;
  // T = [I 0; Psi Phi] (thesis eq 3.5), with its rows in the input's free-DOF order.
  model.recovery = Eigen::MatrixXd::Zero(n, r);
  for (Eigen::Index i = 0; i < nm; ++i) model.recovery(masters[static_cast<size_t>(i)], i) = 1.0;
  for (Eigen::Index j = 0; j < ns; ++j) {
    const int dof = p.slaves[static_cast<size_t>(j)];
    model.recovery.row(dof).head(nm) = psi.row(j);
    if (n_modes > 0) model.recovery.row(dof).tail(n_modes) = modes.shapes.row(j);
  }
  psi = Eigen::MatrixXd();
  model.stiffness = project(stiffness, model.recovery);
  model.mass = project(mass, model.recovery);
  model.dofs = master_names;
  for (int k = 1; k <= n_modes; ++k) model.dofs.push_back(ReducedDof{"", -1, k});
  model.fixed_interface_frequencies_hz = modes.eigenvalues.array().max(0.0).sqrt() / (2 * std::numbers::pi);
  if (timing) timing->projection_seconds = seconds_since(t0);
  return model;
}

int fixed_interface_count(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                          const std::vector<int>& masters, double cut_frequency_hz) {
  const std::vector<ReducedDof> names(masters.size(), ReducedDof{"master", -1, 0});
  const Partition p = partition_dofs(static_cast<int>(stiffness.rows()), masters, names);
  if (p.slaves.empty()) return 0;
  return count_below(slave_block(stiffness, p), slave_block(mass, p), cut_frequency_hz);
}

}  // namespace bb
