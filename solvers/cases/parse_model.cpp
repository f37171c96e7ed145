// [material], [mesh], [section], [sets], [[bc]], [[load]] -> ModelSpec.
#include "cases/parse_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "cases/parse_bladed_disk.hpp"
#include "cases/parse_common.hpp"
#include "cases/parse_dimensions.hpp"
#include "cases/parse_inp.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

ElementType parse_element(TomlReader& r) {
  std::vector<std::string> names;
  for (ElementType t : element_types()) names.emplace_back(element_name(t));
  const std::string e = r.choice("element", names);
  if (const std::optional<ElementType> t = element_type_named(e)) return *t;
  r.fail("element", "unreachable");
}

// Why a corner coordinate cannot be read ("" when it can): common/input_number's rule, worded for coordinates.
std::string coordinate_problem(double c) {
  return std::isfinite(c) ? number_problem(c) : std::string("coordinates must be finite");
}

std::vector<Eigen::Vector3d> parse_points(TomlReader& r, const std::string& key, size_t count) {
  const toml::array& points = r.array(key);
  if (points.size() != count) r.fail(key, fmt::format("expected {} points, found {}", count, points.size()));
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < count; ++i) {
    const toml::array* p = points[i].as_array();
    if (!p || p->size() != 3 || !(*p)[0].is_number() || !(*p)[1].is_number() || !(*p)[2].is_number())
      r.fail(key, fmt::format("point {} must be [x, y, z] with three numbers", i + 1));
    out.emplace_back(*toml_number((*p)[0]), *toml_number((*p)[1]), *toml_number((*p)[2]));
    for (double c : out.back())
      if (const std::string problem = coordinate_problem(c); !problem.empty())
        r.fail(key, fmt::format("point {}: {}", i + 1, problem));
  }
  return out;
}

// The largest mesh the generators build (nodes): far beyond any that one machine factorizes.
constexpr long kMaxGeneratedNodes = 20'000'000;

