#include "friction/masing.hpp"

#include <algorithm>
#include <stdexcept>

#include "friction/friction_law.hpp"

namespace bb::friction {

double SliderDistribution::parameter(const std::string& name) const {
  throw_no_parameter("law " + describe(), name, parameter_names());
}

std::shared_ptr<const SliderDistribution> SliderDistribution::with_parameter(const std::string& name, double) const {
  throw_no_parameter("law " + describe(), name, parameter_names());
}

std::vector<PointParameters> parallel_sliders(const PointParameters& point, const SliderDistribution* distribution) {
  if (!distribution) return {point};
  std::vector<PointParameters> out;
  for (const SliderShare& s : distribution->shares())
    out.push_back({.kn = s.load * point.kn, .kt = s.stiffness * point.kt, .mu = point.mu, .n0 = s.load * point.n0});
  return out;
}

AftResult aft_parallel(const PointParameters& point, const SliderDistribution* distribution, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v, const AftOptions& options) {
  if (!distribution) return aft_jenkins(point, u, v, options);
  const std::vector<SliderShare> shares = distribution->shares();
  const std::vector<PointParameters> sliders = parallel_sliders(point, distribution);
  if (sliders.empty()) throw std::invalid_argument("friction law: no sliders");
  AftResult sum;
  for (size_t i = 0; i < sliders.size(); ++i) {
    AftResult r = aft_jenkins(sliders[i], u, v, options);
    if (r.dtangential_dlaw.size() > 0) {
      // Chain rule to the point's parameters: kt_i = c_i kt, kn_i = s_i kn, N0_i = s_i N0, mu_i = mu.
      const Eigen::Vector4d scale(shares[i].load, shares[i].stiffness, 1.0, shares[i].load);
      r.dtangential_dlaw = r.dtangential_dlaw * scale.asDiagonal();
      r.dnormal_dlaw = r.dnormal_dlaw * scale.asDiagonal();
    }
    if (i == 0) {
      sum = std::move(r);
      continue;
    }
    sum.tangential += r.tangential;
    sum.normal += r.normal;
    sum.dtangential_du += r.dtangential_du;
    sum.dtangential_dv += r.dtangential_dv;
    sum.dnormal_dv += r.dnormal_dv;
    if (r.dtangential_dlaw.size() > 0) {
      sum.dtangential_dlaw += r.dtangential_dlaw;
      sum.dnormal_dlaw += r.dnormal_dlaw;
    }
    sum.t += r.t;
    sum.n += r.n;
    sum.periods = std::max(sum.periods, r.periods);
    sum.closed = sum.closed && r.closed;
    sum.closure_mismatch = std::max(sum.closure_mismatch, r.closure_mismatch);
  }
  return sum;
}

}  // namespace bb::friction
