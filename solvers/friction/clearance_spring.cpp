#include "friction/clearance_spring.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "friction/aft_pieces.hpp"
#include "friction/illinois.hpp"

namespace bb::friction {

void validate(const ClearanceSpring& s) {
  if (!(s.gap > 0.0) || !std::isfinite(s.gap))
    throw std::invalid_argument(fmt::format("clearance spring: the gap must be positive and finite (got {})", s.gap));
  if (!(s.stiffness >= 0.0) || !std::isfinite(s.stiffness))
    throw std::invalid_argument(
        fmt::format("clearance spring: k_gap must be non-negative and finite (got {})", s.stiffness));
  if (s.springs < 1 || s.springs > 1000)
    throw std::invalid_argument(fmt::format("clearance spring: {} springs; give 1 to 1000", s.springs));
  if (s.springs > 1 && !(s.gap_max > s.gap && std::isfinite(s.gap_max)))
    throw std::invalid_argument(fmt::format(
        "clearance spring: gap_max must be finite and above the gap ({:g} m) to spread {} springs (got {:g})", s.gap,
        s.springs, s.gap_max));
  if (s.springs == 1 && s.gap_max != 0.0 && s.gap_max != s.gap)
    throw std::invalid_argument(
        fmt::format("clearance spring: one spring has one gap, not a gap_max ({:g} m)", s.gap_max));
}

std::vector<SpringShare> clearance_springs(const ClearanceSpring& s) {
  std::vector<SpringShare> out;
  const double share = s.stiffness / s.springs;
  for (int i = 0; i < s.springs; ++i) {
    const double t = s.springs == 1 ? 0.0 : static_cast<double>(i) / (s.springs - 1);
    out.push_back({i == 0 ? s.gap : s.gap * std::pow(s.gap_max / s.gap, t), share});
  }
  return out;
}

namespace {

// The force and its slope over the springs' shares, which the law keeps: a Newmark step and every
// AFT sample asks for them.
double force_of(const std::vector<SpringShare>& shares, double u) {
  double f = 0.0;
  for (const SpringShare& k : shares) {
    const double past = std::abs(u) - k.gap;
    if (past > 0.0) f += std::copysign(k.stiffness * past, u);
  }
  return f;
}

double slope_of(const std::vector<SpringShare>& shares, double u) {
  double slope = 0.0;
  for (const SpringShare& k : shares)
    if (std::abs(u) > k.gap) slope += k.stiffness;
  return slope;
}

}  // namespace

double clearance_force(const ClearanceSpring& s, double u) { return force_of(clearance_springs(s), u); }

double clearance_slope(const ClearanceSpring& s, double u) { return slope_of(clearance_springs(s), u); }

double clearance_describing_stiffness(const ClearanceSpring& s, double amplitude) {
  double k1 = 0.0;
  for (const SpringShare& k : clearance_springs(s)) {
    if (!(amplitude > k.gap)) continue;
    const double r = k.gap / amplitude;
    k1 += k.stiffness * (1.0 - 2.0 / std::numbers::pi * (std::asin(r) + r * std::sqrt(1.0 - r * r)));
  }
  return k1;
}

namespace {

class ClearanceStiffenedLaw final : public FrictionLaw {
 public:
  ClearanceStiffenedLaw(std::shared_ptr<const FrictionLaw> masing, const ClearanceSpring& spring)
      : masing_(std::move(masing)), spring_(spring) {
    if (!masing_) throw std::invalid_argument("clearance spring: no friction law to put it beside");
    if (masing_->directions() != 1)
      throw std::invalid_argument(
          fmt::format("clearance spring: the {} law has {} directions; the spring acts beside a law of one",
                      masing_->name(), masing_->directions()));
    validate(spring_);
    shares_ = clearance_springs(spring_);
  }
  std::string name() const override { return masing_->name() + " with a clearance spring"; }
  std::string describe() const override {
    if (spring_.springs == 1)
      return fmt::format("{}, in parallel with a clearance spring (gap = {:g} m, k_gap = {:g} N/m)",
                         masing_->describe(), spring_.gap, spring_.stiffness);
    return fmt::format("{}, in parallel with {} clearance springs (gaps {:g}-{:g} m, k_gap = {:g} N/m)",
                       masing_->describe(), spring_.springs, spring_.gap, spring_.gap_max, spring_.stiffness);
  }
  int directions() const override { return 1; }
  // The friction part's AFT plus the spring's, integrated exactly over the pieces where it is
  // engaged (u > gap, u < -gap; their ends bracketed by the samples and located to rounding): f is
  // linear in u there, so its coefficients are k (G u -+ gap m) with the pieces' basis integrals,
  // and its Jacobian k G, continuous in u (f vanishes at the ends). Sampling instead would put a
  // spurious quadrature term of the order of k_gap (n_t a / gap)^-2 where the kinks fall between
  // samples (1e-3 of a peak at 256 samples in the verification case).
  AftResult harmonics(const PointParameters& point, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const AftOptions& options) const override {
    AftResult r = masing_->harmonics(point, u, v, options);
    const int h = harmonics_of(u.size());
    const AftTransforms& transforms = aft_transforms(h, options.samples);
    const Eigen::VectorXd samples = transforms.synthesis * u;
    for (const SpringShare& k : shares_) {
      const BasisIntegrals above = basis_integrals(engaged(u, samples, k.gap, 1.0), h);
      const BasisIntegrals below = basis_integrals(engaged(u, samples, k.gap, -1.0), h);
      r.tangential.noalias() += k.stiffness * ((above.gram + below.gram) * u - k.gap * (above.mean - below.mean));
      r.dtangential_du.noalias() += k.stiffness * (above.gram + below.gram);
    }
    if (r.t.size() == samples.size())  // the law's whole tangential force at the samples
      for (Eigen::Index i = 0; i < samples.size(); ++i) r.t[i] += force_of(shares_, samples[i]);
    return r;
  }
  LawStep step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
               double v) const override {
    LawStep s = masing_->step(point, slider, u, v);
    s.tangential[0] += force_of(shares_, u[0]);
    s.dt_du(0, 0) += slope_of(shares_, u[0]);
    return s;
  }
  // The exact flow of shooting (timeint/piecewise_flow.cpp) knows the Jenkins pieces only.
  bool piecewise_linear() const override { return false; }
  std::vector<std::string> parameter_names() const override {
    if (spring_.springs == 1) return {"gap", "k_gap"};
    return {"gap", "gap_max", "k_gap"};
  }
  double parameter(const std::string& name) const override {
    if (name == "gap") return spring_.gap;
    if (name == "k_gap") return spring_.stiffness;
    if (name == "gap_max" && spring_.springs > 1) return spring_.gap_max;
    return FrictionLaw::parameter(name);
  }
  std::shared_ptr<const FrictionLaw> with_parameter(const std::string& name, double value) const override {
    ClearanceSpring s = spring_;
    if (name == "gap")
      s.gap = value;
    else if (name == "k_gap")
      s.stiffness = value;
    else if (name == "gap_max" && spring_.springs > 1)
      s.gap_max = value;
    else
      return FrictionLaw::with_parameter(name, value);
    return std::make_shared<ClearanceStiffenedLaw>(masing_, s);
  }
  std::shared_ptr<const FrictionLaw> later_sliders_law() const override { return masing_; }