int parse_divisions(TomlReader& r, const std::string& key) {
  const long n = r.integer(key);
  if (n < 1) r.fail(key, fmt::format("must be >= 1, found {}", n));
  if (n > 100'000) r.fail(key, fmt::format("{} divisions exceed the limit of 100000", n));
  return static_cast<int>(n);
}

HexBlockSpec parse_hex_block(TomlReader r, ElementType element, std::string& body) {
  HexBlockSpec b;
  // Blocks of one body merge at coincident nodes; different bodies only touch (contact pairs).
  body = r.has("body") ? r.name("body") : std::string("main");
  b.element = element;
  const auto corners = parse_points(r, "corners", 8);
  std::copy(corners.begin(), corners.end(), b.corners.begin());
  b.nx = parse_divisions(r, "nx");
  b.ny = parse_divisions(r, "ny");
  b.nz = parse_divisions(r, "nz");
  if (const double nodes = (b.nx + 1.0) * (b.ny + 1.0) * (b.nz + 1.0) * (topology(element).quadratic() ? 4.0 : 1.0);
      nodes > static_cast<double>(kMaxGeneratedNodes))
    r.fail("nx", fmt::format("{} x {} x {} {} divisions make about {:.3g} nodes, above the limit of {} for a "
                             "generated mesh",
                             b.nx, b.ny, b.nz, element_name(element), nodes, kMaxGeneratedNodes));
  // Orientation: corners 1-4 must run counterclockwise seen from corner 5's side.
  const Eigen::Vector3d e1 = b.corners[1] - b.corners[0], e2 = b.corners[3] - b.corners[0],
                        e3 = b.corners[4] - b.corners[0];
  if (!(e1.cross(e2).dot(e3) > 0))
    r.fail("corners", "corners 1-4 must run counterclockwise seen from corners 5-8 (positive volume)");
  if (const int a = inverted_corner(b.corners); a > 0)
    r.fail("corners", fmt::format("the block is twisted or inverted at corner {}: its elements there would have a "
                                  "non-positive Jacobian (the three block edges leaving every corner must form a "
                                  "right-handed frame)",
                                  a));
  r.finish();
  return b;
}

// The shortest distance between neighbouring nodes along a block's edges [m] (hex20: its midside nodes too).
double smallest_node_spacing(const HexBlockSpec& b) {
  static constexpr int kEdges[12][3] = {{0, 1, 0}, {3, 2, 0}, {4, 5, 0}, {7, 6, 0}, {0, 3, 1}, {1, 2, 1},
                                        {4, 7, 1}, {5, 6, 1}, {0, 4, 2}, {1, 5, 2}, {2, 6, 2}, {3, 7, 2}};
  const int divisions[3] = {b.nx, b.ny, b.nz};
  const double per_division = topology(b.element).quadratic() ? 2.0 : 1.0;
  double out = INFINITY;
  for (const auto& e : kEdges)
    out = std::min(out, (b.corners[e[1]] - b.corners[e[0]]).norm() / (divisions[e[2]] * per_division));
  return out;
}

// [mesh.dimensions] of the two-blade article (the blade_section uses its blade): the defaults are
// documented in articles/two_blade.hpp.
void parse_dimensions(TomlReader& r, TwoBladeDimensions& d) { parse_dimensions(r, d, two_blade_dimension_fields()); }

int small_integer(TomlReader& r, const std::string& key, long lo, long hi, int fallback) {
  const auto v = r.optional_integer(key);
  if (!v) return fallback;
  if (*v < lo || *v > hi) r.fail(key, fmt::format("must lie in {}..{}, found {}", lo, hi, *v));
  return static_cast<int>(*v);
}

// The generated two-blade article: mesh density in [mesh], dimensions in [mesh.dimensions].
void parse_two_blade(TomlReader& r, MeshSpec& m) {
  m.kind = MeshSpec::Kind::two_blade;
  // Far below every clearance validate() admits (1e-6 m), far above rounding in the corners.
  m.merge_tolerance = 1e-7;
  TwoBladeDimensions& d = m.two_blade;
  d.refinement = small_integer(r, "refinement", 1, 64, d.refinement);
  d.thickness_divisions = small_integer(r, "thickness_divisions", 1, 1000, d.thickness_divisions);
  d.airfoil_divisions = small_integer(r, "airfoil_divisions", 1, 1000, d.airfoil_divisions);
  m.glue = r.boolean("glue", true);
  parse_dimensions(r, d);
}

// The chapter-2 blade: the thesis's divisions for the element type unless [mesh.divisions] says
// otherwise, dimensions in [mesh.dimensions].
void parse_blade_section(TomlReader& r, MeshSpec& m) {
  m.kind = MeshSpec::Kind::blade_section;
  if (m.element != ElementType::q4 && m.element != ElementType::cst && m.element != ElementType::hex8)
    r.fail("element", "kind 'blade_section' is meshed with q4, cst or hex8 (the thesis's three meshes)");
  BladeSectionDivisions& n = m.blade_divisions;
  n = blade_section_divisions(m.element);
  if (const toml::table* table = r.optional_table("divisions")) {
    TomlReader t(*table, r.path() + ".divisions", r.file());
    for (auto [key, member] : {std::pair{"root_side_columns", &BladeSectionDivisions::root_side_columns},
                               {"root_rows", &BladeSectionDivisions::root_rows},
                               {"neck_rows", &BladeSectionDivisions::neck_rows},
                               {"lip_rows", &BladeSectionDivisions::lip_rows},
                               {"airfoil_columns", &BladeSectionDivisions::airfoil_columns},
                               {"airfoil_rows", &BladeSectionDivisions::airfoil_rows},
                               {"layers", &BladeSectionDivisions::layers}})
      n.*member = small_integer(t, key, 1, 1000, n.*member);
    t.finish();
  }
  parse_dimensions(r, m.two_blade);
}

MeshSpec parse_mesh(TomlReader r, const fs::path& folder, InpDeck& inp_header) {
  MeshSpec m;
  m.at = r.location();
  const std::string kind = r.choice(
      "kind", {"mapped_quad", "csv", "hex_blocks", "gmsh", "inp", "two_blade", "blade_section", "bladed_disk"});
  if (kind == "inp") {
    parse_inp_mesh(r, m, folder, inp_header);
    r.finish();
    return m;
  }
  m.element = parse_element(r);
  if (kind == "bladed_disk") {
    parse_bladed_disk(r, m);
    r.finish();
    return m;
  }
  if (kind == "blade_section") {
    parse_blade_section(r, m);
    r.finish();
    return m;
  }
  if (kind == "two_blade") {
    if (m.dim() != 3) r.fail("element", "kind 'two_blade' needs a solid element (hex8, hex8i, hex20)");
    parse_two_blade(r, m);
    r.finish();
    return m;
  }
  if (kind == "hex_blocks" || kind == "gmsh") {
    // Gmsh files hold plane meshes too (3-node triangles, 4-node quadrilaterals); blocks are solids.
    if (kind == "hex_blocks" && m.dim() != 3)
      r.fail("element", "kind 'hex_blocks' needs a solid element (hex8, hex8i, hex20)");
    // Only blocks are merged: a Gmsh file's nodes are joined by Gmsh, so the key would do nothing there.
    if (kind == "gmsh" && r.has("merge_tolerance"))
      r.fail("merge_tolerance", "applies to kind = \"hex_blocks\" (a Gmsh mesh is used as its file joins it)");
    m.merge_tolerance = r.non_negative("merge_tolerance", m.merge_tolerance);
    if (kind == "gmsh") {
      m.kind = MeshSpec::Kind::gmsh;
      m.gmsh_file = r.input_file("file", folder);
    } else {
      m.kind = MeshSpec::Kind::hex_blocks;
      int index = 0;
      for (const toml::node& n : r.array("block")) {
        if (!n.is_table()) r.fail("block", "write blocks as [[mesh.block]] tables");
        std::string body;
        m.blocks.push_back(parse_hex_block(TomlReader(*n.as_table(), fmt::format("mesh.block[{}]", index++), r.file()),
                                           m.element, body));
        m.block_bodies.push_back(body);
      }
      if (m.blocks.empty()) r.fail("block", "needs at least one [[mesh.block]]");
      // A tolerance that reaches a neighbouring node of one block would merge an element's own nodes.
      double spacing = INFINITY;
      for (const HexBlockSpec& b : m.blocks) spacing = std::min(spacing, smallest_node_spacing(b));
      if (m.merge_tolerance >= spacing)
        r.fail("merge_tolerance",
               fmt::format("{:g} m reaches the smallest node spacing of the blocks ({:.6g} m): it would merge the "
                           "nodes of one element; nodes that should join lie far closer",
                           m.merge_tolerance, spacing));
    }
    r.finish();
    return m;
  }
  if (kind == "csv") {
    m.kind = MeshSpec::Kind::csv;
    m.nodes_csv = r.input_file("nodes", folder);
    m.elements_csv = r.input_file("elements", folder);
    r.finish();
    return m;
  }
  m.kind = MeshSpec::Kind::mapped_quad;
  if (m.dim() != 2) r.fail("element", "a mapped_quad mesh needs q4 or cst elements (solids: kind = \"hex_blocks\")");
  MappedQuadSpec& q = m.mapped;
  q.element = m.element;
  const toml::array& corners = r.array("corners");
  if (corners.size() != 4) r.fail("corners", fmt::format("expected 4 corner points, found {}", corners.size()));
  for (size_t i = 0; i < 4; ++i) {
    const toml::array* p = corners[i].as_array();
    if (!p || p->size() != 2 || !(*p)[0].is_number() || !(*p)[1].is_number())
      r.fail("corners", fmt::format("corner {} must be [x, y] with two numbers", i + 1));
    q.corners[i] = {*toml_number((*p)[0]), *toml_number((*p)[1])};
    for (double c : q.corners[i])
      if (const std::string problem = coordinate_problem(c); !problem.empty()) r.fail("corners", problem);
  }
  const long nx = r.integer("nx"), ny = r.integer("ny");
  if (nx < 1) r.fail("nx", fmt::format("must be >= 1, found {}", nx));
  if (ny < 1) r.fail("ny", fmt::format("must be >= 1, found {}", ny));
  // Far beyond any mesh one machine factorizes (the work estimate refuses those, with the memory they
  // need), and small enough that generating the mesh to estimate it stays quick.
  constexpr long kMaxNodes = kMaxGeneratedNodes;
  if (nx > kMaxNodes || ny > kMaxNodes || (nx + 1) * (ny + 1) > kMaxNodes)
    r.fail(nx >= ny ? "nx" : "ny", fmt::format("{} x {} divisions exceed the limit of {} nodes", nx, ny, kMaxNodes));
  q.nx = static_cast<int>(nx);
  q.ny = static_cast<int>(ny);
  const std::string numbering = r.choice("numbering", {"rows", "serpentine"}, "rows");
  q.numbering = numbering == "rows" ? NodeNumbering::rows : NodeNumbering::serpentine;
  const std::string diag = r.choice("diagonal", {"bottom_left_to_top_right", "bottom_right_to_top_left", "alternating"},
                                    "bottom_left_to_top_right");
  q.diagonal = diag == "bottom_left_to_top_right"   ? TriangleDiagonal::bottom_left_to_top_right
               : diag == "bottom_right_to_top_left" ? TriangleDiagonal::bottom_right_to_top_left
                                                    : TriangleDiagonal::alternating;
  q.first_node_id = r.optional_integer("first_node_id").value_or(1);
  q.first_element_id = r.optional_integer("first_element_id").value_or(1);
  // Signed area of the corner polygon: clockwise corners would invert every element.
  double area2 = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto& a = q.corners[i];
    const auto& b = q.corners[(i + 1) % 4];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  if (!(area2 > 0)) r.fail("corners", "corners must run counterclockwise and enclose a positive area");
  r.finish();
  return m;
}

NodeSetSpec parse_set(TomlReader r, const std::string& name) {
  NodeSetSpec s;
  s.name = name;
  s.at = r.location();
  if (r.has("ids")) {
    s.ids = r.integer_array("ids");
    if (s.ids.empty()) r.fail("ids", "empty id list");
  }
  s.group = r.optional_label("group").value_or("");
  static const char* axes[] = {"x", "y", "z"};
  bool predicate = false;
  for (int a = 0; a < 3; ++a) {
    if (auto v = r.optional_number(axes[a])) {
      s.equals[a] = *v;
      predicate = true;
    }
    const std::string range_key = std::string(axes[a]) + "_range";
    if (r.has(range_key)) {
      const auto v = r.number_array(range_key);
      if (v.size() != 2 || v[0] > v[1]) r.fail(range_key, "expected [min, max] with min <= max");
      s.range[a] = std::make_pair(v[0], v[1]);
      predicate = true;
    }
  }
  s.tol = r.non_negative("tol", 1e-9);
  if (r.has("body")) s.body = r.name("body");
  if (static_cast<int>(predicate) + static_cast<int>(!s.ids.empty()) + static_cast<int>(!s.group.empty()) != 1)
    r.fail("", "a node set needs exactly one of 'ids', 'group' or a coordinate predicate (x, y, z, x_range, ...)");
  r.finish();
  return s;
}

ConstraintSpec parse_constraint(TomlReader r) {
  ConstraintSpec c;
  c.at = r.location();
  c.constraint.set = r.string("set");
  for (const std::string& d : r.string_array("dofs")) c.constraint.directions.push_back(parse_direction(r, "dofs", d));
  if (c.constraint.directions.empty()) r.fail("dofs", "empty list");
  c.constraint.value = r.optional_number("value").value_or(0.0);
  r.finish();
  return c;
}

// A vector of `dim` numbers (a plane mesh's vectors have x, y only).
Eigen::Vector3d parse_vector(TomlReader& r, const std::string& key, int dim) {
  const std::vector<double> v = r.number_array(key);
  if (static_cast<int>(v.size()) != dim)
    r.fail(key, fmt::format("expected {} components ({}) on a {}D mesh, found {}", dim, dim == 2 ? "x, y" : "x, y, z",
                            dim, v.size()));
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int d = 0; d < dim; ++d) out[d] = v[static_cast<size_t>(d)];
  return out;
}

