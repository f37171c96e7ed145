#include "model/build_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "mesh/abaqus_inp.hpp"
#include "mesh/boundary.hpp"
#include "mesh/csv_mesh.hpp"
#include "mesh/gmsh_import.hpp"
#include "mesh/hex_block.hpp"
#include "model/contact_pairs.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

void require_file(const fs::path& file, const SourceLocation& at) {
  if (const std::string why = file_problem(file); why == "no such file")
    throw InputError(fmt::format("{}: file not found: {}", at.where(), file.string()));
  else if (!why.empty())
    throw InputError(fmt::format("{}: {}: cannot open ({})", at.where(), file.string(), why));
}

// Merged mesh of the two-blade article and the node sets it defines itself (the names of
// two_blade_set_names()): every master point must be a node, since the thesis's reduced
// models and forces sit on nodes.
Mesh build_two_blade(const MeshSpec& spec, std::map<std::string, std::vector<int>>& sets) {
  const TwoBladeArticle article = two_blade_article(spec.two_blade, spec.element);
  Mesh mesh;
  // Body of each node: blade 1, blade 2, or the fixture with its wedges (glued to its floor).
  std::vector<int> body_of_node;
  try {
    if (spec.glue) {
      std::vector<Mesh> parts;
      for (const HexBlockSpec& b : article.blocks) parts.push_back(generate_hex_block(b));
      mesh = merge_meshes(parts, spec.merge_tolerance);
    } else {
      std::array<std::vector<Mesh>, 3> groups;
      for (size_t i = 0; i < article.blocks.size(); ++i) {
        const TwoBladeBody body = article.body[i];
        const size_t g = body == TwoBladeBody::blade1 ? 0 : body == TwoBladeBody::blade2 ? 1 : 2;
        groups[g].push_back(generate_hex_block(article.blocks[i]));
      }
      std::vector<Mesh> bodies;
      for (const auto& g : groups) bodies.push_back(merge_meshes(g, spec.merge_tolerance));
      std::vector<std::vector<int>> origin;
      mesh = concatenate_meshes(bodies, &origin);
      body_of_node.assign(static_cast<size_t>(mesh.n_nodes()), -1);
      for (size_t g = 0; g < origin.size(); ++g)
        for (int n : origin[g]) body_of_node[static_cast<size_t>(n)] = static_cast<int>(g);
    }
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("{}: two_blade mesh: {}", spec.at.where(), e.what()));
  }
  constexpr double kOnNode = 1e-6;  // [m] farther than this, the point has no node
  for (const auto& [name, point] : article.points) {
    int best = -1;
    double best_distance = INFINITY;
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      const double distance = (mesh.coords.row(n).transpose() - point).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = n;
      }
    }
    if (best_distance > kOnNode)
      throw InputError(
          fmt::format("{}: two_blade mesh: point {} ({:.6g}, {:.6g}, {:.6g}) has no node (nearest {:.3g} m away)",
                      spec.at.where(), name, point.x(), point.y(), point.z(), best_distance));
    sets[name] = {best};
  }
  constexpr double kOnFace = 1e-9;  // [m]
  auto select = [&](const std::string& name, auto&& on) {
    std::vector<int>& nodes = sets[name];
    for (int n = 0; n < mesh.n_nodes(); ++n)
      if (on(mesh.coords(n, 0), mesh.coords(n, 1))) nodes.push_back(n);
    if (nodes.empty())
      throw InputError(fmt::format("{}: two_blade mesh: set '{}' matches no node", spec.at.where(), name));
  };
  select("fixture_base", [&](double, double y) { return std::abs(y - article.fixture_base_y) <= kOnFace; });
  select("fixture_left", [&](double x, double) { return std::abs(x - article.fixture_left_x) <= kOnFace; });
  select("fixture_right", [&](double x, double) { return std::abs(x - article.fixture_right_x) <= kOnFace; });
  for (size_t b = 0; b < 2; ++b) {
    const TipFace& tip = article.tips[b];
    select(fmt::format("tip{}", b + 1), [&](double x, double y) {
      return std::abs(y - tip.y) <= kOnFace && x >= tip.x_min - kOnFace && x <= tip.x_max + kOnFace;
    });
  }
  if (spec.glue) return mesh;
  // The root interfaces, by body: the shoulders are the root's x-intervals under the arms.
  const TwoBladeDimensions& d = spec.two_blade;
  const auto& Y = article.levels;
  for (int b = 0; b < 2; ++b) {
    const double o = b * d.p;
    auto in = [&](double x, double x0, double x1) { return x >= o + x0 - kOnFace && x <= o + x1 + kOnFace; };
    auto shoulder = [&](double x) { return in(x, 0.0, d.x_n0() - d.g_s) || in(x, d.x_n1 + d.g_s, d.B_r); };
    auto on_body = [&](int n, int body) { return body_of_node[static_cast<size_t>(n)] == body; };
    auto select_on = [&](const std::string& name, int body, double y, auto&& x_ok) {
      std::vector<int>& nodes = sets[name];
      for (int n = 0; n < mesh.n_nodes(); ++n)
        if (on_body(n, body) && std::abs(mesh.coords(n, 1) - y) <= kOnFace && x_ok(mesh.coords(n, 0)))
          nodes.push_back(n);
      if (nodes.empty())
        throw InputError(fmt::format("{}: two_blade mesh: set '{}' matches no node", spec.at.where(), name));
    };
    const std::string k = std::to_string(b + 1);
    select_on("root" + k + "_top", b, Y[3], shoulder);
    select_on("arm" + k + "_bottom", 2, Y[3], shoulder);
    select_on("root" + k + "_bottom", b, Y[2], [&](double x) { return in(x, 0.0, d.B_r); });
    select_on("wedge" + k + "_top", 2, Y[2], [&](double x) { return in(x, 0.0, d.B_r); });
  }
  return mesh;
}

