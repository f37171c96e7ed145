// The quantities of a harmonic-balance solution that the sweep, the peaks and the tables share.
#include "forced/hbm_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>

#include "frf/sweep.hpp"

namespace bb {

Eigen::VectorXcd first_harmonic(const Eigen::MatrixXd& q) {
  return q.col(1).cast<std::complex<double>>() - std::complex<double>(0.0, 1.0) * q.col(2).cast<std::complex<double>>();
}

Eigen::VectorXcd first_harmonic(const hbm::HarmonicBalance& system, const Eigen::VectorXd& x, double omega) {
  return first_harmonic(system.recover(x, omega));
}

void write_response_row(const PreparedHbm& p, const Eigen::MatrixXd& q, std::complex<double> force, Eigen::Index row,
                        Eigen::MatrixXd& amplitude, Eigen::MatrixXd& phase_deg, Eigen::MatrixXd& excursion) {
  const Eigen::VectorXcd z = first_harmonic(q);
  for (size_t r = 0; r < p.responses.size(); ++r) {
    const auto c = static_cast<Eigen::Index>(r);
    amplitude(row, c) = std::abs(z[p.responses[r]]);
    phase_deg(row, c) = std::arg(z[p.responses[r]] / force) * 180.0 / std::numbers::pi;
    excursion(row, c) = largest_excursion(q.row(p.responses[r]));
  }
}

double largest_excursion(const Eigen::RowVectorXd& c) {
  using Eigen::Index;
  const Index harmonics = (c.size() - 1) / 2;
  // cos h theta and sin h theta by the angle-addition recurrence: one sine and cosine per instant
  // (the 2H of them per instant had cost 6 % of a Table XI sweep).
  const auto x = [&](double theta) {
    const double c1 = std::cos(theta), s1 = std::sin(theta);
    double v = c[0], ch = 1.0, sh = 0.0;
    for (Index h = 1; h <= harmonics; ++h) {
      const double next = ch * c1 - sh * s1;
      sh = sh * c1 + ch * s1;
      ch = next;
      v += c[2 * h - 1] * ch + c[2 * h] * sh;
    }
    return std::abs(v);
  };
  const int n = 32 * static_cast<int>(2 * harmonics + 1);
  const double dt = 2 * std::numbers::pi / n;
  int best = 0;
  double best_value = -1.0;
  for (int i = 0; i < n; ++i)
    if (const double v = x(i * dt); v > best_value) best_value = v, best = i;
  const GoldenSearch g = golden_section_maximum([&](double t) { return std::optional<double>(x(t)); }, (best - 1) * dt,
                                                (best + 1) * dt, 40);
  return std::max(best_value, x(0.5 * (g.a + g.b)));
}

PeakValues peak_values(const PreparedHbm& p, const Eigen::VectorXcd& z, int kind) {
  if (!p.ip_oop) return {std::abs(z[p.responses.front()]), std::abs(z[p.responses.front()])};
  const auto [l, r] = *p.ip_oop;
  const double c = kind == 0 ? std::abs(z[l] + z[r]) / 2 : std::abs(z[r] - z[l]) / 2;
  return {c, std::abs(z[r])};
}

}  // namespace bb
