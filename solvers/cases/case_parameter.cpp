#include "cases/case_parameter.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

constexpr const char* kSupported =
    "material.{E,nu,rho}, section.thickness, mesh.dimensions.<name>, analysis.contact[.<i>].{kn,kt,mu,n0}, "
    "analysis.contact[.<i>].<the law's own, e.g. chi, beta>, "
    "analysis.damper.{kn,kt,mu,mass,inertia,centrifugal_force,centre.0,centre.1}, analysis.modal_damping[.<mode>], "
    "analysis.forces.<i>.amplitude, "
    "analysis.model.{stiffness,mass}.<i>.<j>, analysis.model.{frequency_hz,modal_mass}.<i>, "
    "analysis.backbone.{frequency_hz,damping_ratio}.<i>, analysis.mass, "
    "analysis.mode.<k>.backbone.{frequency_hz,damping_ratio}.<i>, analysis.mode.<k>.mass";

// A 0-based index as written in a path: digits only, at most 6.
std::optional<size_t> index_of(const std::string& t) {
  if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stoul(t);
}

// A law's own key: a lower-case identifier (which keys exist, only the contact's law knows).
bool law_key(const std::string& t) {
  return !t.empty() && t.find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789") == std::string::npos &&
         !std::isdigit(static_cast<unsigned char>(t.front()));
}

std::optional<friction::LawParameter> law_of(const std::string& key) {
  if (key == "kn") return friction::law_kn;
  if (key == "kt") return friction::law_kt;
  if (key == "mu") return friction::law_mu;
  if (key == "n0") return friction::law_n0;
  return std::nullopt;
}

double& law_field(friction::PointParameters& law, friction::LawParameter p) {
  switch (p) {
    case friction::law_kn:
      return law.kn;
    case friction::law_kt:
      return law.kt;
    case friction::law_mu:
      return law.mu;
    case friction::law_n0:
      return law.n0;
  }
  throw std::logic_error("unknown law parameter");
}

[[noreturn]] void absent(const CaseParameter& p, const std::string& why) {
  throw std::invalid_argument(fmt::format("'{}': {}", p.path, why));
}

HbmSpec* system_of(CaseSpec& spec) {
  if (auto* h = std::get_if<HbmSpec>(&spec.analysis)) return h;
  if (auto* t = std::get_if<TimeSpec>(&spec.analysis)) return &t->system;
  return nullptr;
}

ReducedModel& written_matrices(CaseSpec& spec, const CaseParameter& p) {
  HbmSpec* hbm = system_of(spec);
  if (!hbm || !hbm->model.matrices) absent(p, "the analysis has no matrices written in the case ([analysis.model])");
  return *hbm->model.matrices;
}

// The mode a backbone value names, checked against the case's form: one mode (analysis.backbone,
// analysis.mass) or [[analysis.mode]] (analysis.mode.<k>.*).
NonlinearMode& nonlinear_mode(CaseSpec& spec, const CaseParameter& p, const BackboneValue& v) {
  auto* modal = std::get_if<NonlinearModalSpec>(&spec.analysis);
  if (!modal) absent(p, "only a nonlinear_modal analysis has a backbone and a mass");
  if (!v.mode) {
    if (modal->mode_array)
      absent(p, "the analysis lists its modes as [[analysis.mode]]: name one, e.g. analysis.mode.0.mass");
    return modal->modes.front();
  }
  if (!modal->mode_array)
    absent(p, "the analysis has one mode (mass and [analysis.backbone]): write analysis.mass or analysis.backbone.*");
  if (*v.mode >= modal->modes.size())
    absent(p, fmt::format("no mode {} (the analysis has {} [[analysis.mode]])", *v.mode, modal->modes.size()));
  return modal->modes[*v.mode];
}

