#include "friction/aft_pieces.hpp"

#include <cmath>
#include <numbers>
#include <tuple>

namespace bb::friction {
namespace {

// Signed sums over the ends of a set of pieces (+ at b, - at a) of theta, cos k theta and sin k theta
// for k = 1 .. 2H: the integrals of the basis and of the products of its functions over the pieces
// are linear in them (products of cosines and sines are sums of cos / sin (h +- g) theta), so a
// set's Gram matrix is built once from its sums instead of once per piece.
struct TrigSums {
  double theta = 0.0;
  Eigen::VectorXd c, s;  // index k: cos k theta, sin k theta (k = 0 unused)

  explicit TrigSums(int top) : c(Eigen::VectorXd::Zero(top + 1)), s(Eigen::VectorXd::Zero(top + 1)) {}
  void add(double at, double sign) {
    theta += sign * at;
    double s1 = 0.0, c1 = 0.0;
    sincos(at, &s1, &c1);  // glibc: the values of std::sin and std::cos, in one call
    double ck = 1.0, sk = 0.0;
    for (Eigen::Index k = 1; k < c.size(); ++k) {
      const double cn = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = cn;
      c[k] += sign * ck;
      s[k] += sign * sk;
    }
  }
  void add_piece(double a, double b) {
    add(b, 1.0);
    add(a, -1.0);
  }
  // int cos k = sin k / k (theta for k = 0), even in k; int sin k = -cos k / k (0 for k = 0), odd in k.
  double int_cos(int k) const { return k == 0 ? theta : s[std::abs(k)] / std::abs(k); }
  double int_sin(int k) const { return k == 0 ? 0.0 : -c[std::abs(k)] / static_cast<double>(k); }

