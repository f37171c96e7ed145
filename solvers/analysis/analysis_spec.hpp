// The analysis a case asks for: exactly one of the analysis types. Every consumer dispatches with
// std::visit, so an analysis type added here and forgotten anywhere does not compile.
#pragma once
#include <string_view>
#include <variant>

#include "analysis/contact_loop_spec.hpp"
#include "analysis/contact_modal_spec.hpp"
#include "analysis/cyclic_modal_spec.hpp"
#include "analysis/frf_spec.hpp"
#include "analysis/modal_spec.hpp"
#include "analysis/nonlinear_modal_spec.hpp"
#include "analysis/rotating_spec.hpp"
#include "analysis/static_spec.hpp"
#include "forced/time_spec.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

using AnalysisSpec = std::variant<StaticSpec, ModalSpec, FrfSpec, HbmSpec, TimeSpec, ContactLoopSpec, RotatingSpec,
                                  ContactModalSpec, CyclicModalSpec, NonlinearModalSpec>;

// The case file's name of each type (`type = "..."` in [analysis]).
constexpr std::string_view analysis_type_name(const StaticSpec&) { return "static"; }
constexpr std::string_view analysis_type_name(const ModalSpec&) { return "modal"; }
constexpr std::string_view analysis_type_name(const FrfSpec&) { return "frf"; }
constexpr std::string_view analysis_type_name(const HbmSpec&) { return "hbm"; }
constexpr std::string_view analysis_type_name(const TimeSpec&) { return "time"; }
constexpr std::string_view analysis_type_name(const ContactLoopSpec&) { return "contact_loop"; }
constexpr std::string_view analysis_type_name(const RotatingSpec&) { return "rotating"; }
constexpr std::string_view analysis_type_name(const ContactModalSpec&) { return "contact_modal"; }
constexpr std::string_view analysis_type_name(const CyclicModalSpec&) { return "cyclic_modal"; }
constexpr std::string_view analysis_type_name(const NonlinearModalSpec&) { return "nonlinear_modal"; }
inline std::string_view analysis_type_name(const AnalysisSpec& a) {
  return std::visit([](const auto& s) { return analysis_type_name(s); }, a);
}

}  // namespace bb
