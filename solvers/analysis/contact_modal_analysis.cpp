#include "analysis/contact_modal_analysis.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>

#include "assembly/assemble.hpp"
#include "assembly/load_vector.hpp"
#include "common/errors.hpp"
#include "common/progress_clock.hpp"
#include "common/seconds_since.hpp"
#include "contact/static_contact.hpp"
#include "ffrf/body_assembly.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

Eigen::VectorXd frequencies_of(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m,
                               const ModalOptions& options) {
  const ModalSolution sol = lowest_modes(k, m, options);
  return sol.eigenvalues.head(options.n_modes).array().max(0.0).sqrt() / (2 * std::numbers::pi);
}

// Free DOFs of the model with the facing nodes of every pair tied (merged): a selection T from the
// tied equations to every DOF, K_tied = T^T K T. A tied DOF is constrained when any of its nodes is.
Eigen::SparseMatrix<double> tie_pairs(const Model& model, const DofMap& dofs) {
  const int dim = model.mesh.dim;
  std::vector<int> rep(static_cast<size_t>(model.mesh.n_nodes()));
  std::iota(rep.begin(), rep.end(), 0);
  auto find = [&](int n) {
    while (rep[static_cast<size_t>(n)] != n) n = rep[static_cast<size_t>(n)] = rep[static_cast<size_t>(rep[static_cast<size_t>(n)])];
    return n;
  };
  for (const ContactPair& p : model.contact_pairs)
    for (const ContactFacetPair& f : p.facets)
      for (size_t a = 0; a < f.contact.size(); ++a) {
        const int x = find(f.contact[a]), y = find(f.target[a]);
        if (x != y) rep[static_cast<size_t>(std::max(x, y))] = std::min(x, y);
      }
  const int n = dofs.n_global();
  std::vector<char> constrained(static_cast<size_t>(n), 0);
  for (int g = 0; g < n; ++g)
    if (dofs.equation[static_cast<size_t>(g)] < 0) constrained[static_cast<size_t>(find(g / dim) * dim + g % dim)] = 1;
  std::vector<int> equation(static_cast<size_t>(n), -1);
  int next = 0;
  for (int g = 0; g < n; ++g)
    if (find(g / dim) == g / dim && !constrained[static_cast<size_t>(g)]) equation[static_cast<size_t>(g)] = next++;
  std::vector<Eigen::Triplet<double>> t;
  for (int g = 0; g < n; ++g) {
    const int e = equation[static_cast<size_t>(find(g / dim) * dim + g % dim)];
    if (e >= 0) t.emplace_back(g, e, 1.0);
  }
  Eigen::SparseMatrix<double> tie(n, next);
  tie.setFromTriplets(t.begin(), t.end());
  return tie;
}

void validate(const Model& model, const ContactModalSpec& spec, const std::vector<ContactPoint>& points) {
  if (model.contact_pairs.empty())
    throw InputError(fmt::format("{}: a contact_modal analysis needs at least one [[contact]] pair", spec.at.where()));
  const double largest = *std::max_element(spec.interferences.begin(), spec.interferences.end());
  const bool any = std::any_of(model.contact_pairs.begin(), model.contact_pairs.end(),
                               [](const ContactPair& p) { return p.interference; });
  if (largest > 0 && !any)
    throw InputError(fmt::format("{}: 'analysis.interference_m': no contact pair has interference = true, so the "
                                 "interference would act nowhere",
                                 spec.at.where()));
  for (const ContactPoint& p : points) {
    const ContactPair& pair = model.contact_pairs[static_cast<size_t>(p.pair)];
    if (pair.interference && largest >= p.facet_size)
      throw InputError(fmt::format("{}: 'analysis.interference_m': an interference of {:g} m exceeds the {:.3g} m "
                                   "faces of contact pair '{}': a small-displacement contact cannot resolve an "
                                   "overlap larger than the bodies' elements",
                                   spec.at.where(), largest, p.facet_size, pair.name));
  }
}

