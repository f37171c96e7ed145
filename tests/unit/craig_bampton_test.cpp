// Craig-Bampton reduction (reduction/craig_bampton) on a plane-stress Q4 cantilever clamped at
// x = 0, its tip nodes the masters: a reduction to every DOF is the identity, the reduced
// frequencies are Rayleigh-Ritz upper bounds that fall monotonically onto the full ones as
// fixed-interface modes are added, Guyan reduction is exact for loads on the masters, the
// recovery matrix expands the reduced static solution to the full one, and the kept modes are
// those of the structure with its masters clamped. Units: SI.
#include "reduction/craig_bampton.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "mesh/mapped_quad.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

constexpr double kLength = 1.0, kHeight = 0.25;

std::vector<int> nodes_at_x(const Mesh& mesh, double x) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (std::abs(mesh.coords(n, 0) - x) < 1e-9) out.push_back(n);
  return out;
}

// A cantilever's free-DOF K and M and its tip DOFs (x and y of every node at x = L) as masters.
struct Cantilever {
  Model model;
  DofMap dofs;
  SparseMatrix k, m;
  std::vector<int> masters;
  std::vector<ReducedDof> names;
};

Cantilever make_cantilever(bool clamped = true, int nx = 12, int ny = 3) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(kLength, 0), Eigen::Vector2d(kLength, kHeight),
                  Eigen::Vector2d(0, kHeight)};
  spec.nx = nx;
  spec.ny = ny;
  Cantilever c;
  c.model.mesh = generate_mapped_quad(spec);
  c.model.section = test::steel_section(0.01);
  c.model.node_sets["clamp"] = nodes_at_x(c.model.mesh, 0.0);
  c.model.node_sets["tip"] = nodes_at_x(c.model.mesh, kLength);
  if (clamped) c.model.constraints = {{"clamp", {0, 1}, 0.0}};
  c.dofs = number_dofs(c.model);
  const GlobalMatrices global = assemble(c.model.mesh, c.model.section);
  c.k = partition(global.stiffness, c.dofs).ff;
  c.m = partition(global.mass, c.dofs).ff;
  for (int node : c.model.node_sets["tip"])
    for (int d = 0; d < 2; ++d) {
      c.masters.push_back(c.dofs.equation[static_cast<size_t>(2 * node + d)]);
      c.names.push_back({fmt::format("N{}", c.model.mesh.node_ids[static_cast<size_t>(node)]), d, 0});
    }
  return c;
}

CraigBamptonOptions with_modes(int n) {
  CraigBamptonOptions o;
  o.n_modes = n;
  o.ordering = FillOrdering::amd;
  return o;
}

// All natural frequencies [Hz] of a small dense (K, M), ascending.
Eigen::VectorXd dense_frequencies(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, m, Eigen::EigenvaluesOnly);
  return eig.eigenvalues().array().max(0.0).sqrt() / (2 * std::numbers::pi);
}

// Full static solution for a load on the master DOFs.
Eigen::VectorXd full_static(const Cantilever& c, const Eigen::VectorXd& f_masters) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(c.k.rows());
  for (size_t i = 0; i < c.masters.size(); ++i) f[c.masters[i]] = f_masters[static_cast<Eigen::Index>(i)];
  return Eigen::MatrixXd(c.k).llt().solve(f);
}

// A tip load with shear, axial pull and a couple, so that every master moves differently.
Eigen::VectorXd tip_load(const Cantilever& c) {
  Eigen::VectorXd f(static_cast<Eigen::Index>(c.masters.size()));
  for (Eigen::Index i = 0; i < f.size(); ++i) f[i] = (i % 2 == 0 ? 2.0e3 * static_cast<double>(i - 3) : -1.0e4);
  return f;
}

TEST(CraigBampton, EveryDofAMasterReproducesKAndMExactly) {
  const Cantilever c = make_cantilever();
  const auto n = static_cast<int>(c.k.rows());
  std::vector<int> masters;
  std::vector<ReducedDof> names;
  for (int i = n - 1; i >= 0; --i) {  // reversed: the reduced order must follow the masters' order
    masters.push_back(i);
    names.push_back({fmt::format("D{}", i), 0, 0});
  }
  const ReducedModel r = craig_bampton(c.k, c.m, masters, names, with_modes(0));
  ASSERT_EQ(r.size(), n);
  const Eigen::MatrixXd k = c.k, m = c.m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(r.stiffness(i, j), k(masters[i], masters[j]), 1e-12 * k.cwiseAbs().maxCoeff());
      EXPECT_NEAR(r.mass(i, j), m(masters[i], masters[j]), 1e-12 * m.cwiseAbs().maxCoeff());
    }
  EXPECT_EQ(r.fixed_interface_frequencies_hz.size(), 0);
}

