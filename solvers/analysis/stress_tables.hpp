// Result tables of a recovered stress field (assembly/stress_recovery): nodal stresses with their
// invariants, nodal strains, and the unaveraged integration-point stresses. Units: Pa, m/m, m.
#pragma once
#include <string>

#include "assembly/stress_recovery.hpp"
#include "fe/plane_stress.hpp"
#include "mesh/mesh.hpp"
#include "results/table.hpp"

namespace bb {

// Key `node`: sxx, syy, sxy [, szz, syz, szx], von_mises, the principal stresses s1 >= s2 (plane
// stress: in-plane; szz = 0 is the third) [>= s3 in 3D], and von_mises_scatter (the largest von Mises
// stress of one element's extrapolated value minus the average: the elements' disagreement).
ResultTable nodal_stress_table(const std::string& name, const Mesh& mesh, const StressField& field);

// Key `node`: exx, eyy, gxy, ezz (plane stress: ezz is the thickness strain) or exx, eyy, gxy, ezz,
// gyz, gzx (solids; engineering shear strains), from the nodal stresses by Hooke's law.
ResultTable nodal_strain_table(const std::string& name, const Mesh& mesh, const StressField& field,
                               const fe::PlaneSection& material);

// Key `point` (1..n in element order): element, gauss_point, x, y [, z], the stress components as in
// nodal_stress_table and von_mises. Needs field.points.
ResultTable integration_point_stress_table(const std::string& name, const StressField& field);

}  // namespace bb