// [[load]]: a nodal force (type "nodal", the default), a distributed load on boundary edges / faces
// ("pressure", "traction") or a body load ("gravity", "centrifugal").
void parse_load(TomlReader r, int dim, ModelSpec& spec) {
  const std::string type = r.choice("type", {"nodal", "pressure", "traction", "gravity", "centrifugal"}, "nodal");
  if (type == "nodal") {
    LoadSpec l;
    l.at = r.location();
    l.load.set = r.string("set");
    l.load.direction = parse_direction(r, "direction", r.string("direction"));
    l.load.total = r.number("total");
    l.load.split = parse_split(r, "split");
    r.finish();
    spec.loads.push_back(l);
    return;
  }
  if (type == "pressure" || type == "traction") {
    // The facets are named by the set of their nodes: `edges` on a plane mesh, `faces` on a solid.
    const std::string key = dim == 2 ? "edges" : "faces";
    const std::string other = dim == 2 ? "faces" : "edges";
    if (r.has(other))
      r.fail(
          other,
          dim == 2
              ? "a plane (2D) mesh has no element faces to load: a distributed load acts on its edges (edges = \"set\")"
              : "a line load on the edges of a solid is not supported: load its faces (faces = \"set\")");
    SurfaceLoadSpec l;
    l.at = r.location(key);
    l.key = r.path() + "." + key;
    l.load.set = r.string(key);
    if (type == "pressure") {
      l.load.kind = SurfaceLoad::Kind::pressure;
      l.load.pressure = r.number("pressure");
    } else {
      l.load.kind = SurfaceLoad::Kind::traction;
      l.load.traction = parse_vector(r, "traction", dim);
    }
    r.finish();
    spec.surface_loads.push_back(l);
    return;
  }
  BodyLoadSpec l;
  l.at = r.location("type");
  if (type == "gravity") {
    l.load.kind = BodyLoad::Kind::gravity;
    l.load.acceleration = parse_vector(r, "acceleration", dim);
  } else {
    l.load.kind = BodyLoad::Kind::centrifugal;
    l.load.speed = r.positive("speed");
    const std::vector<double> axis = r.number_array("axis");
    if (axis.size() != 3)
      r.fail("axis", fmt::format("expected a direction [x, y, z], found {} components", axis.size()));
    const Eigen::Vector3d a(axis[0], axis[1], axis[2]);
    if (!(a.norm() > 0)) r.fail("axis", "the axis direction must not be zero");
    l.load.axis = a.normalized();
    if (r.has("origin")) l.load.origin = parse_vector(r, "origin", dim);
  }
  r.finish();
  spec.body_loads.push_back(l);
}