// A deck's mesh; its node sets as groups for [sets] group = ..., those its *BOUNDARY names as node
// sets of the model, and its *BOUNDARY as constraints.
void read_deck(const ModelSpec& spec, Model& model, NodeGroups& groups) {
  require_file(spec.mesh.inp_file, spec.mesh.at);
  InpDeck deck = read_abaqus_inp(spec.mesh.inp_file, spec.mesh.inp_folder);
  model.mesh = std::move(deck.mesh);
  groups = std::move(deck.node_sets);
  for (const InpBoundary& b : deck.boundaries) {
    for (const NodeSetSpec& s : spec.sets)
      if (s.name == b.set)
        throw InputError(fmt::format("{}: node set '{}': the deck's *BOUNDARY ({}) holds a set of this name; choose "
                                     "another name",
                                     s.at.where(), s.name, b.where));
    Constraint c{b.set, {}, b.value};
    for (int d = b.first; d <= b.last; ++d) {
      if (d > model.mesh.dim)
        throw InputError(fmt::format("{}: *BOUNDARY: DOF {} on a plane mesh (DOFs 1 and 2)", b.where, d));
      c.directions.push_back(d - 1);
    }
    model.node_sets[b.set] = groups.at(b.set);
    model.constraints.push_back(std::move(c));
  }
  model.import_notes = std::move(deck.notes);
  model.import_notes.insert(model.import_notes.end(), spec.mesh.inp_notes.begin(), spec.mesh.inp_notes.end());
}

}  // namespace