 private:
  // The pieces of [0, 2 pi] where sign u > gap (sign = +-1), from the samples of u at theta_k =
  // 2 pi k / n: a sign change of sign u - gap between two samples is an end.
  static std::vector<std::pair<double, double>> engaged(const Eigen::VectorXd& u, const Eigen::VectorXd& samples,
                                                        double gap, double sign) {
    const int h = harmonics_of(u.size());
    const auto excess = [&](double theta) {
      double value = u[0];
      for (int j = 1; j <= h; ++j) value += u[2 * j - 1] * std::cos(j * theta) + u[2 * j] * std::sin(j * theta);
      return sign * value - gap;
    };
    const Eigen::Index n = samples.size();
    const double step = 2.0 * std::numbers::pi / static_cast<double>(n);
    std::vector<std::pair<double, double>> pieces;
    double start = sign * samples[0] > gap ? 0.0 : -1.0;  // -1: not engaged
    for (Eigen::Index k = 0; k < n; ++k) {
      const double a = step * static_cast<double>(k), b = step * static_cast<double>(k + 1);
      const double fa = sign * samples[k] - gap, fb = sign * samples[(k + 1) % n] - gap;
      if ((fa > 0.0) == (fb > 0.0)) continue;
      const double end = illinois(excess, a, b, fa, fb);
      if (fb > 0.0) {
        start = end;
      } else {
        pieces.emplace_back(start, end);
        start = -1.0;
      }
    }
    if (start >= 0.0) pieces.emplace_back(start, 2.0 * std::numbers::pi);
    return pieces;
  }

  std::shared_ptr<const FrictionLaw> masing_;
  ClearanceSpring spring_;
  std::vector<SpringShare> shares_;
};

}  // namespace

std::shared_ptr<const FrictionLaw> with_clearance_spring(std::shared_ptr<const FrictionLaw> masing,
                                                         const ClearanceSpring& spring) {
  return std::make_shared<ClearanceStiffenedLaw>(std::move(masing), spring);
}

}  // namespace bb::friction