// The number a parameter names inside `spec`, for reading and writing alike.
double& locate(CaseSpec& spec, const CaseParameter& p) {
  struct Locator {
    CaseSpec& spec;
    const CaseParameter& p;
    double& operator()(const MaterialValue& v) {
      if (spec.model.mesh.kind == MeshSpec::Kind::none) absent(p, "the case has no [material]");
      return spec.model.section.*v.member;
    }
    double& operator()(const ArticleDimension& v) {
      if (spec.model.mesh.kind != MeshSpec::Kind::two_blade && spec.model.mesh.kind != MeshSpec::Kind::blade_section)
        absent(p, "the mesh is not a two_blade article or its blade_section");
      return spec.model.mesh.two_blade.*v.member;
    }
    double& operator()(const ContactLawValue& v) {
      if (auto* loop = std::get_if<ContactLoopSpec>(&spec.analysis)) {
        if (v.contact) absent(p, "a contact_loop analysis has one [analysis.contact]: leave out the index");
        return law_field(loop->point, v.law);
      }
      HbmSpec* hbm = system();
      if (!hbm) absent(p, "only hbm, time and contact_loop analyses have contacts");
      if (!v.contact) absent(p, "name the contact by its index, e.g. analysis.contact.0.kt");
      if (*v.contact >= hbm->contacts.size())
        absent(p, fmt::format("no contact {} (the analysis has {} [[analysis.contact]])", *v.contact,
                              hbm->contacts.size()));
      return law_field(hbm->contacts[*v.contact].point, v.law);
    }
    double& operator()(const DamperValue& v) {
      HbmSpec* hbm = system();
      if (!hbm || !hbm->damper) absent(p, "the analysis has no [analysis.damper]");
      if (v.law) return law_field(hbm->damper->point, *v.law);
      if (v.centre_axis) return hbm->damper->centre[*v.centre_axis];
      return (*hbm->damper).*v.member;
    }
    double& operator()(const ModalDampingValue& v) {
      FrfDamping* damping = nullptr;
      if (auto* frf = std::get_if<FrfSpec>(&spec.analysis)) damping = &frf->damping;
      if (HbmSpec* hbm = system(); hbm && !hbm->damping_matrix) damping = &hbm->damping;
      if (!damping || damping->kind != FrfDamping::Kind::modal) absent(p, "the analysis has no modal_damping");
      if (!v.mode) {
        if (!damping->mode_zetas.empty())
          absent(p, "modal_damping is given per mode: name the mode, e.g. analysis.modal_damping.0");
        return damping->zeta;
      }
      if (damping->mode_zetas.empty())
        absent(p, "modal_damping is one ratio for every mode: write it as an array, one ratio per mode, to vary one");
      if (*v.mode >= damping->mode_zetas.size())
        absent(p, fmt::format("no mode {} (modal_damping lists {})", *v.mode, damping->mode_zetas.size()));
      return damping->mode_zetas[*v.mode];
    }
    double& operator()(const LawOwnValue&) {
      throw std::logic_error("a law's own parameter is not stored as a number");
    }
    double& operator()(const ModalCoordinate&) {
      throw std::logic_error("a modal coordinate's frequency is not stored as a number");
    }
    double& operator()(const BackboneValue& v) {
      if (v.curve != BackboneValue::Curve::mass) throw std::logic_error("a backbone knot is not stored as a number");
      return nonlinear_mode(spec, p, v).mass;
    }
    double& operator()(const ForceAmplitude& v) {
      std::vector<FrfForce>* forces = nullptr;
      if (auto* frf = std::get_if<FrfSpec>(&spec.analysis)) forces = &frf->forces;
      if (HbmSpec* hbm = system()) forces = &hbm->forces;
      if (!forces) absent(p, "the analysis has no forces");
      if (v.force >= forces->size())
        absent(p, fmt::format("no force {} (the analysis has {})", v.force, forces->size()));
      return (*forces)[v.force].amplitude;
    }
    double& operator()(const LumpedMatrixEntry& v) {
      ReducedModel& model = written_matrices(spec, p);
      Eigen::MatrixXd& m = v.mass ? model.mass : model.stiffness;
      if (static_cast<Eigen::Index>(std::max(v.row, v.col)) >= m.rows())
        absent(p, fmt::format("no entry ({}, {}): the model has {} DOFs", v.row, v.col, m.rows()));
      return m(static_cast<Eigen::Index>(v.row), static_cast<Eigen::Index>(v.col));
    }
    HbmSpec* system() { return system_of(spec); }
  };
  return std::visit(Locator{spec, p}, p.target);
}