  // (scale) int phi over the pieces.
  Eigen::VectorXd mean(const Eigen::VectorXd& scale) const {
    const int harmonics = harmonics_of(scale.size());
    Eigen::VectorXd out(scale.size());
    out[0] = scale[0] * theta;
    for (int h = 1; h <= harmonics; ++h) {
      out[2 * h - 1] = scale[2 * h - 1] * int_cos(h);
      out[2 * h] = scale[2 * h] * int_sin(h);
    }
    return out;
  }
  // diag(scale) int phi phi^T over the pieces.
  Eigen::MatrixXd gram(const Eigen::VectorXd& scale) const {
    const int harmonics = harmonics_of(scale.size());
    // int cos k and int sin k for k = -2H .. 2H, each divided once.
    const int top = 2 * harmonics;
    Eigen::VectorXd ic(2 * top + 1), is(2 * top + 1);
    for (int k = -top; k <= top; ++k) {
      ic[k + top] = int_cos(k);
      is[k + top] = int_sin(k);
    }
    const auto cos_of = [&](int k) { return ic[k + top]; };
    const auto sin_of = [&](int k) { return is[k + top]; };
    Eigen::MatrixXd g(scale.size(), scale.size());
    g(0, 0) = theta;
    for (int h = 1; h <= harmonics; ++h) {
      g(0, 2 * h - 1) = g(2 * h - 1, 0) = cos_of(h);
      g(0, 2 * h) = g(2 * h, 0) = sin_of(h);
      for (int k = 1; k <= harmonics; ++k) {
        g(2 * h - 1, 2 * k - 1) = 0.5 * (cos_of(h - k) + cos_of(h + k));                    // cos h cos k
        g(2 * h, 2 * k) = 0.5 * (cos_of(h - k) - cos_of(h + k));                            // sin h sin k
        g(2 * h - 1, 2 * k) = g(2 * k, 2 * h - 1) = 0.5 * (sin_of(h + k) + sin_of(k - h));  // cos h sin k
      }
    }
    for (Eigen::Index i = 0; i < g.rows(); ++i) g.row(i) *= scale[i];
    return g;
  }
};

Eigen::VectorXd coefficient_scale(Eigen::Index m) {
  // c0 = (1 / 2 pi) int T, a_h = (1 / pi) int T cos h theta, b_h likewise with sin.
  Eigen::VectorXd scale = Eigen::VectorXd::Constant(m, 1.0 / std::numbers::pi);
  scale[0] *= 0.5;
  return scale;
}

}  // namespace

BasisIntegrals basis_integrals(const std::vector<std::pair<double, double>>& pieces, int harmonics) {
  TrigSums sums(2 * harmonics);
  for (const auto& [a, b] : pieces) sums.add_piece(a, b);
  const Eigen::VectorXd scale = coefficient_scale(harmonic_size(harmonics));
  return {sums.mean(scale), sums.gram(scale)};
}

// The coefficients of T and N and their derivatives from the pieces of one period. Within a piece
// T and N are linear in the trigonometric polynomials u, v (stick: kt (u - w0), slip: +-mu N, N =
// n0 + kn v), so each coefficient is a product with the basis's integral or its Gram matrix over
// the piece, both in closed form: no quadrature error. The Gram matrices enter summed per state.
void integrate_pieces(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const std::vector<Piece>& pieces, const std::vector<StuckSlider>& sliders, bool with_law,
                      AftResult& r) {
  const Eigen::Index m = u.size();
  const int top = 2 * harmonics_of(m);
  const Eigen::VectorXd scale = coefficient_scale(m);
  r.tangential = Eigen::VectorXd::Zero(m);
  r.dtangential_du = Eigen::MatrixXd::Zero(m, m);
  r.dtangential_dv = Eigen::MatrixXd::Zero(m, m);
  if (with_law) {
    r.dtangential_dlaw = Eigen::MatrixXd::Zero(m, 4);
    r.dnormal_dlaw = Eigen::MatrixXd::Zero(m, 4);
  }
  TrigSums stick(top), slip_positive(top), slip_negative(top);
  bool any_stick = false, any_positive = false, any_negative = false;
  size_t i = 0;
  while (i < pieces.size()) {
    // One run of pieces in one state (and one stuck slider).
    size_t j = i + 1;
    while (j < pieces.size() && pieces[j].state == pieces[i].state && pieces[j].slider == pieces[i].slider) ++j;
    const ContactState state = pieces[i].state;
    const double a = pieces[i].a, b = pieces[j - 1].b;
    if (state == ContactState::stick) {
      // The slider differs from run to run: its terms need the run's own mean.
      TrigSums run(harmonics_of(m));
      run.add_piece(a, b);
      const Eigen::VectorXd mean = run.mean(scale);
      const StuckSlider& sl = sliders[static_cast<size_t>(pieces[j - 1].slider)];
      r.tangential -= p.kt * sl.w * mean;
      r.dtangential_du.noalias() -= p.kt * mean * sl.dw.head(m);
      r.dtangential_dv.noalias() -= p.kt * mean * sl.dw.tail(m);
      if (with_law) {
        r.dtangential_dlaw.noalias() -= p.kt * mean * sl.dw_law;
        r.dtangential_dlaw.col(law_kt) -= sl.w * mean;
      }
      stick.add_piece(a, b);
      any_stick = true;
    } else if (state == ContactState::slip_positive) {
      slip_positive.add_piece(a, b);
      any_positive = true;
    } else if (state == ContactState::slip_negative) {
      slip_negative.add_piece(a, b);
      any_negative = true;
    }
    i = j;
  }
  // In contact: stick and both slips.
  TrigSums contact(top);
  for (const TrigSums* t : {&stick, &slip_positive, &slip_negative}) {
    contact.theta += t->theta;
    contact.c += t->c;
    contact.s += t->s;
  }
  const Eigen::MatrixXd gram = contact.gram(scale);
  const Eigen::VectorXd mean = contact.mean(scale), gram_v = gram * v;
  r.normal = p.n0 * mean + p.kn * gram_v;
  r.dnormal_dv = p.kn * gram;
  if (with_law) {
    r.dnormal_dlaw.col(law_kn) = gram_v;
    r.dnormal_dlaw.col(law_n0) = mean;
  }
  if (any_stick) {
    const Eigen::MatrixXd g = stick.gram(scale);
    const Eigen::VectorXd g_u = g * u;
    r.tangential += p.kt * g_u;
    r.dtangential_du += p.kt * g;
    if (with_law) r.dtangential_dlaw.col(law_kt) += g_u;
  }
  for (const auto& [slips, any, sign] :
       {std::tuple{&slip_positive, any_positive, 1.0}, std::tuple{&slip_negative, any_negative, -1.0}}) {
    if (!any) continue;
    const Eigen::MatrixXd g = slips->gram(scale);
    const Eigen::VectorXd g_v = g * v, mean_slip = slips->mean(scale);
    const Eigen::VectorXd normal = p.n0 * mean_slip + p.kn * g_v;
    r.tangential += sign * p.mu * normal;
    r.dtangential_dv += sign * p.mu * p.kn * g;
    if (with_law) {
      r.dtangential_dlaw.col(law_mu) += sign * normal;
      r.dtangential_dlaw.col(law_kn) += sign * p.mu * g_v;
      r.dtangential_dlaw.col(law_n0) += sign * p.mu * mean_slip;
    }
  }
}

}  // namespace bb::friction
