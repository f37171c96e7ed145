#include "report/calculix_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "common/errors.hpp"
#include "contact/surface_contact.hpp"
#include "mesh/boundary.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

// ccx reads every real with Fortran format f20.0 from the first 20 characters of a field
// (e.g. nodes.f), so a longer number would be cut silently. The shortest round-trip form fits
// for most values; otherwise 14 significant digits do.
std::string ccx_real(double v) {
  std::string s = fmt::format("{}", v);
  if (s.size() > 20) s = fmt::format("{:.13e}", v);
  if (s.size() > 20)
    throw InputError(fmt::format("CalculiX export: {} does not fit ccx's 20-character number field", s));
  return s;
}

// "hex8, hex8i and hex20": the types ccx takes, from the element table.
std::string exported_names() {
  std::vector<std::string_view> names;
  for (ElementType t : element_types())
    if (topology(t).dimension == 3 && !topology(t).calculix.empty()) names.push_back(topology(t).name);
  std::string out;
  for (size_t i = 0; i < names.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : i + 1 == names.size() ? " and " : ", ", names[i]);
  return out;
}

std::string_view ccx_element_type(ElementType type) {
  const ElementTopology& t = topology(type);
  if (t.dimension == 3 && !t.calculix.empty()) return t.calculix;
  throw InputError(fmt::format("CalculiX export: element type '{}' is not a 3D solid ccx takes; only {} are exported",
                               t.name, exported_names()));
}

// ccx set names are case-insensitive words; keep letters, digits and '_' and make them unique.
std::string ccx_set_name(const std::string& name, std::set<std::string>& used) {
  std::string base = "N_";
  for (const char c : name)
    base += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(static_cast<unsigned char>(c)))
                                                        : '_';
  base.resize(std::min<size_t>(base.size(), 70));
  std::string candidate = base;
  for (int k = 2; used.count(candidate) != 0; ++k) candidate = fmt::format("{}_{}", base, k);
  used.insert(candidate);
  return candidate;
}

// Data lines of at most `per_line` entries; a line ending in a comma continues on the next.
void write_list(std::ofstream& out, const std::vector<long>& values, size_t per_line, bool continued) {
  for (size_t i = 0; i < values.size(); ++i) {
    out << values[i];
    if (i + 1 < values.size()) out << (((i + 1) % per_line == 0) ? ",\n" : ", ");
  }
  out << (continued ? ",\n" : "\n");
}