// The contact of an hbm or time analysis a law's own parameter names, checked to exist; null for
// the one contact of a contact_loop.
HbmContactSpec* own_value_contact(CaseSpec& spec, const CaseParameter& p, const LawOwnValue& v) {
  if (auto* loop = std::get_if<ContactLoopSpec>(&spec.analysis)) {
    if (v.contact) absent(p, "a contact_loop analysis has one [analysis.contact]: leave out the index");
    return nullptr;
  }
  HbmSpec* hbm = system_of(spec);
  if (!hbm) absent(p, "only hbm, time and contact_loop analyses have contacts");
  if (!v.contact) absent(p, fmt::format("name the contact by its index, e.g. analysis.contact.0.{}", v.key));
  if (*v.contact >= hbm->contacts.size())
    absent(p,
           fmt::format("no contact {} (the analysis has {} [[analysis.contact]])", *v.contact, hbm->contacts.size()));
  return &hbm->contacts[*v.contact];
}

// The friction law of the contact when the parameter is one of that law's own (a clearance
// spring's gap), else null: the parameter is then its slider distribution's (Iwan's chi).
std::shared_ptr<const friction::FrictionLaw>* own_law_slot(CaseSpec& spec, const CaseParameter& p,
                                                           const LawOwnValue& v) {
  HbmContactSpec* c = own_value_contact(spec, p, v);
  if (!c) return nullptr;
  const std::vector<std::string> names = c->law->parameter_names();
  return std::find(names.begin(), names.end(), v.key) == names.end() ? nullptr : &c->law;
}

// The slot of the slider distribution of the contact a law's own parameter names.
std::shared_ptr<const friction::SliderDistribution>& law_slot(CaseSpec& spec, const CaseParameter& p,
                                                              const LawOwnValue& v) {
  HbmContactSpec* c = own_value_contact(spec, p, v);
  std::shared_ptr<const friction::SliderDistribution>* slot =
      c ? &c->distribution : &std::get<ContactLoopSpec>(spec.analysis).distribution;
  if (!*slot) {
    const std::vector<std::string> names = c ? c->law->parameter_names() : std::vector<std::string>{};
    absent(p, names.empty() ? fmt::format("the contact's law is {}, which has no parameter '{}' of its own",
                                          c ? c->law->name() : std::string("jenkins"), v.key)
                            : fmt::format("the contact's law is {}, whose own parameters are {}", c->law->name(),
                                          fmt::join(names, ", ")));
  }
  return *slot;
}

// The diagonal entries (K_ii, M_ii) of a modal coordinate, checked to be one.
std::pair<double*, double*> modal_entries(CaseSpec& spec, const CaseParameter& p, const ModalCoordinate& v) {
  ReducedModel& m = written_matrices(spec, p);
  const auto i = static_cast<Eigen::Index>(v.mode);
  if (i >= m.stiffness.rows()) absent(p, fmt::format("no DOF {}: the model has {} DOFs", v.mode, m.stiffness.rows()));
  const auto coupled = [&](const Eigen::MatrixXd& a) {
    return a.row(i).cwiseAbs().sum() + a.col(i).cwiseAbs().sum() != 2.0 * std::abs(a(i, i));
  };
  if (coupled(m.stiffness) || coupled(m.mass))
    absent(p, fmt::format("DOF {} is coupled to others in K or M: a frequency and a modal mass belong to a modal "
                          "model (frequency_hz and modal_mass in [analysis.model])",
                          v.mode));
  return {&m.stiffness(i, i), &m.mass(i, i)};
}

