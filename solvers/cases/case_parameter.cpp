#include "cases/case_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "cases/case_spec.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

constexpr const char* kSupported =
    "material.{E,nu,rho}, section.thickness, mesh.dimensions.<name>, analysis.contact[.<i>].{kn,kt,mu,n0}, "
    "analysis.damper.{kn,kt,mu,mass,inertia,centrifugal_force,centre.0,centre.1}, analysis.modal_damping, "
    "analysis.forces.<i>.amplitude, "
    "analysis.model.{stiffness,mass}.<i>.<j>";

std::optional<contact::LawParameter> law_of(const std::string& key) {
  if (key == "kn") return contact::law_kn;
  if (key == "kt") return contact::law_kt;
  if (key == "mu") return contact::law_mu;
  if (key == "n0") return contact::law_n0;
  return std::nullopt;
}

double& law_field(contact::JenkinsParameters& law, contact::LawParameter p) {
  switch (p) {
    case contact::law_kn:
      return law.kn;
    case contact::law_kt:
      return law.kt;
    case contact::law_mu:
      return law.mu;
    case contact::law_n0:
      return law.n0;
  }
  throw std::logic_error("unknown law parameter");
}

[[noreturn]] void absent(const CaseParameter& p, const std::string& why) {
  throw std::invalid_argument(fmt::format("'{}': {}", p.path, why));
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
        return law_field(loop->law, v.law);
      }
      HbmSpec* hbm = system();
      if (!hbm) absent(p, "only hbm, time and contact_loop analyses have contacts");
      if (!v.contact) absent(p, "name the contact by its index, e.g. analysis.contact.0.kt");
      if (*v.contact >= hbm->contacts.size())
        absent(p, fmt::format("no contact {} (the analysis has {} [[analysis.contact]])", *v.contact,
                              hbm->contacts.size()));
      return law_field(hbm->contacts[*v.contact].law, v.law);
    }
    double& operator()(const DamperValue& v) {
      HbmSpec* hbm = system();
      if (!hbm || !hbm->damper) absent(p, "the analysis has no [analysis.damper]");
      if (v.law) return law_field(hbm->damper->law, *v.law);
      if (v.centre_axis) return hbm->damper->centre[*v.centre_axis];
      return (*hbm->damper).*v.member;
    }
    double& operator()(const ModalDampingValue&) {
      FrfDamping* damping = nullptr;
      if (auto* frf = std::get_if<FrfSpec>(&spec.analysis)) damping = &frf->damping;
      if (HbmSpec* hbm = system(); hbm && !hbm->damping_matrix) damping = &hbm->damping;
      if (!damping || damping->kind != FrfDamping::Kind::modal) absent(p, "the analysis has no modal_damping");
      return damping->zeta;
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
      RomSpec* rom = nullptr;
      if (HbmSpec* hbm = system()) rom = &hbm->model;
      if (!rom || !rom->matrices) absent(p, "the analysis has no matrices written in the case ([analysis.model])");
      Eigen::MatrixXd& m = v.mass ? rom->matrices->mass : rom->matrices->stiffness;
      if (static_cast<Eigen::Index>(std::max(v.row, v.col)) >= m.rows())
        absent(p, fmt::format("no entry ({}, {}): the model has {} DOFs", v.row, v.col, m.rows()));
      return m(static_cast<Eigen::Index>(v.row), static_cast<Eigen::Index>(v.col));
    }
    HbmSpec* system() {
      if (auto* h = std::get_if<HbmSpec>(&spec.analysis)) return h;
      if (auto* t = std::get_if<TimeSpec>(&spec.analysis)) return &t->system;
      return nullptr;
    }
  };
  return std::visit(Locator{spec, p}, p.target);
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
  else if (const std::string name = after("mesh.dimensions."); !name.empty()) {
    for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
      if (name == f.name) p.target = ArticleDimension{f.member};
    if (!std::holds_alternative<ArticleDimension>(p.target)) return unknown();
  } else if (const std::string key = after("analysis.damper."); !key.empty()) {
    if (const auto law = law_of(key); law && *law != contact::law_n0)
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
    const std::string index = force.substr(0, dot);
    if (dot == std::string::npos || force.substr(dot + 1) != "amplitude" || index.empty() || index.size() > 6 ||
        index.find_first_not_of("0123456789") != std::string::npos)
      return unknown();
    p.target = ForceAmplitude{std::stoul(index)};
  } else if (path.starts_with("analysis.model.stiffness.") || path.starts_with("analysis.model.mass.")) {
    const bool mass = path.starts_with("analysis.model.mass.");
    const std::string rest = after(mass ? "analysis.model.mass." : "analysis.model.stiffness.");
    const size_t dot = rest.find('.');
    const auto index = [](const std::string& t) {
      return !t.empty() && t.size() <= 6 && t.find_first_not_of("0123456789") == std::string::npos;
    };
    if (dot == std::string::npos || !index(rest.substr(0, dot)) || !index(rest.substr(dot + 1))) return unknown();
    p.target = LumpedMatrixEntry{mass, std::stoul(rest.substr(0, dot)), std::stoul(rest.substr(dot + 1))};
  } else if (const std::string rest = after("analysis.contact."); !rest.empty()) {
    const size_t dot = rest.find('.');
    if (dot == std::string::npos) {
      const auto law = law_of(rest);
      if (!law) return unknown();
      p.target = ContactLawValue{std::nullopt, *law};
    } else {
      const std::string index = rest.substr(0, dot);
      const auto law = law_of(rest.substr(dot + 1));
      if (index.empty() || index.size() > 6 || index.find_first_not_of("0123456789") != std::string::npos || !law)
        return unknown();
      p.target = ContactLawValue{std::stoul(index), *law};
    }
  } else {
    return unknown();
  }
  return p;
}

double parameter_value(const CaseSpec& spec, const CaseParameter& parameter) {
  return locate(const_cast<CaseSpec&>(spec), parameter);  // locate only reads here
}

void set_parameter_value(CaseSpec& spec, const CaseParameter& parameter, double value) {
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
    const auto check = [&](const contact::JenkinsParameters& law) {
      try {
        contact::validate(law);
      } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("'{}' = {}: {}", parameter.path, value, e.what()));
      }
    };
    if (auto* loop = std::get_if<ContactLoopSpec>(&spec.analysis)) check(loop->law);
    const HbmSpec* hbm = std::get_if<HbmSpec>(&spec.analysis);
    if (auto* t = std::get_if<TimeSpec>(&spec.analysis)) hbm = &t->system;
    if (hbm) {
      for (const HbmContactSpec& c : hbm->contacts) check(c.law);
      if (hbm->damper) check(hbm->damper->law);
    }
  }
}

std::optional<HbmParameter> hbm_parameter(const CaseParameter& parameter) {
  HbmParameter out;
  out.label = parameter.path;
  if (std::holds_alternative<ModalDampingValue>(parameter.target)) {
    out.kind = HbmParameter::Kind::modal_damping;
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
  if (const auto* d = std::get_if<DamperValue>(&parameter.target); d && d->law && *d->law != contact::law_kn) {
    out.kind = HbmParameter::Kind::damper_law;
    out.law = *d->law;
    return out;
  }
  return std::nullopt;
}

}  // namespace bb