// Contact pairs as ccx surfaces, interactions and pairs. ccx face k of a hexahedron is our facet k - 1
// (mesh/element_topology.cpp lists them in CalculiX's order: S1 = 1-2-3-4, S2 = 5-8-7-6, ...).
void write_contact(std::ofstream& out, const Model& model, const CalculixContact& c) {
  if (c.roughness > 0)
    throw InputError(
        "CalculiX export: the stiffening (rough) contact law has no ccx counterpart; export a case with "
        "roughness_m = 0 (ccx's PRESSURE-OVERCLOSURE=LINEAR is the linear penalty law)");
  const Mesh& mesh = model.mesh;
  std::vector<long> first_element(mesh.blocks.size() + 1, 1);
  for (size_t k = 0; k < mesh.blocks.size(); ++k)
    first_element[k + 1] = first_element[k] + static_cast<long>(mesh.blocks[k].conn.rows());
  auto sorted = [](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  // Each face's size as the analysis measures it (contact/surface_contact), so kn is the analysis's.
  std::map<const ContactFacetPair*, double> facet_size;
  for (const ContactPoint& p : contact_points(mesh, model.contact_pairs)) facet_size[p.facet] = p.facet_size;
  int group = 0;
  for (const ContactPair& pair : model.contact_pairs) {
    std::map<std::vector<int>, Facet> by_nodes;  // boundary facets of either side, by their sorted nodes
    for (const std::string& set : {pair.contact_set, pair.target_set})
      for (Facet& f : boundary_facets_within(mesh, model.node_sets.at(set))) by_nodes.emplace(sorted(f.nodes), f);
    // Faces of equal size share a penalty kn = FKN E / h: one ccx interaction per size.
    std::map<long, std::pair<std::vector<const Facet*>, std::vector<const Facet*>>> by_size;
    std::map<long, double> size_of;
    for (const ContactFacetPair& f : pair.facets) {
      const Facet& slave = by_nodes.at(sorted(f.contact));
      const Facet& master = by_nodes.at(sorted(f.target));
      const double h = facet_size.at(&f);
      const long key = std::lround(h * 1e9);
      size_of[key] = h;
      by_size[key].first.push_back(&slave);
      by_size[key].second.push_back(&master);
    }
    for (const auto& [key, sides] : by_size) {
      ++group;
      const double kn = penalty_from_factor(c.penalty_factor, model.section.youngs_modulus, size_of.at(key));
      for (int side = 0; side < 2; ++side) {
        out << fmt::format("*SURFACE, NAME={}{}, TYPE=ELEMENT\n", side == 0 ? "SLAVE" : "MASTER", group);
        for (const Facet* f : side == 0 ? sides.first : sides.second)
          out << fmt::format("{}, S{}\n", first_element[static_cast<size_t>(f->block)] + f->element, f->local + 1);
      }
      out << fmt::format("** pair '{}', faces of size {:.6g} m: kn = FKN E / h = {:.6g} Pa/m\n", pair.name,
                         size_of.at(key), kn);
      out << fmt::format("*CONTACT PAIR, INTERACTION=SI{}, TYPE=SURFACE TO SURFACE\nSLAVE{}, MASTER{}\n", group, group,
                         group);
      out << fmt::format("*SURFACE INTERACTION, NAME=SI{}\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{}, 0.\n",
                         group, ccx_real(kn));
      if (c.sticking) out << fmt::format("*FRICTION\n1000., {}\n", ccx_real(c.tangential_ratio * kn));
      if (pair.interference && c.interference > 0)
        out << fmt::format("*CLEARANCE, MASTER=MASTER{}, SLAVE=SLAVE{}, VALUE={}\n", group, group,
                           ccx_real(-c.interference));
    }
  }
}

void write_cyclic(std::ofstream& out, const Model& model, const CalculixCyclic& c) {
  std::map<int, std::set<Direction>> constrained;
  for (const Constraint& k : model.constraints)
    if (const auto it = model.node_sets.find(k.set); it != model.node_sets.end())
      for (const int n : it->second) constrained[n].insert(k.directions.begin(), k.directions.end());
  for (const auto& [name, set, dependent] :
       {std::tuple{"CYCLIC_LEFT", c.left, false}, {"CYCLIC_RIGHT", c.right, true}}) {
    const auto it = model.node_sets.find(set);
    if (it == model.node_sets.end())
      throw InputError(fmt::format("CalculiX export: cyclic face set '{}' is not a node set of the model", set));
    std::vector<long> nodes;
    for (const int i : it->second) {
      const auto fixed = constrained.find(i);
      if (dependent && fixed != constrained.end() && fixed->second.size() != 3)
        throw InputError(
            fmt::format("CalculiX export: node {} of cyclic face '{}' is constrained in some directions "
                        "only: ccx can neither tie it nor leave it out",
                        model.mesh.node_ids[static_cast<size_t>(i)], set));
      if (!dependent || fixed == constrained.end()) nodes.push_back(i + 1L);
    }
    if (nodes.empty())
      throw InputError(fmt::format("CalculiX export: every node of cyclic face '{}' is clamped: nothing to tie", set));
    out << fmt::format("*NSET, NSET={}\n", name);
    write_list(out, nodes, 10, false);
    out << fmt::format("*SURFACE, NAME=S_{}, TYPE=NODE\n{}\n", name, name);
  }
  out << "*TIE, NAME=CYCLIC, CYCLIC SYMMETRY\nS_CYCLIC_RIGHT, S_CYCLIC_LEFT\n"
      << fmt::format("*CYCLIC SYMMETRY MODEL, N={}, NGRAPH=1, TIE=CYCLIC\n0., 0., 0., 0., 0., 1.\n", c.sectors);
}

}  // namespace