std::vector<int> select_nodes(const Mesh& mesh, const NodeSetSpec& set, const NodeGroups* groups) {
  std::vector<int> nodes;
  if (!set.group.empty()) {
    auto it = groups ? groups->find(set.group) : NodeGroups::const_iterator{};
    if (!groups || it == groups->end()) {
      std::string known;
      if (groups)
        for (const auto& [name, members] : *groups) known += (known.empty() ? "" : ", ") + name;
      throw InputError(fmt::format("{}: node set '{}': the mesh has no group '{}' (a Gmsh physical group or a deck's *NSET){}", set.at.where(), set.name,
                                   set.group, known.empty() ? "" : " (groups: " + known + ")"));
    }
    nodes = it->second;
  } else if (!set.ids.empty()) {
    for (long id : set.ids) {
      const int n = mesh.index_of(id);
      if (n < 0)
        throw InputError(
            fmt::format("{}: node set '{}' names node {}, which is not in the mesh", set.at.where(), set.name, id));
      nodes.push_back(n);
    }
  } else {
    if (mesh.dim == 2 && (set.equals[2] || set.range[2]))
      throw InputError(fmt::format("{}: node set '{}': a z predicate on a plane (2D) mesh", set.at.where(), set.name));
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      bool match = true;
      for (int a = 0; a < 3 && match; ++a) {
        const double c = a < mesh.dim ? mesh.coords(n, a) : 0.0;
        if (set.equals[a] && std::abs(c - *set.equals[a]) > set.tol) match = false;
        if (set.range[a] && (c < set.range[a]->first - set.tol || c > set.range[a]->second + set.tol)) match = false;
      }
      if (match) nodes.push_back(n);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.empty()) throw InputError(fmt::format("{}: node set '{}' matches no node", set.at.where(), set.name));
  return nodes;
}