// The knot's curve, checked to have the knot (nullptr for the mass).
ModalBackbone* backbone_curve(CaseSpec& spec, const CaseParameter& p, const BackboneValue& v) {
  if (v.curve == BackboneValue::Curve::mass) return nullptr;
  NonlinearMode& mode = nonlinear_mode(spec, p, v);
  ModalBackbone& c = v.curve == BackboneValue::Curve::frequency ? mode.frequency_hz : mode.damping_ratio;
  if (v.knot >= c.knots()) absent(p, fmt::format("no knot {} (the backbone has {})", v.knot, c.knots()));
  return &c;
}

// "mass", "backbone.frequency_hz.<i>" or "backbone.damping_ratio.<i>": one mode's own values.
std::optional<BackboneValue> backbone_value(const std::string& rest) {
  if (rest == "mass") return BackboneValue{};
  for (const auto& [prefix, curve] : {std::pair{"backbone.frequency_hz.", BackboneValue::Curve::frequency},
                                      std::pair{"backbone.damping_ratio.", BackboneValue::Curve::damping}})
    if (rest.starts_with(prefix)) {
      const auto knot = index_of(rest.substr(std::string(prefix).size()));
      if (!knot) return std::nullopt;
      return BackboneValue{curve, *knot, std::nullopt};
    }
  return std::nullopt;
}

}  // namespace

CaseParameter parse_parameter_path(const std::string& path) {
  CaseParameter p;
  p.path = path;
  const auto unknown = [&]() -> CaseParameter {
    throw std::invalid_argument(fmt::format("'{}' is not a parameter a calibration can vary ({})", path, kSupported));
  };
  const auto after = [&](const std::string& prefix) {
    return path.starts_with(prefix) ? path.substr(prefix.size()) : std::string();
  };
  if (path == "material.E")
    p.target = MaterialValue{&fe::PlaneSection::youngs_modulus};
  else if (path == "material.nu")
    p.target = MaterialValue{&fe::PlaneSection::poisson_ratio};
  else if (path == "material.rho")
    p.target = MaterialValue{&fe::PlaneSection::density};
  else if (path == "section.thickness")
    p.target = MaterialValue{&fe::PlaneSection::thickness};
  else if (path == "analysis.modal_damping")
    p.target = ModalDampingValue{};
  else if (path == "analysis.mass" || path.starts_with("analysis.backbone.")) {
    const std::optional<BackboneValue> v = backbone_value(path.substr(std::string("analysis.").size()));
    if (!v) return unknown();
    p.target = *v;
  } else if (const std::string moded = after("analysis.mode."); !moded.empty()) {
    const size_t dot = moded.find('.');
    const auto mode = index_of(moded.substr(0, dot));
    std::optional<BackboneValue> v = dot == std::string::npos ? std::nullopt : backbone_value(moded.substr(dot + 1));
    if (!mode || !v) return unknown();
    v->mode = *mode;
    p.target = *v;
  } else if (const std::string damped = after("analysis.modal_damping."); !damped.empty()) {
    if (!index_of(damped)) return unknown();
    p.target = ModalDampingValue{index_of(damped)};
  } else if (path.starts_with("analysis.model.frequency_hz.") || path.starts_with("analysis.model.modal_mass.")) {
    const bool mass = path.starts_with("analysis.model.modal_mass.");
    const auto mode = index_of(after(mass ? "analysis.model.modal_mass." : "analysis.model.frequency_hz."));
    if (!mode) return unknown();
    p.target = ModalCoordinate{*mode, mass};
  } else if (const std::string name = after("mesh.dimensions."); !name.empty()) {
    for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
      if (name == f.name) p.target = ArticleDimension{f.member};
    if (!std::holds_alternative<ArticleDimension>(p.target)) return unknown();
  } else if (const std::string key = after("analysis.damper."); !key.empty()) {
    if (const auto law = law_of(key); law && *law != friction::law_n0)
      p.target = DamperValue{law, nullptr, std::nullopt};
    else if (key == "mass")
      p.target = DamperValue{std::nullopt, &DamperSpec::mass, std::nullopt};
    else if (key == "inertia")
      p.target = DamperValue{std::nullopt, &DamperSpec::inertia, std::nullopt};
    else if (key == "centrifugal_force")
      p.target = DamperValue{std::nullopt, &DamperSpec::centrifugal_force, std::nullopt};
    else if (key == "centre.0" || key == "centre.1")
      p.target = DamperValue{std::nullopt, nullptr, key == "centre.0" ? 0u : 1u};
    else
      return unknown();
  } else if (const std::string force = after("analysis.forces."); !force.empty()) {
    const size_t dot = force.find('.');
    const auto index = index_of(force.substr(0, dot));
    if (dot == std::string::npos || force.substr(dot + 1) != "amplitude" || !index) return unknown();
    p.target = ForceAmplitude{*index};
  } else if (path.starts_with("analysis.model.stiffness.") || path.starts_with("analysis.model.mass.")) {
    const bool mass = path.starts_with("analysis.model.mass.");
    const std::string rest = after(mass ? "analysis.model.mass." : "analysis.model.stiffness.");
    const size_t dot = rest.find('.');
    const auto row = index_of(rest.substr(0, dot)),
               col = index_of(dot == std::string::npos ? "" : rest.substr(dot + 1));
    if (!row || !col) return unknown();
    p.target = LumpedMatrixEntry{mass, *row, *col};
  } else if (const std::string rest = after("analysis.contact."); !rest.empty()) {
    const size_t dot = rest.find('.');
    const std::optional<size_t> contact = dot == std::string::npos ? std::nullopt : index_of(rest.substr(0, dot));
    if (dot != std::string::npos && !contact) return unknown();
    const std::string field = dot == std::string::npos ? rest : rest.substr(dot + 1);
    if (const auto law = law_of(field))
      p.target = ContactLawValue{contact, *law};
    else if (law_key(field))
      p.target = LawOwnValue{contact, field};
    else
      return unknown();
  } else {
    return unknown();
  }
  return p;
}

