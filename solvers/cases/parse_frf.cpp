#include "cases/parse_frf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "cases/parse_common.hpp"
#include "cases/parse_modal.hpp"
#include "frf/receptance.hpp"

namespace bb {
namespace fs = std::filesystem;

// "T2.x": a point (one-node set) and a direction.
PointDof parse_point_dof(TomlReader& r, const std::string& key, const std::string& text) {
  const size_t dot = text.rfind('.');
  const std::string axis = dot == std::string::npos ? "" : text.substr(dot + 1);
  if (dot == 0 || (axis != "x" && axis != "y" && axis != "z"))
    r.fail(key, fmt::format("'{}' is not a point DOF; write the point and the direction, e.g. \"T2.x\"", text));
  return {text.substr(0, dot), static_cast<Direction>(axis[0] - 'x')};
}

std::vector<PointDof> parse_responses(TomlReader& r) {
  std::vector<PointDof> out;
  for (const std::string& s : r.string_array("responses")) out.push_back(parse_point_dof(r, "responses", s));
  if (out.empty()) r.fail("responses", "needs at least one response, e.g. [\"T2.x\"]");
  return out;
}

// { "A.x" = 1.0, "B.x" = -1.0 }: the coefficients of a relative displacement.
std::vector<std::pair<PointDof, double>> parse_combination(TomlReader& r, const std::string& key) {
  std::vector<std::pair<PointDof, double>> out;
  for (const auto& [name, value] : r.table(key)) {
    const std::optional<double> c = toml_number(value);
    if (!c || !number_problem(*c).empty() || *c == 0.0)
      r.fail(key, fmt::format("the coefficient of '{}' must be a finite nonzero number", name.str()));
    out.emplace_back(parse_point_dof(r, key, std::string(name.str())), *c);
  }
  if (out.empty()) r.fail(key, "needs at least one DOF, e.g. { \"A.x\" = 1.0 }");
  return out;
}

std::vector<FrfForce> parse_forces(TomlReader& r) {
  std::vector<FrfForce> out;
  int i = 0;
  for (const toml::node& n : r.array("forces")) {
    if (!n.is_table()) r.fail("forces", "write each force as { dof = \"F.x\", amplitude = 5.0 }");
    TomlReader f(*n.as_table(), fmt::format("{}.forces[{}]", r.path(), i++), r.file());
    FrfForce force;
    force.dof = parse_point_dof(f, "dof", f.string("dof"));
    force.amplitude = f.number("amplitude");
    if (force.amplitude == 0.0 || !std::isfinite(force.amplitude)) f.fail("amplitude", "must be finite and nonzero");
    f.finish();
    out.push_back(force);
  }
  if (out.empty()) r.fail("forces", "needs at least one force");
  return out;
}

Eigen::MatrixXd parse_square_matrix(TomlReader& r, const std::string& key, size_t n) {
  const toml::array& rows = r.array(key);
  if (rows.size() != n) r.fail(key, fmt::format("needs {} rows, one per DOF in 'dofs', found {}", n, rows.size()));
  // Every row is checked before the n x n matrix is allocated: its size is then written in the file.
  for (size_t i = 0; i < n; ++i)
    if (const toml::array* row = rows[i].as_array(); !row || row->size() != n)
      r.fail(key, fmt::format("row {} must be a list of {} numbers", i + 1, n));
  Eigen::MatrixXd m(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (size_t i = 0; i < n; ++i) {
    const toml::array* row = rows[i].as_array();
    for (size_t j = 0; j < n; ++j) {
      const std::optional<double> v = toml_number((*row)[j]);
      if (!v || !number_problem(*v).empty())
        r.fail(key, fmt::format("entry ({}, {}) is not a finite number", i + 1, j + 1));
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = *v;
    }
  }
  return m;
}

namespace {

// A lumped or reduced model written in the case: dofs = ["A.x", ...], stiffness and mass as rows.
ReducedModel parse_matrices(TomlReader& r) {
  ReducedModel m;
  for (const std::string& name : r.string_array("dofs")) {
    const std::optional<ReducedDof> dof = ReducedDof::parse(name);
    if (!dof) r.fail("dofs", fmt::format("'{}' is not a DOF name (\"A.x\", or \"mode 3\")", name));
    m.dofs.push_back(*dof);
  }
  if (m.dofs.empty()) r.fail("dofs", "needs at least one DOF");
  if (r.has("frequency_hz")) {
    // A modal model (a modal test's): one DOF per mode, K = diag(m_i (2 pi f_i)^2), M = diag(m_i).
    if (r.has("stiffness") || r.has("mass"))
      r.fail("frequency_hz", "a modal model gives frequency_hz and modal_mass instead of stiffness and mass");
    const std::vector<double> f = r.number_array("frequency_hz"), mass = r.number_array("modal_mass");
    if (f.size() != m.dofs.size())
      r.fail("frequency_hz", fmt::format("expected one frequency per DOF ({}), found {}", m.dofs.size(), f.size()));
    if (mass.size() != m.dofs.size())
      r.fail("modal_mass", fmt::format("expected one modal mass per DOF ({}), found {}", m.dofs.size(), mass.size()));
    const auto n = static_cast<Eigen::Index>(f.size());
    m.stiffness = Eigen::MatrixXd::Zero(n, n);
    m.mass = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double fi = f[static_cast<size_t>(i)], mi = mass[static_cast<size_t>(i)];
      if (!(fi > 0.0) || !std::isfinite(fi))
        r.fail("frequency_hz", fmt::format("mode {}: a frequency must be positive and finite, found {}", i + 1, fi));
      if (!(mi > 0.0) || !std::isfinite(mi))
        r.fail("modal_mass", fmt::format("mode {}: a modal mass must be positive and finite, found {}", i + 1, mi));
      m.mass(i, i) = mi;
      m.stiffness(i, i) = mi * std::pow(2.0 * std::numbers::pi * fi, 2);
    }
    validate_reduced_model(m, r.location("frequency_hz").where() + ": '" + r.path() + "'");
    return m;
  }
  m.stiffness = parse_square_matrix(r, "stiffness", m.dofs.size());
  m.mass = parse_square_matrix(r, "mass", m.dofs.size());
  validate_reduced_model(m, r.location("stiffness").where() + ": '" + r.path() + "'");
  return m;
}

}  // namespace

RomSpec parse_rom(TomlReader& r, const fs::path& folder) {
  RomSpec rom;
  // The name becomes file names (reduced_models/<name>.toml) and table names (peaks_<name>).
  rom.name = r.name("name");
  if (rom.name == "full") r.fail("name", "\"full\" names the full mesh's curves; choose another name");
  const bool matrices = r.has("stiffness") || r.has("frequency_hz");
  if (static_cast<int>(r.has("file")) + static_cast<int>(r.has("masters")) + static_cast<int>(matrices) != 1)
    r.fail("masters",
           "give one of 'masters' (Craig-Bampton), 'file' (a reduced model on disk), 'stiffness' + 'mass' + 'dofs' "
           "(matrices) or 'frequency_hz' + 'modal_mass' + 'dofs' (a modal model)");
  if (r.has("file")) {
    rom.file = r.input_file("file", folder);
  } else if (matrices) {
    rom.matrices = parse_matrices(r);
  } else {
    rom.masters = r.string_array("masters");
    if (rom.masters.empty()) r.fail("masters", "needs at least one master point");
    std::set<std::string> unique(rom.masters.begin(), rom.masters.end());
    if (unique.size() != rom.masters.size()) r.fail("masters", "a master point is listed twice");
    if (r.has("modes") == r.has("modes_below_hz"))
      r.fail("modes", "give either 'modes' (how many fixed-interface modes) or 'modes_below_hz' (every mode below)");
    if (r.has("modes")) {
      const long modes = r.integer("modes");
      if (modes < 0 || modes > 10000) r.fail("modes", "must lie in [0, 10000]");
      rom.modes = static_cast<int>(modes);
    } else {
      rom.modes_below_hz = r.positive("modes_below_hz");
    }
    rom.eigensolver = parse_eigensolver(r);
  }
  const std::string method = r.choice("method", {"direct", "modal"}, "direct");
  rom.method = method == "modal" ? RomSpec::Method::modal : RomSpec::Method::direct;
  if (r.has("forces")) rom.forces = parse_forces(r);
  if (r.has("responses")) rom.responses = parse_responses(r);
  r.finish();
  return rom;
}

FrfDamping parse_damping(TomlReader& r) {
  FrfDamping damping;
  if (r.has("modal_damping") == r.has("rayleigh"))
    r.fail("modal_damping",
           "give either 'modal_damping' (one ratio for every mode, or one per mode, lowest first) or 'rayleigh' = { "
           "frequency_hz = [f1, f2], zeta = "
           "[z1, z2] }");
  if (r.has_array("modal_damping")) {
    // One ratio per mode, lowest first (a modal test's); the modes above the last take its ratio.
    damping.mode_zetas = r.number_array("modal_damping");
    if (damping.mode_zetas.empty()) r.fail("modal_damping", "needs at least one ratio (or one number for every mode)");
    for (size_t i = 0; i < damping.mode_zetas.size(); ++i)
      if (!(damping.mode_zetas[i] >= 0.0 && damping.mode_zetas[i] < 1.0))
        r.fail("modal_damping",
               fmt::format("the ratio of mode {} must lie in [0, 1), found {}", i + 1, damping.mode_zetas[i]));
  } else if (r.has("modal_damping")) {
    damping.zeta = r.non_negative("modal_damping", 0.0);
    if (damping.zeta >= 1.0) r.fail("modal_damping", "must be below 1 (critical damping)");
  } else {
    TomlReader d(r.table("rayleigh"), r.path() + ".rayleigh", r.file());
    const auto f = d.number_array("frequency_hz");
    const auto z = d.number_array("zeta");
    if (f.size() != 2 || !(f[0] > 0) || !(f[1] > f[0])) d.fail("frequency_hz", "expected [f1, f2] with 0 < f1 < f2");
    if (z.size() != 2 || !(z[0] >= 0) || !(z[1] >= 0) || z[0] >= 1 || z[1] >= 1)
      d.fail("zeta", "expected [zeta1, zeta2], each in [0, 1)");
    // A negative coefficient damps some frequencies negatively: no steady response balances that.
    const RayleighCoefficients c =
        fit_rayleigh(2.0 * std::numbers::pi * f[0], z[0], 2.0 * std::numbers::pi * f[1], z[1]);
    if (c.alpha < 0.0 || c.beta < 0.0)
      d.fail("zeta", fmt::format("zeta = {} at {} Hz and {} at {} Hz make a negative Rayleigh coefficient (alpha = "
                                 "{:.6g} 1/s, beta = {:.6g} s): damping falls below zero at {} frequencies; keep "
                                 "zeta1 / zeta2 between f1 / f2 and f2 / f1",
                                 z[0], f[0], z[1], f[1], c.alpha, c.beta, c.alpha < 0.0 ? "low" : "high"));
    d.finish();
    damping.kind = FrfDamping::Kind::rayleigh;
    damping.rayleigh_hz = {f[0], f[1]};
    damping.rayleigh_zeta = {z[0], z[1]};
  }
  return damping;
}

FrfSpec parse_frf(TomlReader& r, const fs::path& folder) {
  FrfSpec s;
  const std::vector<double> range = r.number_array("frequency_hz");
  if (range.size() != 2 || !(range[0] >= 0.0) || !(range[0] < range[1]))
    r.fail("frequency_hz", "expected [f_min, f_max] with 0 <= f_min < f_max");
  s.f_min = range[0];
  s.f_max = range[1];
  s.step = r.positive("step_hz");
  if ((s.f_max - s.f_min) / s.step > 2e6)
    r.fail("step_hz", "more than 2 million frequencies: choose a larger step or adaptive = true");
  s.adaptive = r.boolean("adaptive", false);
  if (s.adaptive) {
    s.min_step = r.positive("min_step_hz");
    if (s.min_step >= s.step) r.fail("min_step_hz", "must be smaller than step_hz");
  }
  s.damping = parse_damping(r);
  s.full_model = r.boolean("full_model", true);
  if (s.full_model) {
    const long modes = r.integer("full_modes");
    if (modes < 1 || modes > 10000) r.fail("full_modes", "must lie in [1, 10000]");
    s.full_modes = static_cast<int>(modes);
    s.residual_flexibility = r.boolean("residual_flexibility", true);
  }
  s.forces = parse_forces(r);
  s.responses = parse_responses(r);
  if (r.has("force_levels")) {
    s.force_levels = r.number_array("force_levels");
    if (s.force_levels.empty()) r.fail("force_levels", "empty list (leave it out for no linearity sweep)");
    for (double f : s.force_levels)
      if (!(f > 0) || !std::isfinite(f)) r.fail("force_levels", "every level must be a positive force [N]");
  }
  if (r.has("peak_prominence")) {
    s.peak_prominence = r.positive("peak_prominence");
    if (s.peak_prominence < 1.0) r.fail("peak_prominence", "must be >= 1");
  }
  if (r.has("peak_floor")) {
    s.peak_floor = r.non_negative("peak_floor", 0.0);
    if (s.peak_floor >= 1.0) r.fail("peak_floor", "must lie in [0, 1): a fraction of the largest response");
  }
  if (r.has("match_tolerance")) s.match_tolerance = r.positive("match_tolerance");
  if (r.has("rom")) {
    int i = 0;
    std::set<std::string> names;
    for (const toml::node& n : r.array("rom")) {
      if (!n.is_table()) r.fail("rom", "write each reduced model as a [[analysis.rom]] table");
      TomlReader rr(*n.as_table(), fmt::format("{}.rom[{}]", r.path(), i++), r.file());
      s.roms.push_back(parse_rom(rr, folder));
      if (!names.insert(s.roms.back().name).second)
        rr.fail("name", fmt::format("a reduced model named '{}' exists already", s.roms.back().name));
    }
  }
  if (!s.full_model && s.roms.empty())
    r.fail("full_model", "with full_model = false, give at least one [[analysis.rom]]");
  s.pairs = parse_mode_pairs(r);
  return s;
}

}  // namespace bb