ResultTable contact_state_table(const Model& model, const std::vector<ContactPoint>& points,
                                const StaticContactSolution& s) {
  std::vector<std::vector<double>> rows;
  for (size_t k = 0; k < points.size(); ++k) {
    const auto ki = static_cast<Index>(k);
    const ContactPoint& p = points[k];
    rows.push_back({static_cast<double>(k + 1), static_cast<double>(p.pair + 1), p.position.x(), p.position.y(),
                    p.position.z(), s.gap[ki], s.pressure[ki], s.shear[ki], s.closed[k] ? 1.0 : 0.0});
  }
  ResultTable t = table_from_rows(
      "contact_state", {"point", "pair", "x_m", "y_m", "z_m", "gap_m", "pressure_pa", "shear_pa", "closed"}, rows);
  std::vector<std::string> names;
  for (const ContactPoint& p : points) names.push_back(model.contact_pairs[static_cast<size_t>(p.pair)].name);
  t.add_text_column("pair_name", std::move(names));
  return t;
}

// Per mode, interference_effect: the frequency at the softest corner (smallest interference and
// FKN) and the stiffest; the rise from the smallest to the largest interference, smallest and largest
// over FKN, and how many interference steps lower it; the rise from the smallest to the largest FKN
// at the smallest and the largest interference; the FKN rise and the interference rise (at the
// smallest FKN) over the first pair's, and FKN's effect at the largest interference over that at the
// smallest. glued_limit: both corners against the glued model.
void add_summary_tables(ContactModalOutcome& o, const ContactModalSpec& spec) {
  const size_t n_i = spec.interferences.size(), n_p = spec.penalty_factors.size();
  auto at = [&](size_t i, size_t j) -> const ContactGridPoint& { return o.grid[i * n_p + j]; };
  std::vector<std::vector<double>> effect, limit;
  // The first pair's penalty effect, which the thesis finds the smallest (L1010).
  auto penalty_rise = [&](int m) { return at(0, n_p - 1).frequencies_hz[m] / at(0, 0).frequencies_hz[m] - 1; };
  auto interference_rise = [&](int m) { return at(n_i - 1, 0).frequencies_hz[m] / at(0, 0).frequencies_hz[m] - 1; };
  auto first_pair = [&](auto&& rise) { return spec.modes > 1 ? 0.5 * (rise(0) + rise(1)) : rise(0); };
  auto ratio = [](double a, double b) { return b != 0 ? a / b : 0.0; };  // 0: nothing to compare with
  for (int m = 0; m < spec.modes; ++m) {
    auto f = [&](size_t i, size_t j) { return at(i, j).frequencies_hz[m]; };
    // Rise from the smallest to the largest interference, the smallest over the penalty factors.
    double rise_min = INFINITY, rise_max = -INFINITY;
    int decreasing = 0;
    for (size_t j = 0; j < n_p; ++j) {
      const double rise = f(n_i - 1, j) / f(0, j) - 1;
      rise_min = std::min(rise_min, rise);
      rise_max = std::max(rise_max, rise);
      for (size_t i = 1; i < n_i; ++i) decreasing += f(i, j) < f(i - 1, j) * (1 - 1e-9) ? 1 : 0;
    }
    const double penalty_low = f(0, n_p - 1) / f(0, 0) - 1;
    const double penalty_high = f(n_i - 1, n_p - 1) / f(n_i - 1, 0) - 1;
    effect.push_back({static_cast<double>(m + 1), f(0, 0), f(n_i - 1, n_p - 1), rise_min, rise_max,
                      static_cast<double>(decreasing), penalty_low, penalty_high,
                      ratio(penalty_low, first_pair(penalty_rise)),
                      ratio(interference_rise(m), first_pair(interference_rise)), ratio(penalty_high, penalty_low)});
    if (o.glued_hz.size() > 0) {
      const double g = o.glued_hz[m];
      limit.push_back({static_cast<double>(m + 1), g, f(n_i - 1, n_p - 1), f(0, 0), f(n_i - 1, n_p - 1) / g - 1,
                       f(0, 0) / g - 1});
    }
  }
  o.tables.emplace("interference_effect",
                   table_from_rows("interference_effect",
                                   {"mode", "softest_hz", "stiffest_hz", "interference_rise_min",
                                    "interference_rise_max", "decreasing_steps", "penalty_rise_at_min_interference",
                                    "penalty_rise_at_max_interference", "penalty_rise_vs_first_pair",
                                    "interference_rise_vs_first_pair", "penalty_effect_ratio"},
                                   effect));
  if (!limit.empty())
    o.tables.emplace("glued_limit", table_from_rows("glued_limit",
                                                    {"mode", "glued_hz", "stiffest_hz", "softest_hz",
                                                     "stiffest_vs_glued", "softest_vs_glued"},
                                                    limit));
}

}  // namespace