void write_calculix_frequency_deck(const Model& model, int n_modes, const std::filesystem::path& inp,
                                   const CalculixContact* contact, const CalculixCyclic* cyclic) {
  const Mesh& mesh = model.mesh;
  if (mesh.dim != 3) throw InputError("CalculiX export: only 3D solid meshes (hex8, hex8i, hex20) are exported");
  if (n_modes < 1) throw InputError(fmt::format("CalculiX export: asked for {} modes; give at least 1", n_modes));
  for (const Constraint& c : model.constraints)
    if (c.value != 0.0)
      throw InputError(
          fmt::format("CalculiX export: constraint on set '{}' prescribes {} m; a frequency step needs "
                      "homogeneous constraints (value 0)",
                      c.set, c.value));
  for (const ElementBlock& b : mesh.blocks) ccx_element_type(b.type);  // reject before writing anything

  std::ofstream out(inp);
  if (!out) throw std::runtime_error("cannot write " + inp.string());
  out << "** CalculiX deck written by bladebench (report/calculix_export). SI units: m, Pa, kg/m^3.\n"
         "** Node n = bladebench internal node index n-1; elements numbered 1..m over the blocks in order.\n";
  if (!model.loads.empty())
    out << fmt::format("** {} nodal load(s) of the case left out: a frequency step does not use them.\n",
                       model.loads.size());

  out << "*NODE, NSET=NALL\n";
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    out << i + 1;
    for (int d = 0; d < 3; ++d) out << ", " << ccx_real(mesh.coords(i, d));
    out << '\n';
  }

  long element = 0;
  for (size_t k = 0; k < mesh.blocks.size(); ++k) {
    const ElementBlock& b = mesh.blocks[k];
    out << fmt::format("*ELEMENT, TYPE={}, ELSET=E{}\n", ccx_element_type(b.type), k + 1);
    std::vector<long> nodes(static_cast<size_t>(b.conn.cols()));
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      for (Eigen::Index a = 0; a < b.conn.cols(); ++a) nodes[static_cast<size_t>(a)] = b.conn(e, a) + 1L;
      // Ten node numbers a line keeps even 10-digit numbers within ccx's line length.
      out << ++element << ", ";
      write_list(out, nodes, 10, false);
    }
  }

  std::map<std::string, std::string> set_names;  // model set -> ccx set
  std::set<std::string> used{"NALL"};
  for (const Constraint& c : model.constraints) {
    if (set_names.count(c.set) != 0) continue;
    const auto it = model.node_sets.find(c.set);
    if (it == model.node_sets.end())
      throw InputError(fmt::format("CalculiX export: constraint names unknown node set '{}'", c.set));
    const std::string name = ccx_set_name(c.set, used);
    set_names.emplace(c.set, name);
    out << fmt::format("*NSET, NSET={}\n", name);
    std::vector<long> nodes;
    for (const int i : it->second) nodes.push_back(i + 1L);
    write_list(out, nodes, 10, false);
  }
  if (!model.constraints.empty()) {
    out << "*BOUNDARY\n";
    for (const Constraint& c : model.constraints)
      for (const Direction d : c.directions) out << fmt::format("{}, {}, {}\n", set_names.at(c.set), d + 1, d + 1);
  }

  out << "*MATERIAL, NAME=MAT\n*ELASTIC\n"
      << ccx_real(model.section.youngs_modulus) << ", " << ccx_real(model.section.poisson_ratio) << '\n'
      << "*DENSITY\n"
      << ccx_real(model.section.density) << '\n';
  for (size_t k = 0; k < mesh.blocks.size(); ++k)
    out << fmt::format("*SOLID SECTION, ELSET=E{}, MATERIAL=MAT\n", k + 1);

  if (cyclic) write_cyclic(out, model, *cyclic);
  if (contact) {
    write_contact(out, model, *contact);
    out << "*STEP\n*STATIC\n*END STEP\n*STEP, PERTURBATION\n";
  } else {
    out << "*STEP\n";
  }
  out << "*FREQUENCY\n" << n_modes << '\n';
  if (cyclic) out << fmt::format("*SELECT CYCLIC SYMMETRY MODES, NMIN={}, NMAX={}\n", cyclic->nd_min, cyclic->nd_max);
  out << "** add '*NODE FILE' and 'U' here to write the mode shapes to the .frd file\n"
         "*END STEP\n";
  if (!out) throw std::runtime_error("failed writing " + inp.string());
}

}  // namespace bb
