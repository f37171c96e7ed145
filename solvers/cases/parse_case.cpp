// TOML case file -> CaseSpec. The format is documented in cases/README.md.
#include <fmt/format.h>

#include <toml++/toml.h>

#include "cases/case_spec.hpp"
#include "cases/toml_reader.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

Direction parse_direction(TomlReader& r, const std::string& key, const std::string& value) {
  if (value == "x") return 0;
  if (value == "y") return 1;
  if (value == "z") return 2;
  r.fail(key, fmt::format("unknown direction '{}'; expected x, y or z", value));
}

LoadSplit parse_split(TomlReader& r, const std::string& key) {
  return r.choice(key, {"equal", "consistent"}) == "equal" ? LoadSplit::equal : LoadSplit::consistent_edge;
}

ElementType parse_element(TomlReader& r) {
  const std::string e = r.choice("element", {"q4", "cst"});
  return e == "q4" ? ElementType::q4 : ElementType::cst;
}

MeshSpec parse_mesh(TomlReader r, const fs::path& folder) {
  MeshSpec m;
  m.at = r.location();
  const std::string kind = r.choice("kind", {"mapped_quad", "csv"});
  m.element = parse_element(r);
  if (kind == "csv") {
    m.kind = MeshSpec::Kind::csv;
    m.nodes_csv = folder / r.string("nodes");
    m.elements_csv = folder / r.string("elements");
    r.finish();
    return m;
  }
  m.kind = MeshSpec::Kind::mapped_quad;
  MappedQuadSpec& q = m.mapped;
  q.element = m.element;
  const toml::array& corners = r.array("corners");
  if (corners.size() != 4) r.fail("corners", fmt::format("expected 4 corner points, found {}", corners.size()));
  for (size_t i = 0; i < 4; ++i) {
    const toml::array* p = corners[i].as_array();
    if (!p || p->size() != 2 || !(*p)[0].is_number() || !(*p)[1].is_number())
      r.fail("corners", fmt::format("corner {} must be [x, y] with two numbers", i + 1));
    q.corners[i] = {(*p)[0].value<double>().value(), (*p)[1].value<double>().value()};
    if (!q.corners[i].allFinite()) r.fail("corners", "coordinates must be finite");
  }
  const long nx = r.integer("nx"), ny = r.integer("ny");
  if (nx < 1) r.fail("nx", fmt::format("must be >= 1, found {}", nx));
  if (ny < 1) r.fail("ny", fmt::format("must be >= 1, found {}", ny));
  // DOF numbers are int (CHOLMOD's int interface): keep 3 (nx+1)(ny+1) well inside its range.
  constexpr long kMaxNodes = 200'000'000;
  if (nx > kMaxNodes || ny > kMaxNodes || (nx + 1) * (ny + 1) > kMaxNodes)
    r.fail(nx >= ny ? "nx" : "ny", fmt::format("{} x {} divisions exceed the limit of {} nodes", nx, ny, kMaxNodes));
  q.nx = static_cast<int>(nx);
  q.ny = static_cast<int>(ny);
  const std::string numbering = r.choice("numbering", {"rows", "serpentine"}, "rows");
  q.numbering = numbering == "rows" ? NodeNumbering::rows : NodeNumbering::serpentine;
  const std::string diag = r.choice(
      "diagonal", {"bottom_left_to_top_right", "bottom_right_to_top_left", "alternating"}, "bottom_left_to_top_right");
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
  if (predicate == !s.ids.empty())
    r.fail("", "a node set needs either 'ids' or a coordinate predicate (x, y, z, x_range, ...), not both");
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

LoadSpec parse_load(TomlReader r) {
  LoadSpec l;
  l.at = r.location();
  l.load.set = r.string("set");
  l.load.direction = parse_direction(r, "direction", r.string("direction"));
  l.load.total = r.number("total");
  l.load.split = parse_split(r, "split");
  r.finish();
  return l;
}

AnalysisSpec parse_analysis(TomlReader r) {
  AnalysisSpec a;
  const std::string type = r.choice("type", {"static", "modal"});
  if (type == "modal") {
    a.type = AnalysisType::modal;
    const long modes = r.integer("modes");
    if (modes < 1) r.fail("modes", "must be >= 1");
    a.modal.n_modes = static_cast<int>(modes);
    a.modal.shift_frequency_hz = r.optional_number("shift_hz").value_or(a.modal.shift_frequency_hz);
    a.modal.tolerance = r.optional_number("tolerance").value_or(a.modal.tolerance);
  }
  r.finish();
  return a;
}

CheckSpec parse_check(TomlReader r, const fs::path& folder) {
  CheckSpec c;
  c.at = r.location();
  c.name = r.string("name");
  c.result = r.choice("result", {"nodal_displacements", "frequencies"});
  c.reference = folder / r.string("reference");
  c.key = r.string("key");
  TomlReader compare(r.table("compare"), r.path() + ".compare", r.file());
  for (const auto& [k, v] : r.table("compare")) {
    const std::string result_column(k.str());
    c.compare.emplace_back(result_column, compare.string(result_column));
  }
  if (c.compare.empty()) r.fail("compare", "needs at least one 'result_column = \"reference_column\"' pair");
  if (!r.has("abs_tol") && !r.has("rel_tol")) r.fail("", "a check needs abs_tol and/or rel_tol");
  c.abs_tol = r.non_negative("abs_tol", 0.0);
  c.rel_tol = r.non_negative("rel_tol", 0.0);
  c.source = r.optional_string("source").value_or("");
  r.finish();
  return c;
}

RefinementStudySpec parse_study(TomlReader r) {
  RefinementStudySpec s;
  s.at = r.location();
  r.choice("kind", {"refinement"});
  for (long level : r.integer_array("levels")) {
    if (level < 1) r.fail("levels", "refinement factors must be >= 1");
    s.levels.push_back(static_cast<int>(level));
  }
  if (s.levels.size() < 3) r.fail("levels", "need at least 3 levels to estimate a convergence order");
  s.probe_set = r.string("probe_set");
  s.probe_direction = parse_direction(r, "probe_direction", r.string("probe_direction"));
  if (r.has("load_split")) s.load_split = parse_split(r, "load_split");
  s.load_set = r.optional_string("load_set");
  TomlReader ref(r.table("reference"), r.path() + ".reference", r.file());
  ref.choice("kind", {"timoshenko_cantilever"});
  s.beam_length = ref.positive("length");
  s.beam_height = ref.positive("height");
  s.beam_load = ref.number("load");
  s.shear_coefficient = ref.optional_number("shear_coefficient").value_or(s.shear_coefficient);
  if (!(s.shear_coefficient > 0)) ref.fail("shear_coefficient", "must be > 0");
  ref.finish();
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

template <typename Fn>
void for_each_table_in_array(TomlReader& top, const std::string& key, Fn fn) {
  if (!top.has(key)) return;
  const toml::array& arr = top.array(key);
  int index = 0;
  for (const toml::node& n : arr) {
    if (!n.is_table()) top.fail(key, fmt::format("write entries as [[{}]] tables", key));
    fn(TomlReader(*n.as_table(), fmt::format("{}[{}]", key, index++), top.file()));
  }
}

}  // namespace

CaseSpec parse_case_file(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw InputError(fmt::format("{}: case file not found", file.string()));
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: TOML syntax error: {}", file.string(), e.source().begin.line, e.description()));
  }
  const fs::path folder = file.parent_path();
  TomlReader top(root, "", file);
  CaseSpec spec;
  spec.file = file;
  {
    TomlReader c(top.table("case"), "case", file);
    spec.name = c.optional_string("name").value_or(file.stem().string());
    spec.title = c.optional_string("title").value_or(spec.name);
    spec.description = c.optional_string("description").value_or("");
    c.finish();
  }
  spec.analysis = parse_analysis(TomlReader(top.table("analysis"), "analysis", file));
  {
    TomlReader m(top.table("material"), "material", file);
    spec.section.youngs_modulus = m.positive("E");
    spec.section.poisson_ratio = m.number("nu");
    if (!(spec.section.poisson_ratio > -1 && spec.section.poisson_ratio < 0.5))
      m.fail("nu", fmt::format("must lie in (-1, 0.5), found {}", spec.section.poisson_ratio));
    spec.section.density = m.non_negative("rho", 0.0);
    if (spec.analysis.type == AnalysisType::modal && !(spec.section.density > 0))
      m.fail("rho", "must be > 0 for a modal analysis");
    m.finish();
  }
  {
    TomlReader s(top.table("section"), "section", file);
    spec.section.thickness = s.positive("thickness");
    s.finish();
  }
  spec.mesh = parse_mesh(TomlReader(top.table("mesh"), "mesh", file), folder);
  if (const toml::table* sets = top.optional_table("sets")) {
    for (const auto& [k, v] : *sets) {
      const std::string name(k.str());
      if (!v.is_table()) top.fail("sets", fmt::format("set '{}' must be a table [sets.{}]", name, name));
      spec.sets.push_back(parse_set(TomlReader(*v.as_table(), "sets." + name, file), name));
    }
  }
  for_each_table_in_array(top, "bc", [&](TomlReader r) { spec.constraints.push_back(parse_constraint(std::move(r))); });
  for_each_table_in_array(top, "load", [&](TomlReader r) { spec.loads.push_back(parse_load(std::move(r))); });
  for_each_table_in_array(top, "check", [&](TomlReader r) { spec.checks.push_back(parse_check(std::move(r), folder)); });
  if (const toml::table* study = top.optional_table("study")) {
    spec.study = parse_study(TomlReader(*study, "study", file));
    if (spec.mesh.kind != MeshSpec::Kind::mapped_quad || spec.analysis.type != AnalysisType::static_linear)
      top.fail("study", "a refinement study needs a mapped_quad mesh and a static analysis");
  }
  top.finish();
  return spec;
}

}  // namespace bb
