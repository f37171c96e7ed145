// A number of a case that calibration varies (and an hbm analysis differentiates), named in the case
// file by its dotted path ("analysis.contact.0.kt") and resolved once, by the parser, into a typed
// reference: calibration then edits the CaseSpec directly instead of rewriting and re-parsing TOML.
#pragma once
#include <optional>
#include <string>
#include <variant>

#include "articles/two_blade.hpp"
#include "fe/plane_stress.hpp"
#include "forced/hbm_spec.hpp"
#include "friction/aft.hpp"

namespace bb {

struct CaseSpec;

struct MaterialValue {  // material.E, material.nu, material.rho, section.thickness
  double fe::PlaneSection::*member = nullptr;
};
struct ArticleDimension {  // mesh.dimensions.<name> of the two-blade article
  double TwoBladeDimensions::*member = nullptr;
};
struct ContactLawValue {  // analysis.contact.<i>.<law> (hbm, time); analysis.contact.<law> (contact_loop)
  std::optional<size_t> contact;
  friction::LawParameter law = friction::law_kt;
};
// analysis.damper.{kn,kt,mu} (law), analysis.damper.{mass,inertia,centrifugal_force} (member) or
// analysis.damper.centre.{0,1} (x or y of G: where CF acts, which shares it between the points)
struct DamperValue {
  std::optional<friction::LawParameter> law;
  double DamperSpec::*member = nullptr;
  std::optional<size_t> centre_axis;
};
struct LawOwnValue {  // analysis.contact[.<i>].<key> of a law's own parameters (Iwan's chi, beta)
  std::optional<size_t> contact;
  std::string key;
};
// analysis.modal_damping (frf, hbm, time), or analysis.modal_damping.<i>: the ratio of mode i
// (0-based, ascending frequency) when the case gives one per mode
struct ModalDampingValue {
  std::optional<size_t> mode;
};
struct ForceAmplitude {  // analysis.forces.<i>.amplitude (frf, hbm, time)
  size_t force = 0;
};

struct LumpedMatrixEntry {  // analysis.model.{stiffness,mass}.<i>.<j> of matrices written in the case
  bool mass = false;
  size_t row = 0, col = 0;  // set symmetrically: (row, col) and (col, row)
};

// analysis.model.frequency_hz.<i> or analysis.model.modal_mass.<i> of a modal model (a DOF whose row
// of K and M is diagonal): the frequency sets K_ii = M_ii (2 pi f)^2; the modal mass sets M_ii and
// scales K_ii with it, so that the frequency stays. Either order of the two gives the same model.
struct ModalCoordinate {
  size_t mode = 0;
  bool mass = false;
};

// analysis.backbone.{frequency_hz,damping_ratio}.<i> (a knot's value) or analysis.mass of a
// nonlinear_modal analysis of one mode; analysis.mode.<k>.backbone.{frequency_hz,damping_ratio}.<i>
// or analysis.mode.<k>.mass of mode k of its [[analysis.mode]].
struct BackboneValue {
  enum class Curve { frequency, damping, mass } curve = Curve::mass;
  size_t knot = 0;
  std::optional<size_t> mode;
};

struct CaseParameter {
  std::string path;  // as written in the case file
  std::variant<MaterialValue, ArticleDimension, ContactLawValue, DamperValue, ModalDampingValue, ForceAmplitude,
               LumpedMatrixEntry, LawOwnValue, ModalCoordinate, BackboneValue>
      target;
};

// The typed reference of `path`; std::invalid_argument (with the supported paths) when its form is unknown.
CaseParameter parse_parameter_path(const std::string& path);

// The value in `spec`; std::invalid_argument when the case has no such value (e.g. no contact 3).
double parameter_value(const CaseSpec& spec, const CaseParameter& parameter);
// Sets it, then validates what depends on it (article dimensions, contact laws); InputError when
// the new value makes the case invalid, std::invalid_argument as parameter_value.
void set_parameter_value(CaseSpec& spec, const CaseParameter& parameter, double value);

// The same parameter as an hbm sensitivity (hbm/sensitivity.hpp differentiates it), or nullopt.
std::optional<HbmParameter> hbm_parameter(const CaseParameter& parameter);

}  // namespace bb
