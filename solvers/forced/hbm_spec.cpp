#include "forced/hbm_spec.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace bb {

std::optional<std::string> unsupported_sensitivity(const HbmSpec& spec, const HbmParameter& parameter) {
  switch (parameter.kind) {
    case HbmParameter::Kind::modal_damping:
      if (spec.damping_matrix || spec.damping.kind != FrfDamping::Kind::modal)
        return "needs modal damping (modal_damping = zeta); rayleigh damping or a damping matrix has no single scale";
      if (!spec.damping.mode_zetas.empty())
        return "modal_damping is given per mode: name the mode (analysis.modal_damping.<i>)";
      if (!(spec.damping.zeta > 0.0)) return "needs modal_damping > 0 (the log-sensitivity of zero damping is zero)";
      return std::nullopt;
    case HbmParameter::Kind::mode_damping:
      if (spec.damping_matrix || spec.damping.kind != FrfDamping::Kind::modal || spec.damping.mode_zetas.empty())
        return "needs modal damping given per mode (modal_damping = [z1, z2, ...])";
      if (spec.cyclic) return "a cyclic sector's modes are those of each nodal diameter: not differentiated per mode";
      if (parameter.row >= spec.damping.mode_zetas.size())
        return fmt::format("no mode {} (modal_damping lists {})", parameter.row, spec.damping.mode_zetas.size());
      if (!(spec.damping.mode_zetas[parameter.row] > 0.0))
        return "needs a ratio > 0 (the log-sensitivity of zero damping is zero)";
      return std::nullopt;
    case HbmParameter::Kind::damper_law:
      if (!spec.damper) return "the analysis has no [analysis.damper]";
      return std::nullopt;
    case HbmParameter::Kind::lumped_matrix:
    case HbmParameter::Kind::modal_coordinate:  // a diagonal entry of K (and M)
      if (!spec.model.matrices) return "needs the stiffness and mass matrices written in the case ([analysis.model])";
      if (spec.base_motion && parameter.mass)
        return "with a base motion the load -M r a_b moves with the mass, which the sensitivities leave out: fit a "
               "stiffness (or frequency) instead";
      if (spec.damper || spec.cyclic || spec.gap_damper)
        return "an entry of the lumped matrices is differentiated without a damper or [analysis.cyclic]";
      if (std::max(parameter.row, parameter.kind == HbmParameter::Kind::lumped_matrix ? parameter.col : 0) >=
          static_cast<size_t>(spec.model.matrices->size()))
        return fmt::format("no entry ({}, {}): the model has {} DOFs", parameter.row, parameter.col,
                           spec.model.matrices->size());
      return std::nullopt;
    case HbmParameter::Kind::contact_law:
      if (parameter.contact >= spec.contacts.size())
        return fmt::format("no contact {} (the analysis has {} [[analysis.contact]])", parameter.contact,
                           spec.contacts.size());
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace bb
