// Each element type's formulas in one row: its node count and dimension, its Gauss points, and its
// stiffness, consistent mass, Gauss-point stresses, extrapolation to the nodes and geometric
// stiffness (fe/plane_stress.hpp, fe/solid.hpp, fe/initial_stress.hpp, fe/stress_recovery.hpp).
// Its data (name, topology, Gmsh and CalculiX names, work per row) is its row in
// mesh/element_topology.cpp. Every loop over a mesh's blocks reaches the formulas through
// with_element, whose switch is the one over element types that needs them (-Wswitch flags a
// type without a row): a new element is a struct here, its data row, and its formulas with their
// test.
#pragma once
#include <utility>

#include "fe/initial_stress.hpp"
#include "fe/plane_stress.hpp"
#include "fe/solid.hpp"
#include "fe/stress_recovery.hpp"
#include "mesh/mesh.hpp"

namespace bb {

// What a plane element integrates over (its section) and what a solid does (its material).
struct ElementMaterials {
  const fe::PlaneSection& plane;
  const fe::SolidMaterial& solid;
};

// The rows, one per element type.
namespace elements {

using namespace fe;

struct Q4 {
  static constexpr ElementType type = ElementType::q4;
  static constexpr int nodes = 4, dim = 2, points = 4;
  static Matrix8 stiffness(const Q4Coords& x, const ElementMaterials& m) { return q4_stiffness(x, m.plane); }
  static Matrix8 mass(const Q4Coords& x, const ElementMaterials& m) { return q4_consistent_mass(x, m.plane); }
  static Q4PointStresses point_stresses(const Q4Coords& x, const Eigen::Matrix<double, 8, 1>& u,
                                        const ElementMaterials& m) {
    return q4_point_stresses(x, u, m.plane);
  }
  static Matrix8 geometric_stiffness(const Q4Coords& x, const Q4PointStresses& s, const ElementMaterials& m) {
    return q4_geometric_stiffness(x, s, m.plane.thickness);
  }
  static const auto& extrapolation() { return q4_extrapolation(); }
  static auto integration_points(const Q4Coords& x) { return q4_integration_points(x); }
};

struct Cst {
  static constexpr ElementType type = ElementType::cst;
  static constexpr int nodes = 3, dim = 2, points = 1;
  static Matrix6 stiffness(const CstCoords& x, const ElementMaterials& m) { return cst_stiffness(x, m.plane); }
  static Matrix6 mass(const CstCoords& x, const ElementMaterials& m) { return cst_consistent_mass(x, m.plane); }
  static CstPointStresses point_stresses(const CstCoords& x, const Eigen::Matrix<double, 6, 1>& u,
                                         const ElementMaterials& m) {
    return cst_point_stresses(x, u, m.plane);
  }
  static Matrix6 geometric_stiffness(const CstCoords& x, const CstPointStresses& s, const ElementMaterials& m) {
    return cst_geometric_stiffness(x, s, m.plane.thickness);
  }
  static const auto& extrapolation() { return cst_extrapolation(); }
  static auto integration_points(const CstCoords& x) { return cst_integration_points(x); }
};

struct Hex8 {
  static constexpr ElementType type = ElementType::hex8;
  static constexpr int nodes = 8, dim = 3, points = 8;
  static Matrix24 stiffness(const Hex8Coords& x, const ElementMaterials& m) { return hex8_stiffness(x, m.solid); }
  static Matrix24 mass(const Hex8Coords& x, const ElementMaterials& m) { return hex8_consistent_mass(x, m.solid); }
  static Hex8PointStresses point_stresses(const Hex8Coords& x, const Eigen::Matrix<double, 24, 1>& u,
                                          const ElementMaterials& m) {
    return hex8_point_stresses(x, u, m.solid);
  }
  static Matrix24 geometric_stiffness(const Hex8Coords& x, const Hex8PointStresses& s, const ElementMaterials&) {
    return hex8_geometric_stiffness(x, s);
  }
  static const auto& extrapolation() { return hex8_extrapolation(); }
  static auto integration_points(const Hex8Coords& x) { return hex8_integration_points(x); }
};

// hex8 with incompatible (bubble) modes: its own stiffness and stresses; its mass, Gauss points and
// geometric stiffness are hex8's (the bubbles carry no mass).
struct Hex8i : Hex8 {
  static constexpr ElementType type = ElementType::hex8i;
  static Matrix24 stiffness(const Hex8Coords& x, const ElementMaterials& m) {
    return hex8_incompatible_stiffness(x, m.solid);
  }
  static Hex8PointStresses point_stresses(const Hex8Coords& x, const Eigen::Matrix<double, 24, 1>& u,
                                          const ElementMaterials& m) {
    return hex8_incompatible_point_stresses(x, u, m.solid);
  }
};

struct Hex20 {
  static constexpr ElementType type = ElementType::hex20;
  static constexpr int nodes = 20, dim = 3, points = 27;
  static Matrix60 stiffness(const Hex20Coords& x, const ElementMaterials& m) { return hex20_stiffness(x, m.solid); }
  static Matrix60 mass(const Hex20Coords& x, const ElementMaterials& m) { return hex20_consistent_mass(x, m.solid); }
  static Hex20PointStresses point_stresses(const Hex20Coords& x, const Eigen::Matrix<double, 60, 1>& u,
                                           const ElementMaterials& m) {
    return hex20_point_stresses(x, u, m.solid);
  }
  static Matrix60 geometric_stiffness(const Hex20Coords& x, const Hex20PointStresses& s, const ElementMaterials&) {
    return hex20_geometric_stiffness(x, s);
  }
  static const auto& extrapolation() { return hex20_extrapolation(); }
  static auto integration_points(const Hex20Coords& x) { return hex20_integration_points(x); }
};

}  // namespace elements

// Calls f(E{}) with E the row of `type`.
template <class F>
decltype(auto) with_element(ElementType type, F&& f) {
  switch (type) {
    case ElementType::q4:
      return std::forward<F>(f)(elements::Q4{});
    case ElementType::cst:
      return std::forward<F>(f)(elements::Cst{});
    case ElementType::hex8:
      return std::forward<F>(f)(elements::Hex8{});
    case ElementType::hex8i:
      return std::forward<F>(f)(elements::Hex8i{});
    case ElementType::hex20:
      return std::forward<F>(f)(elements::Hex20{});
  }
  return std::forward<F>(f)(elements::Q4{});  // unreachable: every enumerator is handled above (-Wswitch)
}

}  // namespace bb
