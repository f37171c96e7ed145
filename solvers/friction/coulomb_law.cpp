#include "friction/coulomb_law.hpp"

namespace bb::friction {

namespace {

class CoulombLaw final : public FrictionLaw {
 public:
  std::string name() const override { return "coulomb"; }
  std::string describe() const override {
    return "Coulomb (rigid stick on the exact flow; regularised by kt, the Jenkins law, in the harmonic balance "
           "and the Newmark step)";
  }
  int directions() const override { return 1; }
  AftResult harmonics(const PointParameters& point, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const AftOptions& options) const override {
    return jenkins_law()->harmonics(point, u, v, options);
  }
  LawStep step(const PointParameters& point, const Eigen::Vector2d& slider, const Eigen::Vector2d& u,
               double v) const override {
    return jenkins_law()->step(point, slider, u, v);
  }
  bool piecewise_linear() const override { return true; }
  bool rigid_stick() const override { return true; }
};

}  // namespace

const std::shared_ptr<const FrictionLaw>& coulomb_law() {
  static const std::shared_ptr<const FrictionLaw> law = std::make_shared<CoulombLaw>();
  return law;
}

}  // namespace bb::friction