double parameter_value(const CaseSpec& spec, const CaseParameter& parameter) {
  CaseSpec& s = const_cast<CaseSpec&>(spec);  // only read here
  if (const auto* v = std::get_if<LawOwnValue>(&parameter.target)) {
    if (const auto* own = own_law_slot(s, parameter, *v)) return (*own)->parameter(v->key);
    const auto& law = law_slot(s, parameter, *v);
    try {
      return law->parameter(v->key);
    } catch (const std::invalid_argument& e) {
      absent(parameter, e.what());
    }
  }
  if (const auto* v = std::get_if<ModalCoordinate>(&parameter.target)) {
    const auto [k, m] = modal_entries(s, parameter, *v);
    return v->mass ? *m : std::sqrt(*k / *m) / (2.0 * std::numbers::pi);
  }
  if (const auto* v = std::get_if<BackboneValue>(&parameter.target))
    if (const ModalBackbone* c = backbone_curve(s, parameter, *v)) return c->values()[v->knot];
  return locate(s, parameter);
}

void set_parameter_value(CaseSpec& spec, const CaseParameter& parameter, double value) {
  if (const auto* v = std::get_if<LawOwnValue>(&parameter.target)) {
    if (auto* own = own_law_slot(spec, parameter, *v)) {
      try {
        *own = (*own)->with_parameter(v->key, value);
      } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("'{}' = {}: {}", parameter.path, value, e.what()));
      }
      return;
    }
    auto& law = law_slot(spec, parameter, *v);
    parameter_value(spec, parameter);  // names a key the law lacks
    try {
      law = law->with_parameter(v->key, value);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("'{}' = {}: {}", parameter.path, value, e.what()));
    }
    return;
  }
  if (const auto* v = std::get_if<ModalCoordinate>(&parameter.target)) {
    if (!(value > 0.0) || !std::isfinite(value))
      throw InputError(fmt::format("'{}' = {}: must be positive and finite", parameter.path, value));
    const auto [k, m] = modal_entries(spec, parameter, *v);
    if (v->mass) {
      *k *= value / *m;
      *m = value;
    } else {
      *k = *m * std::pow(2.0 * std::numbers::pi * value, 2);
    }
    return;
  }
  if (const auto* v = std::get_if<BackboneValue>(&parameter.target)) {
    if (!(value > 0.0) || !std::isfinite(value))
      throw InputError(fmt::format("'{}' = {}: must be positive and finite", parameter.path, value));
    if (ModalBackbone* c = backbone_curve(spec, parameter, *v)) {
      c->set_value(v->knot, value);
      const auto& a = c->amplitudes();
      if (const double lo = c->range(a.front(), a.back(), 2000).first; !(lo > 0.0))
        throw InputError(
            fmt::format("'{}' = {}: the backbone's spline then reaches {:.6g} between its knots; it must "
                        "stay positive",
                        parameter.path, value, lo));
      return;
    }
  }
  locate(spec, parameter) = value;
  if (const auto* e = std::get_if<LumpedMatrixEntry>(&parameter.target); e && e->row != e->col) {
    CaseParameter mirror = parameter;
    mirror.target = LumpedMatrixEntry{e->mass, e->col, e->row};
    locate(spec, mirror) = value;  // the matrices stay symmetric
  }
  if (std::holds_alternative<ArticleDimension>(parameter.target)) {
    spec.model.mesh.two_blade.validate();  // DimensionError is an InputError
  } else if (std::holds_alternative<ContactLawValue>(parameter.target) ||
             std::holds_alternative<DamperValue>(parameter.target)) {
    const auto check = [&](const friction::PointParameters& law) {
      try {
        friction::validate(law);
      } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("'{}' = {}: {}", parameter.path, value, e.what()));
      }
    };
    if (auto* loop = std::get_if<ContactLoopSpec>(&spec.analysis)) check(loop->point);
    const HbmSpec* hbm = std::get_if<HbmSpec>(&spec.analysis);
    if (auto* t = std::get_if<TimeSpec>(&spec.analysis)) hbm = &t->system;
    if (hbm) {
      for (const HbmContactSpec& c : hbm->contacts) check(c.point);
      if (hbm->damper) check(hbm->damper->point);
    }
  }
}