// [[contact]]: a pair of surfaces (node sets) of a solid mesh that may touch.
void parse_contact_pair(TomlReader r, ModelSpec& spec) {
  ContactPairSpec c;
  c.at = r.location();
  if (spec.mesh.dim() != 3) r.fail("", "contact pairs need a solid mesh (hex8, hex8i, hex20)");
  c.name = r.name("name");
  for (const ContactPairSpec& other : spec.contact_pairs)
    if (other.name == c.name) r.fail("name", fmt::format("a second contact pair named '{}'", c.name));
  c.contact = r.name("contact");
  c.target = r.name("target");
  if (c.contact == c.target) r.fail("target", fmt::format("the same surface '{}' on both sides of the pair", c.target));
  c.interference = r.boolean("interference", false);
  r.finish();
  spec.contact_pairs.push_back(std::move(c));
}

}  // namespace

// Material, mesh, section, node sets, constraints and loads: the model when it has a mesh.
ModelSpec parse_model(TomlReader& top, const fs::path& folder, bool needs_mass) {
  const fs::path& file = top.file();
  ModelSpec spec;
  InpDeck deck;
  spec.mesh = parse_mesh(TomlReader(top.table("mesh"), "mesh", file), folder, deck);
  const bool from_deck = spec.mesh.kind == MeshSpec::Kind::inp;
  if (from_deck && !top.has("material")) {
    material_from_deck(deck, spec, needs_mass);
  } else {
    TomlReader m(top.table("material"), "material", file);
    spec.section.youngs_modulus = m.positive("E");
    spec.section.poisson_ratio = m.number("nu");
    if (!(spec.section.poisson_ratio > -1 && spec.section.poisson_ratio < 0.5))
      m.fail("nu", fmt::format("must lie in (-1, 0.5), found {}", spec.section.poisson_ratio));
    spec.section.density = m.non_negative("rho", 0.0);
    if (needs_mass && !(spec.section.density > 0))
      m.fail("rho", "must be > 0 for a modal analysis or a forced response");
    m.finish();
    for (const InpMaterial& d : deck.materials)
      spec.mesh.inp_notes.push_back(fmt::format("the deck's *MATERIAL {} ({}) is replaced by the case's [material]",
                                                d.name, d.where));
  }
  if (from_deck && spec.mesh.dim() == 2 && deck.thickness) {
    if (top.has("section"))
      top.fail("section", fmt::format("the deck gives the thickness ({} m at {}); remove [section] or the deck's",
                                      *deck.thickness, deck.thickness_where));
    spec.section.thickness = *deck.thickness;
  } else if (spec.mesh.dim() == 2) {
    TomlReader s(top.table("section"), "section", file);
    spec.section.thickness = s.positive("thickness");
    s.finish();
  } else if (top.has("section")) {
    top.fail("section", "a solid mesh takes no [section] (thickness is for plane stress)");
  }
  if (const toml::table* sets = top.optional_table("sets")) {
    for (const auto& [k, v] : *sets) {
      const std::string name(k.str());
      // Set names become DOF names ("tip.x"), CSV column names and plot file names.
      if (const std::string problem = name_problem(name); !problem.empty())
        TomlReader(*sets, "sets", file).fail(name, problem);
      if (!v.is_table()) top.fail("sets", fmt::format("set '{}' must be a table [sets.{}]", name, name));
      spec.sets.push_back(parse_set(TomlReader(*v.as_table(), "sets." + name, file), name));
      if (spec.mesh.kind == MeshSpec::Kind::two_blade || spec.mesh.kind == MeshSpec::Kind::blade_section ||
          spec.mesh.kind == MeshSpec::Kind::bladed_disk) {
        const auto reserved = spec.mesh.kind == MeshSpec::Kind::two_blade     ? two_blade_set_names()
                              : spec.mesh.kind == MeshSpec::Kind::bladed_disk ? bladed_disk_set_names()
                                                                              : blade_section_set_names();
        const auto contact_sets = two_blade_contact_set_names();
        const bool contact_name = spec.mesh.kind == MeshSpec::Kind::two_blade &&
                                  std::find(contact_sets.begin(), contact_sets.end(), name) != contact_sets.end();
        if (contact_name || std::find(reserved.begin(), reserved.end(), name) != reserved.end())
          throw InputError(fmt::format("{}: 'sets.{}': the {} mesh defines this set itself ({}); choose another name",
                                       spec.sets.back().at.where(), name,
                                       spec.mesh.kind == MeshSpec::Kind::two_blade     ? "two_blade"
                                       : spec.mesh.kind == MeshSpec::Kind::bladed_disk ? "bladed_disk"
                                                                                       : "blade_section",
                                       fmt::join(reserved, ", ")));
      }
    }
  }
  for_each_table_in_array(top, "bc", [&](TomlReader r) {
    const ConstraintSpec c = parse_constraint(r);
    // One direction of a set held at two values: the later would win silently.
    for (const ConstraintSpec& other : spec.constraints)
      for (const Direction d : c.constraint.directions)
        if (other.constraint.set == c.constraint.set && other.constraint.value != c.constraint.value &&
            std::find(other.constraint.directions.begin(), other.constraint.directions.end(), d) !=
                other.constraint.directions.end())
          r.fail("value", fmt::format("set '{}' is held in this direction at {} m already, by the [[bc]] of line {}",
                                      c.constraint.set, other.constraint.value, other.at.line));
    spec.constraints.push_back(c);
  });
  for_each_table_in_array(top, "load", [&](TomlReader r) { parse_load(std::move(r), spec.mesh.dim(), spec); });
  for_each_table_in_array(top, "contact", [&](TomlReader r) { parse_contact_pair(std::move(r), spec); });
  if (!spec.body_loads.empty() && !(spec.section.density > 0))
    throw InputError(fmt::format(
        "{}: a {} load acts through the mass: 'material.rho' must be > 0", spec.body_loads.front().at.where(),
        spec.body_loads.front().load.kind == BodyLoad::Kind::gravity ? "gravity" : "centrifugal"));
  return spec;
}

}  // namespace bb