TEST(CraigBampton, FrequenciesConvergeFromAboveAsFixedInterfaceModesAreAdded) {
  const Cantilever c = make_cantilever();
  const Eigen::VectorXd full = dense_frequencies(Eigen::MatrixXd(c.k), Eigen::MatrixXd(c.m));
  const int n_slaves = static_cast<int>(c.k.rows() - static_cast<Eigen::Index>(c.masters.size()));
  constexpr int kChecked = 6;  // fewer than the 8 masters: every reduction has that many frequencies
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(kChecked, INFINITY);
  for (int modes : {0, 1, 2, 4, 8, 16, 32, n_slaves}) {
    const ReducedModel r = craig_bampton(c.k, c.m, c.masters, c.names, with_modes(modes));
    const Eigen::VectorXd f = dense_frequencies(r.stiffness, r.mass).head(kChecked);
    for (int i = 0; i < kChecked; ++i) {
      // Rayleigh-Ritz on nested subspaces: an upper bound that can only fall as modes are added.
      EXPECT_GE(f[i], full[i] * (1 - 1e-10)) << modes << " modes, frequency " << i + 1;
      EXPECT_LE(f[i], previous[i] * (1 + 1e-9)) << modes << " modes, frequency " << i + 1;
    }
    previous = f;
  }
  // Every slave mode kept: T spans the whole space and the reduction is exact.
  for (int i = 0; i < kChecked; ++i) EXPECT_NEAR(previous[i] / full[i], 1.0, 1e-9) << "frequency " << i + 1;
  // ... and on the way there the error closes: Guyan alone misses the first bending frequency
  // by far more than 16 fixed-interface modes do.
  const auto first = [&](int modes) {
    const ReducedModel r = craig_bampton(c.k, c.m, c.masters, c.names, with_modes(modes));
    return dense_frequencies(r.stiffness, r.mass)[0] / full[0] - 1.0;
  };
  EXPECT_LT(first(16), 0.01 * first(0));
}

TEST(CraigBampton, GuyanReductionGivesTheFullStaticDisplacementsOfTheMasters) {
  const Cantilever c = make_cantilever();
  const Eigen::VectorXd f = tip_load(c);
  const Eigen::VectorXd u = full_static(c, f);
  for (int modes : {0, 6}) {  // modes carry no load from the masters, so they change nothing here
    const ReducedModel r = craig_bampton(c.k, c.m, c.masters, c.names, with_modes(modes));
    Eigen::VectorXd f_reduced = Eigen::VectorXd::Zero(r.size());
    f_reduced.head(f.size()) = f;
    const Eigen::VectorXd q = r.stiffness.llt().solve(f_reduced);
    for (size_t i = 0; i < c.masters.size(); ++i)
      EXPECT_NEAR(q[static_cast<Eigen::Index>(i)], u[c.masters[i]], 1e-10 * u.cwiseAbs().maxCoeff())
          << modes << " modes, master " << c.names[i].name();
  }
}

TEST(CraigBampton, RecoveryExpandsTheReducedStaticSolutionToTheFullOne) {
  const Cantilever c = make_cantilever();
  const Eigen::VectorXd f = tip_load(c);
  const Eigen::VectorXd u = full_static(c, f);
  const ReducedModel r = craig_bampton(c.k, c.m, c.masters, c.names, with_modes(4));
  ASSERT_EQ(r.recovery.rows(), c.k.rows());
  ASSERT_EQ(r.recovery.cols(), r.size());
  for (size_t i = 0; i < c.masters.size(); ++i) {
    const Eigen::RowVectorXd unit = Eigen::RowVectorXd::Unit(r.size(), static_cast<Eigen::Index>(i));
    EXPECT_EQ(r.recovery.row(c.masters[i]), unit) << "master " << c.names[i].name();
  }
  Eigen::VectorXd f_reduced = Eigen::VectorXd::Zero(r.size());
  f_reduced.head(f.size()) = f;
  const Eigen::VectorXd expanded = r.recovery * r.stiffness.llt().solve(f_reduced);
  EXPECT_LT((expanded - u).cwiseAbs().maxCoeff(), 1e-10 * u.cwiseAbs().maxCoeff());
}