ContactModalOutcome run_contact_modal(const Model& model, const ContactModalSpec& spec, const HbmProgress& progress) {
  const auto t0 = Clock::now();
  ContactModalOutcome o;
  const std::vector<ContactPoint> points = contact_points(model.mesh, model.contact_pairs);
  validate(model, spec, points);
  for (const ContactPair& p : model.contact_pairs) o.pair_names.push_back(p.name);
  const DofMap dofs = number_dofs(model);
  const GlobalMatrices global = assemble(model.mesh, model.section);
  const Eigen::SparseMatrix<double> mass = partition(global.mass, dofs).ff;
  const Eigen::VectorXd external = load_vector(model);
  o.free_dofs = dofs.n_free;
  o.contact_points = static_cast<int>(points.size());
  ModalOptions options = spec.options;
  options.n_modes = spec.modes;
  options.ordering = FillOrdering::metis;
  if (spec.modes >= dofs.n_free)
    throw InputError(fmt::format("{}: 'analysis.modes': {} modes of a model with {} free DOFs", spec.at.where(),
                                 spec.modes, dofs.n_free));
  o.setup_seconds = seconds_since(t0);

  const auto n_points = static_cast<Index>(points.size());
  Eigen::VectorXd unit_gap = Eigen::VectorXd::Zero(n_points);  // -1 on the interference pairs
  for (Index k = 0; k < n_points; ++k)
    if (model.contact_pairs[static_cast<size_t>(points[static_cast<size_t>(k)].pair)].interference) unit_gap[k] = -1.0;
  const size_t n_i = spec.interferences.size(), n_p = spec.penalty_factors.size();
  o.grid.resize(n_i * n_p);
  const size_t state_i = spec.state_interference >= 0 ? static_cast<size_t>(spec.state_interference) : n_i - 1;
  const size_t state_p = spec.state_penalty >= 0 ? static_cast<size_t>(spec.state_penalty) : n_p - 1;
  const int steps = static_cast<int>(n_i * n_p);
  ProgressClock clock(steps);
  int finished = 0;
  for (size_t j = 0; j < n_p; ++j) {
    ContactPenalty penalty;
    penalty.normal.resize(n_points);
    penalty.tangential.resize(n_points);
    for (Index k = 0; k < n_points; ++k) {
      penalty.normal[k] = penalty_from_factor(spec.penalty_factors[j], model.section.youngs_modulus,
                                              points[static_cast<size_t>(k)].facet_size);
      penalty.tangential[k] = spec.sticking ? spec.tangential_ratio * penalty.normal[k] : 0.0;
    }
    penalty.roughness = spec.roughness;
    // The previous interference's state seeds the next.
    std::vector<char> closed(points.size(), 1);
    Eigen::VectorXd start;
    for (size_t i = 0; i < n_i; ++i) {
      ContactGridPoint& g = o.grid[i * n_p + j];
      g.interference = spec.interferences[i];
      g.penalty_factor = spec.penalty_factors[j];
      const auto t1 = Clock::now();
      const StaticContactSolution s =
          solve_static_contact(global.stiffness, dofs, points, penalty, spec.interferences[i] * unit_gap, external,
                               closed, {.max_iterations = spec.max_status_iterations},
                               fmt::format("static contact at grid point {} of {} (interference {:g} m, FKN {:g})",
                                           i * n_p + j + 1, steps, spec.interferences[i], spec.penalty_factors[j]),
                               start);
      closed = s.closed;
      // The next interference starts from this state scaled: the bodies' response is nearly linear in it.
      start = s.displacement;
      if (i + 1 < n_i && spec.interferences[i] > 0) start *= spec.interferences[i + 1] / spec.interferences[i];
      g.static_iterations = s.iterations;
      g.newton_iterations = s.newton_iterations;
      g.status_changes = s.status_changes;
      g.closed_fraction = n_points > 0 ? static_cast<double>(std::count(closed.begin(), closed.end(), 1)) /
                                             static_cast<double>(n_points)
                                       : 0.0;
      g.max_pressure = s.pressure.size() > 0 ? s.pressure.maxCoeff() : 0.0;
      g.static_seconds = seconds_since(t1);
      const auto t2 = Clock::now();
      // Linearized about the state: the law's tangent normal stiffness, and a sticking one in proportion.
      ContactPenalty tangent = penalty;
      tangent.normal = s.normal_stiffness;
      if (spec.sticking) tangent.tangential = spec.tangential_ratio * s.normal_stiffness;
      Eigen::SparseMatrix<double> k = global.stiffness + contact_stiffness(points, s.closed, tangent, dofs.n_global());
      if (spec.prestress) k += ffrf::assemble_geometric_stiffness(model.mesh, model.section, s.displacement);
      g.frequencies_hz = frequencies_of(partition(k, dofs).ff, mass, options);
      g.modal_seconds = seconds_since(t2);
      if (i == state_i && j == state_p) o.tables.emplace("contact_state", contact_state_table(model, points, s));
      clock.finished(++finished);
      if (progress)
        progress(fmt::format("interference {:g} m, FKN {:g}: f1 = {:.3f} Hz, {} of the contact points closed  [{}]",
                             g.interference, g.penalty_factor, g.frequencies_hz[0], std::count(closed.begin(), closed.end(), 1),
                             clock.status()));
    }
  }
  if (spec.glued_reference) {
    const auto t3 = Clock::now();
    const Eigen::SparseMatrix<double> tie = tie_pairs(model, dofs);
    const Eigen::SparseMatrix<double> k = tie.transpose() * global.stiffness * tie;
    const Eigen::SparseMatrix<double> m = tie.transpose() * global.mass * tie;
    o.glued_hz = frequencies_of(k, m, options);
    o.glued_seconds = seconds_since(t3);
  }

  std::vector<std::vector<double>> rows;
  for (size_t p = 0; p < o.grid.size(); ++p)
    for (int m = 0; m < spec.modes; ++m) {
      const ContactGridPoint& g = o.grid[p];
      rows.push_back({static_cast<double>(p + 1), g.interference, g.penalty_factor, static_cast<double>(m + 1),
                      g.frequencies_hz[m], g.closed_fraction});
    }
  o.tables.emplace("frequencies_grid",
                   table_from_rows("frequencies_grid",
                                   {"point", "interference_m", "fkn", "mode", "frequency_hz", "closed_fraction"}, rows));
  std::vector<std::vector<double>> cost;
  for (size_t p = 0; p < o.grid.size(); ++p) {
    const ContactGridPoint& g = o.grid[p];
    cost.push_back({static_cast<double>(p + 1), g.interference, g.penalty_factor, static_cast<double>(g.static_iterations),
                    static_cast<double>(g.newton_iterations),
                    static_cast<double>(g.status_changes), g.closed_fraction, g.max_pressure, g.static_seconds,
                    g.modal_seconds});
  }
  o.tables.emplace("contact_grid",
                   table_from_rows("contact_grid",
                                   {"point", "interference_m", "fkn", "static_iterations", "newton_iterations",
                                    "status_changes",
                                    "closed_fraction", "max_pressure_pa", "static_seconds", "modal_seconds"},
                                   cost));
  if (o.glued_hz.size() > 0) {
    std::vector<std::vector<double>> glued;
    for (int m = 0; m < spec.modes; ++m) glued.push_back({static_cast<double>(m + 1), o.glued_hz[m]});
    o.tables.emplace("glued_frequencies", table_from_rows("glued_frequencies", {"mode", "frequency_hz"}, glued));
  }
  add_summary_tables(o, spec);
  return o;
}

}  // namespace bb
