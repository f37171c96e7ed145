// Cyclic symmetry: a ring of spring-mass oscillators against its closed form, and a bladed-disk
// sector against the whole disk built from it (frequencies per nodal diameter, completeness counts).
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assembly/free_system.hpp"
#include "bladed_disk_sector_fixture.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "cyclic/cyclic_campbell.hpp"
#include "cyclic/cyclic_modes.hpp"
#include "cyclic/whole_disk.hpp"
#include "ffrf/rotating_body.hpp"
#include "linalg/inertia.hpp"

namespace bb {
namespace {

// One sector of a ring of N masses m, each grounded by k0 and coupled to the next by kc: the
// sector holds its own mass (DOF 0, left face) and the coupling spring's far end (DOF 1, the next
// sector's mass: right face).
struct OscillatorRing {
  double m = 2.0, k0 = 3.0e4, kc = 5.0e4;
  Eigen::SparseMatrix<double> K, M;
  CyclicDofs cyclic;

  explicit OscillatorRing(int sectors) {
    Eigen::MatrixXd k(2, 2), mm = Eigen::MatrixXd::Zero(2, 2);
    k << k0 + kc, -kc, -kc, kc;
    mm(0, 0) = m;
    K = k.sparseView();
    M = mm.sparseView();
    cyclic.sectors = sectors;
    cyclic.dim = 1;
    cyclic.rotation = Eigen::MatrixXd::Identity(1, 1);
    cyclic.left = {0};
    cyclic.right = {1};
  }
  // Den Hartog / any text on periodic structures: w_k^2 = (k0 + 4 kc sin^2(k pi / N)) / m.
  double closed_form(int k) const { return (k0 + 4 * kc * std::pow(std::sin(k * kPi / cyclic.sectors), 2)) / m; }
};

TEST(CyclicSymmetry, RingOfOscillatorsHasTheClosedFormPerNodalDiameter) {
  for (int N : {5, 6, 12}) {
    const OscillatorRing ring(N);
    for (int k = 0; 2 * k <= N; ++k) {
      const CyclicProjection p = cyclic_projection(2, ring.cyclic, k);
      const Eigen::MatrixXd Kk = Eigen::MatrixXd(project(ring.K, p)), Mk = Eigen::MatrixXd(project(ring.M, p));
      const bool pair = k != 0 && 2 * k != N;
      ASSERT_EQ(Kk.rows(), pair ? 2 : 1) << "N " << N << " k " << k;
      // The cosine and sine parts do not couple and carry the same frequency.
      const Eigen::MatrixXd expected = ring.closed_form(k) * Mk;
      EXPECT_LT((Kk - expected).norm(), 1e-9 * Kk.norm()) << "N " << N << " k " << k;
      EXPECT_NEAR(Mk(0, 0), ring.m, 1e-12);
    }
  }
}

// The travelling wave's complex amplitude: one real frequency per nodal diameter, no pair.
TEST(CyclicSymmetry, RingTravellingWaveIsOneHermitianUnknownWithTheClosedForm) {
  for (int N : {5, 6, 12})
    for (int k = 0; 2 * k <= N; ++k) {
      const OscillatorRing ring(N);
      const auto T = complex_cyclic_projection(2, ring.cyclic, 2 * kPi * k / N);
      const Eigen::MatrixXcd Kk = Eigen::MatrixXcd(project(ring.K, T)), Mk = Eigen::MatrixXcd(project(ring.M, T));
      ASSERT_EQ(Kk.rows(), 1);
      EXPECT_NEAR(std::abs(Kk(0, 0) - ring.closed_form(k) * Mk(0, 0)), 0.0, 1e-9 * std::abs(Kk(0, 0)))
          << "N " << N << " k " << k;
      EXPECT_NEAR(Mk(0, 0).real(), ring.m, 1e-12);
    }
}

TEST(CyclicSymmetry, RingSpectrumIsTheUnionOfTheNodalDiametersTwiceForPairs) {
  const int N = 7;
  const OscillatorRing ring(N);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  for (int j = 0; j < N; ++j) {
    K(j, j) += ring.k0 + 2 * ring.kc;
    K(j, (j + 1) % N) -= ring.kc;
    K((j + 1) % N, j) -= ring.kc;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> whole(K / ring.m);
  std::vector<double> union_of_diameters;
  for (int k = 0; 2 * k <= N; ++k)
    for (int copy = 0; copy < (k == 0 || 2 * k == N ? 1 : 2); ++copy) union_of_diameters.push_back(ring.closed_form(k));
  std::sort(union_of_diameters.begin(), union_of_diameters.end());
  ASSERT_EQ(union_of_diameters.size(), static_cast<size_t>(N));
  for (int i = 0; i < N; ++i)
    EXPECT_NEAR(whole.eigenvalues()[i], union_of_diameters[static_cast<size_t>(i)], 1e-9 * K.norm());
}

TEST(CyclicSymmetry, NodalDiameterOutsideTheRangeIsRefused) {
  const OscillatorRing ring(6);
  EXPECT_THROW(cyclic_projection(2, ring.cyclic, 4), InputError);
  EXPECT_THROW(cyclic_projection(2, ring.cyclic, -1), InputError);
}

TEST(CyclicSymmetry, BladedDiskSectorFacesMatchByTheSectorRotation) {
  const Model m = sector_model(6);
  const SectorFaces faces =
      pair_sector_faces(m.mesh, m.node_sets.at("cyclic_left"), m.node_sets.at("cyclic_right"), 6, 1e-9, "test");
  EXPECT_EQ(faces.left.size(), m.node_sets.at("cyclic_left").size());
  EXPECT_GT(faces.left.size(), 10u);
  // Pairing against the wrong sector count names a node that has no partner.
  EXPECT_THROW(pair_sector_faces(m.mesh, m.node_sets.at("cyclic_left"), m.node_sets.at("cyclic_right"), 7, 1e-9, "t"),
               InputError);
}

// The whole disk's spectrum is the union of the sector's nodal diameters (twice for 0 < k < N/2),
// and its Sturm count at any frequency the sum of theirs.
TEST(CyclicSymmetry, SectorModesEqualTheWholeDisksPerNodalDiameter) {
  const int N = 6, families = 4;
  const SectorSystem t(N);
  const Model& sector = t.model;
  const FreeSystem& s = t.system;
  const CyclicDofs& cyclic = t.cyclic;
  std::vector<double> union_hz;
  double cut = INFINITY;
  ModalOptions options;
  std::vector<NodalDiameterModes> per_diameter;
  for (int k = 0; 2 * k <= N; ++k) {
    per_diameter.push_back(nodal_diameter_modes(s.stiffness, s.mass, cyclic, k, families, options));
    const NodalDiameterModes& nd = per_diameter.back();
    ASSERT_GE(nd.frequencies_hz.size(), families);
    EXPECT_EQ(nd.pairs, k != 0 && 2 * k != N);
    cut = std::min(cut, nd.frequencies_hz[families - 1]);
    for (Eigen::Index f = 0; f < nd.frequencies_hz.size(); ++f)
      for (int c = 0; c < (nd.pairs ? 2 : 1); ++c) union_hz.push_back(nd.frequencies_hz[f]);
  }
  std::sort(union_hz.begin(), union_hz.end());
  const double below = 0.999 * cut;
  const auto n_below = std::count_if(union_hz.begin(), union_hz.end(), [&](double f) { return f < below; });
  ASSERT_GE(n_below, 2 * N);

  const Model whole = whole_from_sector(sector, N, 1e-9);
  ASSERT_EQ(whole.mesh.n_nodes(), N * (sector.mesh.n_nodes() - static_cast<int>(t.faces.left.size())));
  const FreeSystem w = assemble_free_system(whole);
  options.n_modes = static_cast<int>(n_below);
  const ModalSolution all = lowest_modes(w.stiffness, w.mass, options);
  for (Eigen::Index i = 0; i < n_below; ++i) {
    const double f = std::sqrt(all.eigenvalues[i]) / (2 * kPi);
    EXPECT_NEAR(f, union_hz[static_cast<size_t>(i)], 1e-8 * f) << "mode " << i + 1;
  }
  // Completeness: the whole disk's count equals the nodal diameters' counts summed with multiplicity.
  const double sigma = std::pow(2 * kPi * below, 2);
  const InertiaCount whole_count = eigenvalues_below(w.stiffness, w.mass, sigma);
  ASSERT_TRUE(whole_count.ok);
  int sum = 0;
  for (int k = 0; 2 * k <= N; ++k) {
    const int c = nodal_diameter_count(s.stiffness, s.mass, cyclic, k, below);
    ASSERT_GE(c, 0);
    sum += (k != 0 && 2 * k != N ? 2 : 1) * c;
  }
  EXPECT_EQ(sum, whole_count.negative);
  EXPECT_EQ(sum, n_below);
}

// Turning at 1500 rad/s: the sector's pre-stressed, spin-softened families per nodal diameter are
// the whole disk's (its own centrifugal deflection, K_sigma1 and M_p from ffrf::build_rotating_body).
TEST(CyclicSymmetry, CampbellOfTheSectorIsTheWholeDisksAtSpeed) {
  const int N = 6, families = 3;
  const SectorSystem t(N);
  const double speed = 1500.0;
  const CyclicCampbell c =
      cyclic_campbell(t.model, t.system, t.cyclic, {0.0, speed}, {0, 1, 2, 3}, families, ModalOptions{}, 2);
  std::vector<double> union_hz;
  double cut = INFINITY;
  for (size_t d = 0; d < 4; ++d) {
    EXPECT_GT(c.frequencies_hz[d](1, 0), c.frequencies_hz[d](0, 0)) << "the blade stiffens with speed, ND " << d;
    cut = std::min(cut, c.frequencies_hz[d](1, families - 1));
    for (Eigen::Index f = 0; f < families; ++f)
      for (int copy = 0; copy < (d == 0 || d == 3 ? 1 : 2); ++copy) union_hz.push_back(c.frequencies_hz[d](1, f));
  }
  std::sort(union_hz.begin(), union_hz.end());
  const auto n_below = std::count_if(union_hz.begin(), union_hz.end(), [&](double f) { return f < 0.999 * cut; });
  ASSERT_GE(n_below, N);
  const ffrf::RotatingBody whole = ffrf::build_rotating_body(whole_from_sector(t.model, N, 1e-9));
  const Eigen::SparseMatrix<double> k =
      whole.stiffness + speed * speed * (whole.geometric_stiffness - whole.projected_mass);
  ModalOptions options;
  options.n_modes = static_cast<int>(n_below);
  const ModalSolution all = lowest_modes(k, whole.mass, options);
  for (Eigen::Index i = 0; i < n_below; ++i) {
    const double f = std::sqrt(all.eigenvalues[i]) / (2 * kPi);
    EXPECT_NEAR(f, union_hz[static_cast<size_t>(i)], 1e-8 * f) << "mode " << i + 1;
  }
  // Engine order 2 excites ND 2 (and EO 4 folds onto ND 2 as well on six sectors).
  EXPECT_EQ(excited_nodal_diameter(4, N), 2);
  EXPECT_EQ(excited_nodal_diameter(7, N), 1);
}

TEST(CyclicSymmetry, ImpossibleDiskIsRefusedByName) {
  BladedDiskDimensions d;
  d.sectors = 6;  // the default pitch and depth leave no bore
  try {
    bladed_disk_sector(d, ElementType::hex8);
    FAIL() << "no error";
  } catch (const DimensionError& e) {
    EXPECT_EQ(e.name(), "disk_depth");
  }
}

}  // namespace
}  // namespace bb