TEST(CraigBampton, FixedInterfaceModesAreThoseOfTheStructureWithItsMastersClamped) {
  const Cantilever c = make_cantilever();
  constexpr int kModes = 5;
  const ReducedModel r = craig_bampton(c.k, c.m, c.masters, c.names, with_modes(kModes));
  // The same cantilever with its tip clamped too, numbered and assembled independently.
  Cantilever clamped = make_cantilever();
  clamped.model.constraints.push_back({"tip", {0, 1}, 0.0});
  clamped.dofs = number_dofs(clamped.model);
  const GlobalMatrices global = assemble(clamped.model.mesh, clamped.model.section);
  const Eigen::VectorXd expected = dense_frequencies(Eigen::MatrixXd(partition(global.stiffness, clamped.dofs).ff),
                                                     Eigen::MatrixXd(partition(global.mass, clamped.dofs).ff));
  ASSERT_EQ(r.fixed_interface_frequencies_hz.size(), kModes);
  const auto nm = static_cast<Eigen::Index>(c.masters.size());
  for (int k = 0; k < kModes; ++k) {
    EXPECT_NEAR(r.fixed_interface_frequencies_hz[k] / expected[k], 1.0, 1e-8) << "mode " << k + 1;
    EXPECT_EQ(r.dofs[static_cast<size_t>(nm + k)], (ReducedDof{"", -1, k + 1}));
    // Mass-normalized modes: the modal block of K is diag(w^2) and of M the identity.
    const double omega = 2 * std::numbers::pi * r.fixed_interface_frequencies_hz[k];
    EXPECT_NEAR(r.stiffness(nm + k, nm + k) / (omega * omega), 1.0, 1e-8);
    EXPECT_NEAR(r.mass(nm + k, nm + k), 1.0, 1e-8);
  }
  // Constraint modes are K-orthogonal to fixed-interface modes (K_ss Psi = -K_sm).
  const double k_scale = r.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LT(r.stiffness.topRightCorner(nm, kModes).cwiseAbs().maxCoeff(), 1e-9 * k_scale);
}

std::string input_error(const Cantilever& c, const std::vector<int>& masters, const std::vector<ReducedDof>& names,
                        int modes) {
  try {
    craig_bampton(c.k, c.m, masters, names, with_modes(modes));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(CraigBampton, RejectsARepeatedMaster) {
  const Cantilever c = make_cantilever();
  std::vector<int> masters = c.masters;
  std::vector<ReducedDof> names = c.names;
  masters.push_back(masters[1]);
  names.push_back({"again", 0, 0});
  const std::string message = input_error(c, masters, names, 2);
  EXPECT_NE(message.find("repeats free DOF"), std::string::npos) << message;
  EXPECT_NE(message.find(c.names[1].name()), std::string::npos) << message;
}

TEST(CraigBampton, RejectsAMasterOutsideTheFreeDofs) {
  const Cantilever c = make_cantilever();
  for (int bad : {-1, static_cast<int>(c.k.rows())}) {
    std::vector<int> masters = c.masters;
    masters[2] = bad;
    const std::string message = input_error(c, masters, c.names, 2);
    EXPECT_NE(message.find("outside 0.."), std::string::npos) << message;
    EXPECT_NE(message.find(c.names[2].name()), std::string::npos) << message;
  }
}

TEST(CraigBampton, RejectsMoreModesThanSlaveDofs) {
  const Cantilever c = make_cantilever();
  const int n_slaves = static_cast<int>(c.k.rows()) - static_cast<int>(c.masters.size());
  const std::string message = input_error(c, c.masters, c.names, n_slaves + 1);
  EXPECT_NE(message.find("only " + std::to_string(n_slaves) + " slave DOFs"), std::string::npos) << message;
}

TEST(CraigBampton, RejectsSlavesThatTheMastersDoNotHold) {
  // Unclamped, and one master direction only: the slaves can still translate in y and rotate.
  const Cantilever c = make_cantilever(false);
  const std::string message = input_error(c, {c.masters[0]}, {c.names[0]}, 0);
  EXPECT_NE(message.find("K_ss cannot be factored"), std::string::npos) << message;
}

}  // namespace
}  // namespace bb
