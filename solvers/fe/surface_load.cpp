// Consistent nodal forces of facet loads (see the header). SI units.
#include "fe/surface_load.hpp"

#include "fe/face_shape.hpp"
#include "fe/gauss_abscissae.hpp"

namespace bb::fe {
namespace {

template <int N, int G>
Eigen::Matrix<double, 3 * N, 1> face_load(const Eigen::Matrix<double, N, 3>& xyz, double pressure,
                                          const Eigen::Vector3d& traction, const double (&x)[G], const double (&w)[G]) {
  Eigen::Matrix<double, 3 * N, 1> f = Eigen::Matrix<double, 3 * N, 1>::Zero();
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      Eigen::Matrix<double, N, 1> n;
      Eigen::Matrix<double, 2, N> dn;
      face_shape<N>(x[i], x[j], n, dn);
      const Eigen::Matrix<double, 2, 3> tangents = dn * xyz;  // rows dx/dxi, dx/deta
      const Eigen::Vector3d area = tangents.row(0).transpose().cross(tangents.row(1).transpose());  // n dA per dxi deta
      const Eigen::Vector3d t = w[i] * w[j] * (traction * area.norm() - pressure * area);
      for (int a = 0; a < N; ++a) f.template segment<3>(3 * a) += n[a] * t;
    }
  return f;
}

}  // namespace

Eigen::Matrix<double, 4, 1> edge2_load(const Eigen::Matrix<double, 2, 2>& xy, double thickness, double pressure,
                                       const Eigen::Vector2d& traction) {
  const Eigen::Vector2d d = (xy.row(1) - xy.row(0)).transpose();
  const Eigen::Vector2d normal_length(d.y(), -d.x());  // outward normal times the length
  const Eigen::Vector2d half = 0.5 * thickness * (traction * d.norm() - pressure * normal_length);
  Eigen::Matrix<double, 4, 1> f;
  f << half, half;
  return f;
}

Eigen::Matrix<double, 12, 1> quad4_face_load(const Eigen::Matrix<double, 4, 3>& xyz, double pressure,
                                             const Eigen::Vector3d& traction) {
  static constexpr double x[2] = {-kG2, kG2}, w[2] = {1.0, 1.0};
  return face_load<4, 2>(xyz, pressure, traction, x, w);
}

Eigen::Matrix<double, 24, 1> quad8_face_load(const Eigen::Matrix<double, 8, 3>& xyz, double pressure,
                                             const Eigen::Vector3d& traction) {
  static constexpr double x[3] = {-kG3, 0.0, kG3}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  return face_load<8, 3>(xyz, pressure, traction, x, w);
}

}  // namespace bb::fe