Model build_model(const ModelSpec& spec) {
  Model model;
  NodeGroups groups;
  NodeGroups body_nodes;  // hex_blocks: the nodes of each body
  switch (spec.mesh.kind) {
    case MeshSpec::Kind::csv:
      require_file(spec.mesh.nodes_csv, spec.mesh.at);
      require_file(spec.mesh.elements_csv, spec.mesh.at);
      model.mesh = read_csv_mesh(spec.mesh.nodes_csv, spec.mesh.elements_csv, spec.mesh.element);
      break;
    case MeshSpec::Kind::mapped_quad:
      model.mesh = generate_mapped_quad(spec.mesh.mapped);
      break;
    case MeshSpec::Kind::hex_blocks: {
      // Bodies in order of first appearance; each merged, then set side by side unmerged.
      std::vector<std::string> names;
      std::vector<std::vector<Mesh>> bodies;
      for (size_t i = 0; i < spec.mesh.blocks.size(); ++i) {
        const std::string name = i < spec.mesh.block_bodies.size() ? spec.mesh.block_bodies[i] : "main";
        const auto b = static_cast<size_t>(std::find(names.begin(), names.end(), name) - names.begin());
        if (b == names.size()) {
          names.push_back(name);
          bodies.emplace_back();
        }
        bodies[b].push_back(generate_hex_block(spec.mesh.blocks[i]));
      }
      std::vector<Mesh> merged;
      for (std::vector<Mesh>& parts : bodies)
        merged.push_back(parts.size() == 1 ? std::move(parts.front()) : merge_meshes(parts, spec.mesh.merge_tolerance));
      std::vector<std::vector<int>> origin;
      model.mesh = concatenate_meshes(merged, &origin);
      for (size_t b = 0; b < names.size(); ++b) {
        std::vector<int>& nodes = body_nodes[names[b]];
        nodes = origin[b];
        std::sort(nodes.begin(), nodes.end());
      }
      break;
    }
    case MeshSpec::Kind::two_blade:
      model.mesh = build_two_blade(spec.mesh, model.node_sets);
      break;
    case MeshSpec::Kind::blade_section: {
      BladeSection b = blade_section(spec.mesh.two_blade, spec.mesh.blade_divisions, spec.mesh.element);
      model.mesh = std::move(b.mesh);
      model.node_sets = std::move(b.sets);
      break;
    }
    case MeshSpec::Kind::bladed_disk: {
      BladedDiskSector s = bladed_disk_sector(spec.mesh.bladed_disk, spec.mesh.element);
      model.mesh = std::move(s.mesh);
      model.node_sets = std::move(s.sets);
      break;
    }
    case MeshSpec::Kind::none:
      return model;  // the analysis brings its own matrices
    case MeshSpec::Kind::gmsh: {
      require_file(spec.mesh.gmsh_file, spec.mesh.at);
      // Which element an 8-node Gmsh hexahedron becomes (plane meshes: triangles and quads map by type).
      const ElementType linear = spec.mesh.element == ElementType::hex8i ? ElementType::hex8i : ElementType::hex8;
      GmshMesh g = read_gmsh_msh41(spec.mesh.gmsh_file, linear);
      for (const auto& b : g.mesh.blocks)
        if (b.type != spec.mesh.element)
          throw InputError(fmt::format("{}: the Gmsh file holds {} elements, the case says mesh.element = \"{}\"",
                                       spec.mesh.at.where(), element_name(b.type), element_name(spec.mesh.element)));
      model.mesh = std::move(g.mesh);
      groups = std::move(g.node_groups);
      break;
    }
    case MeshSpec::Kind::inp:
      read_deck(spec, model, groups);
      break;
  }
  model.section = spec.section;
  for (const NodeSetSpec& s : spec.sets) {
    std::vector<int> nodes = select_nodes(model.mesh, s, &groups);
    if (!s.body.empty()) {
      const auto body = body_nodes.find(s.body);
      if (body == body_nodes.end()) {
        std::string known;
        for (const auto& [name, members] : body_nodes) known += (known.empty() ? "" : ", ") + name;
        throw InputError(
            fmt::format("{}: node set '{}': the mesh has no body '{}' ({})", s.at.where(), s.name, s.body,
                        known.empty() ? "bodies are named by [[mesh.block]] body = ..." : "bodies: " + known));
      }
      std::vector<int> in_body;
      std::set_intersection(nodes.begin(), nodes.end(), body->second.begin(), body->second.end(),
                            std::back_inserter(in_body));
      if (in_body.empty())
        throw InputError(fmt::format("{}: node set '{}' matches no node of body '{}'", s.at.where(), s.name, s.body));
      nodes = std::move(in_body);
    }
    model.node_sets[s.name] = std::move(nodes);
  }
  auto require_set = [&](const std::string& name, const SourceLocation& at) {
    if (!model.node_sets.count(name)) throw InputError(fmt::format("{}: unknown node set '{}'", at.where(), name));
  };
  for (const ConstraintSpec& c : spec.constraints) {
    require_set(c.constraint.set, c.at);
    for (Direction d : c.constraint.directions)
      if (d >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", c.at.where()));
    model.constraints.push_back(c.constraint);
  }
  for (const LoadSpec& l : spec.loads) {
    require_set(l.load.set, l.at);
    if (l.load.direction >= model.mesh.dim) throw InputError(fmt::format("{}: direction z on a 2D mesh", l.at.where()));
    model.loads.push_back(l.load);
  }
  for (const SurfaceLoadSpec& l : spec.surface_loads) {
    const auto set = model.node_sets.find(l.load.set);
    if (set == model.node_sets.end())
      throw InputError(fmt::format("{}: '{}': unknown node set '{}'", l.at.where(), l.key, l.load.set));
    if (boundary_facets_within(model.mesh, set->second).empty())
      throw InputError(fmt::format("{}: '{}': node set '{}' holds no boundary {} of the mesh ({})", l.at.where(), l.key,
                                   l.load.set, model.mesh.dim == 2 ? "edge" : "face",
                                   model.mesh.dim == 2
                                       ? "an element edge on the boundary is loaded when both its nodes lie in the set"
                                       : "an element face on the boundary is loaded when all its nodes lie in the set, "
                                         "a hex20 face's mid-edge nodes too"));
    model.surface_loads.push_back(l.load);
  }
  for (const BodyLoadSpec& l : spec.body_loads) model.body_loads.push_back(l.load);
  for (const ContactPairSpec& c : spec.contact_pairs) model.contact_pairs.push_back(build_contact_pair(model, c));
  return model;
}

}  // namespace bb
