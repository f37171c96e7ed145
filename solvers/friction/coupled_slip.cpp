#include "friction/coupled_slip.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bb::friction {

LawStep coupled_slip_step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
                          double v) {
  LawStep out;
  out.normal = std::max(point.n0 + point.kn * v, 0.0);
  if (out.normal <= 0.0) {
    out.normal = 0.0;
    out.slider = u;
    out.state = ContactState::lift_off;
    return out;
  }
  out.dn_dv = point.kn;
  const double limit = point.mu * out.normal;
  const Eigen::Vector2d trial = point.kt * (u - slider);
  const double size = trial.norm();
  if (size < limit) {
    out.tangential = trial;
    out.slider = slider;
    out.dt_du = point.kt * Eigen::Matrix2d::Identity();
    return out;
  }
  // A frictionless contact (limit 0) slips with T = 0 whatever the direction: take x's.
  const Eigen::Vector2d n = size > 0.0 ? Eigen::Vector2d(trial / size) : Eigen::Vector2d::UnitX();
  out.tangential = limit * n;
  out.slider = u - out.tangential / point.kt;
  out.state = ContactState::slip_positive;
  if (size > 0.0) out.dt_du = limit * point.kt / size * (Eigen::Matrix2d::Identity() - n * n.transpose());
  out.dt_dv = point.mu * point.kn * n;
  return out;
}

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The march and its chain rule over the inputs x = [u1; u2; v] (3m): dw, the slider's 2 x 3m
// derivative, carried through every period from 0 as aft_jenkins carries its row (friction/aft.cpp):
//   lift-off: dT = 0,                                   dw = du_k
//   stick:    dT = kt (du_k - dw),                      dw unchanged
//   slip:     dT = (mu N / |T*|)(I - n n^T) kt (du_k - dw) + mu n dN,   dw = du_k - dT / kt
AftResult march(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                const AftOptions& options) {
  const Eigen::Index m = v.size();
  const int harmonics = harmonics_of(m);
  const int n = options.samples;
  const AftTransforms& transforms = aft_transforms(harmonics, n);
  const RowMajor& synthesis = transforms.synthesis;
  const Eigen::MatrixXd& analysis = transforms.analysis;
  const Eigen::VectorXd u1 = synthesis * u.head(m), u2 = synthesis * u.tail(m);

  AftResult r;
  r.u = u1;
  r.u_2 = u2;
  r.v = synthesis * v;
  r.t.resize(n);
  r.n.resize(n);
  r.w.resize(n);
  r.state.assign(static_cast<size_t>(n), ContactState::stick);
  RowMajor t1_samples(n, 1), t2_samples(n, 1);
  RowMajor dt1 = RowMajor::Zero(n, 3 * m), dt2 = RowMajor::Zero(n, 3 * m), dn = RowMajor::Zero(n, 3 * m);
  RowMajor dw = RowMajor::Zero(2, 3 * m), du = RowMajor::Zero(2, 3 * m), dt(2, 3 * m);
  Eigen::RowVectorXd dvk(3 * m);  // dv_k where the contact is closed

  Eigen::Vector2d slider(options.initial_slider, 0.0);
  double reach = 0.0;
  for (int k = 0; k < n; ++k) reach = std::max(reach, std::hypot(u1[k], u2[k]));
  const double scale = reach + p.mu * std::max(p.n0 + p.kn * r.v.maxCoeff(), 0.0) / p.kt;
  for (int period = 1; period <= options.max_periods; ++period) {
    const Eigen::Vector2d start = slider;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d uk(u1[k], u2[k]);
      const LawStep s = coupled_slip_step(p, slider, uk, r.v[k]);
      du.block(0, 0, 1, m) = synthesis.row(k);
      du.block(1, m, 1, m) = synthesis.row(k);
      dvk.setZero();
      if (s.normal > 0.0) dvk.tail(m) = synthesis.row(k);
      switch (s.state) {
        case ContactState::lift_off:
          dt.setZero();
          dw = du;
          break;
        case ContactState::stick:
          dt.noalias() = p.kt * (du - dw);
          break;
        default:
          // s.dt_du already holds (mu N / |T*|)(I - n n^T) kt and s.dt_dv = mu kn n.
          dt.noalias() = s.dt_du * (du - dw);
          dt.noalias() += s.dt_dv * dvk;
          dw = du - dt / p.kt;
          break;
      }
      slider = s.slider;
      t1_samples(k, 0) = s.tangential[0];
      t2_samples(k, 0) = s.tangential[1];
      r.t[k] = s.tangential[0];
      r.n[k] = s.normal;
      r.w[k] = s.slider[0];
      r.state[static_cast<size_t>(k)] = s.state;
      dt1.row(k) = dt.row(0);
      dt2.row(k) = dt.row(1);
      dn.row(k) = p.kn * dvk;
    }
    r.periods = period;
    r.closure_mismatch = (slider - start).norm();
    if (period >= 2 && r.closure_mismatch <= options.closure_tolerance * scale) {
      r.closed = true;
      break;
    }
  }

  r.tangential.resize(2 * m);
  r.tangential.head(m) = analysis * t1_samples;
  r.tangential.tail(m) = analysis * t2_samples;
  r.normal = analysis * r.n;
  const Eigen::MatrixXd c1 = analysis * dt1, c2 = analysis * dt2;
  r.dtangential_du.resize(2 * m, 2 * m);
  r.dtangential_du << c1.leftCols(2 * m), c2.leftCols(2 * m);
  r.dtangential_dv.resize(2 * m, m);
  r.dtangential_dv << c1.rightCols(m), c2.rightCols(m);
  r.dnormal_dv = (analysis * dn).rightCols(m);
  return r;
}

class CoupledSlipLaw final : public FrictionLaw {
 public:
  std::string name() const override { return "coupled_slip"; }
  std::string describe() const override {
    return "coupled slip (one slider in the tangent plane, circular Coulomb limit |T| <= mu N; sampled AFT)";
  }
  int directions() const override { return 2; }
  AftResult harmonics(const PointParameters& point, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const AftOptions& options) const override {
    checked_aft_inputs(point, u, v, options, 2);
    if (options.law_derivatives) throw std::invalid_argument("coupled_slip has no law derivatives (sensitivities)");
    return march(point, u, v, options);
  }
  LawStep step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
               double v) const override {
    return coupled_slip_step(point, slider, u, v);
  }
  bool piecewise_linear() const override { return false; }
};

}  // namespace

const std::shared_ptr<const FrictionLaw>& coupled_slip_law() {
  static const std::shared_ptr<const FrictionLaw> law = std::make_shared<CoupledSlipLaw>();
  return law;
}

}  // namespace bb::friction