std::optional<HbmParameter> hbm_parameter(const CaseParameter& parameter) {
  HbmParameter out;
  out.label = parameter.path;
  if (const auto* d = std::get_if<ModalDampingValue>(&parameter.target)) {
    out.kind = d->mode ? HbmParameter::Kind::mode_damping : HbmParameter::Kind::modal_damping;
    out.row = d->mode.value_or(0);
    return out;
  }
  if (const auto* m = std::get_if<ModalCoordinate>(&parameter.target)) {
    out.kind = HbmParameter::Kind::modal_coordinate;
    out.mass = m->mass;
    out.row = m->mode;
    return out;
  }
  if (const auto* e = std::get_if<LumpedMatrixEntry>(&parameter.target)) {
    out.kind = HbmParameter::Kind::lumped_matrix;
    out.mass = e->mass;
    out.row = e->row;
    out.col = e->col;
    return out;
  }
  if (const auto* c = std::get_if<ContactLawValue>(&parameter.target); c && c->contact) {
    out.kind = HbmParameter::Kind::contact_law;
    out.contact = *c->contact;
    out.law = c->law;
    return out;
  }
  // damper.kn is left out: the damper's seat (the sliders' offsets, from the static pre-solve)
  // moves with kn, which the derivative holds fixed.
  if (const auto* d = std::get_if<DamperValue>(&parameter.target); d && d->law && *d->law != friction::law_kn) {
    out.kind = HbmParameter::Kind::damper_law;
    out.law = *d->law;
    return out;
  }
  return std::nullopt;
}

}  // namespace bb
