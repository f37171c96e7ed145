// TOML case file -> CaseSpec. The format is documented in cases/README.md.
#include <fmt/format.h>

#include <algorithm>

#include <toml++/toml.h>

#include "cases/case_spec.hpp"
#include "cases/parse_contact_loop.hpp"
#include "cases/parse_frf.hpp"
#include "cases/parse_hbm.hpp"
#include "cases/parse_time.hpp"
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
  const std::string e = r.choice("element", {"q4", "cst", "hex8", "hex8i", "hex20"});
  for (ElementType t : {ElementType::q4, ElementType::cst, ElementType::hex8, ElementType::hex8i, ElementType::hex20})
    if (element_name(t) == e) return t;
  r.fail("element", "unreachable");
}

std::vector<Eigen::Vector3d> parse_points(TomlReader& r, const std::string& key, size_t count) {
  const toml::array& points = r.array(key);
  if (points.size() != count) r.fail(key, fmt::format("expected {} points, found {}", count, points.size()));
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < count; ++i) {
    const toml::array* p = points[i].as_array();
    if (!p || p->size() != 3 || !(*p)[0].is_number() || !(*p)[1].is_number() || !(*p)[2].is_number())
      r.fail(key, fmt::format("point {} must be [x, y, z] with three numbers", i + 1));
    out.emplace_back((*p)[0].value<double>().value(), (*p)[1].value<double>().value(), (*p)[2].value<double>().value());
    if (!out.back().allFinite()) r.fail(key, "coordinates must be finite");
  }
  return out;
}

int parse_divisions(TomlReader& r, const std::string& key) {
  const long n = r.integer(key);
  if (n < 1) r.fail(key, fmt::format("must be >= 1, found {}", n));
  if (n > 100'000) r.fail(key, fmt::format("{} divisions exceed the limit of 100000", n));
  return static_cast<int>(n);
}

HexBlockSpec parse_hex_block(TomlReader r, ElementType element) {
  HexBlockSpec b;
  b.element = element;
  const auto corners = parse_points(r, "corners", 8);
  std::copy(corners.begin(), corners.end(), b.corners.begin());
  b.nx = parse_divisions(r, "nx");
  b.ny = parse_divisions(r, "ny");
  b.nz = parse_divisions(r, "nz");
  // Orientation: corners 1-4 must run counterclockwise seen from corner 5's side.
  const Eigen::Vector3d e1 = b.corners[1] - b.corners[0], e2 = b.corners[3] - b.corners[0], e3 = b.corners[4] - b.corners[0];
  if (!(e1.cross(e2).dot(e3) > 0)) r.fail("corners", "corners 1-4 must run counterclockwise seen from corners 5-8 (positive volume)");
  r.finish();
  return b;
}

// The generated two-blade article: mesh density in [mesh], any subset of the named dimensions
// in [mesh.dimensions] (the others keep their documented defaults, articles/two_blade.hpp).
void parse_two_blade(TomlReader& r, MeshSpec& m) {
  m.kind = MeshSpec::Kind::two_blade;
  // Far below every clearance validate() admits (1e-6 m), far above rounding in the corners.
  m.merge_tolerance = 1e-7;
  TwoBladeDimensions& d = m.two_blade;
  auto small_integer = [&r](const std::string& key, long lo, long hi, int fallback) {
    const auto v = r.optional_integer(key);
    if (!v) return fallback;
    if (*v < lo || *v > hi) r.fail(key, fmt::format("must lie in {}..{}, found {}", lo, hi, *v));
    return static_cast<int>(*v);
  };
  d.refinement = small_integer("refinement", 1, 64, d.refinement);
  d.thickness_divisions = small_integer("thickness_divisions", 1, 1000, d.thickness_divisions);
  d.airfoil_divisions = small_integer("airfoil_divisions", 1, 1000, d.airfoil_divisions);
  std::optional<TomlReader> dims;
  if (const toml::table* table = r.optional_table("dimensions")) {
    dims.emplace(*table, r.path() + ".dimensions", r.file());
    for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
      if (auto v = dims->optional_number(f.name)) d.*f.member = *v;
    dims->finish();
  }
  try {
    d.validate();
  } catch (const DimensionError& e) {
    if (dims && dims->has(e.name())) dims->fail(e.name(), e.what());
    r.fail(r.has(e.name()) ? e.name() : std::string(), e.what());
  }
}

MeshSpec parse_mesh(TomlReader r, const fs::path& folder) {
  MeshSpec m;
  m.at = r.location();
  const std::string kind = r.choice("kind", {"mapped_quad", "csv", "hex_blocks", "gmsh", "two_blade"});
  m.element = parse_element(r);
  if (kind == "two_blade") {
    if (m.dim() != 3) r.fail("element", "kind 'two_blade' needs a solid element (hex8, hex8i, hex20)");
    parse_two_blade(r, m);
    r.finish();
    return m;
  }
  if (kind == "hex_blocks" || kind == "gmsh") {
    if (m.dim() != 3) r.fail("element", fmt::format("kind '{}' needs a solid element (hex8, hex8i, hex20)", kind));
    m.merge_tolerance = r.non_negative("merge_tolerance", m.merge_tolerance);
    if (kind == "gmsh") {
      m.kind = MeshSpec::Kind::gmsh;
      m.gmsh_file = folder / r.string("file");
    } else {
      m.kind = MeshSpec::Kind::hex_blocks;
      int index = 0;
      for (const toml::node& n : r.array("block")) {
        if (!n.is_table()) r.fail("block", "write blocks as [[mesh.block]] tables");
        m.blocks.push_back(parse_hex_block(TomlReader(*n.as_table(), fmt::format("mesh.block[{}]", index++), r.file()), m.element));
      }
      if (m.blocks.empty()) r.fail("block", "needs at least one [[mesh.block]]");
    }
    r.finish();
    return m;
  }
  if (kind == "csv") {
    m.kind = MeshSpec::Kind::csv;
    m.nodes_csv = folder / r.string("nodes");
    m.elements_csv = folder / r.string("elements");
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
  s.group = r.optional_string("group").value_or("");
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

AnalysisSpec parse_analysis(TomlReader r, const fs::path& folder) {
  AnalysisSpec a;
  const std::string type = r.choice("type", {"static", "modal", "frf", "hbm", "time", "contact_loop"});
  if (type == "contact_loop") {
    a.type = AnalysisType::contact_loop;
    a.contact_loop = parse_contact_loop(r);
  }
  if (type == "time") {
    a.type = AnalysisType::time;
    a.time = parse_time(r, folder);
  }
  if (type == "frf") {
    a.type = AnalysisType::frf;
    a.frf = parse_frf(r, folder);
  }
  if (type == "hbm") {
    a.type = AnalysisType::hbm;
    a.hbm = parse_hbm(r, folder);
  }
  if (type == "modal") {
    a.type = AnalysisType::modal;
    if (r.has("band_hz")) {
      const auto band = r.number_array("band_hz");
      if (band.size() != 2 || band[0] < 0 || band[0] >= band[1]) r.fail("band_hz", "expected [f_min, f_max] with 0 <= f_min < f_max");
      a.modes.band_min_hz = band[0];
      a.modes.band_max_hz = band[1];
    }
    const auto modes = r.optional_integer("modes");
    if (!modes && !a.modes.band_max_hz) r.fail("modes", "missing required key (or give band_hz)");
    if (modes && *modes < 1) r.fail("modes", "must be >= 1");
    // With a band, `modes` is the first guess of how many modes lie below its top.
    a.modes.lowest = static_cast<int>(modes.value_or(20));
    a.modal.shift_frequency_hz = r.optional_number("shift_hz").value_or(a.modal.shift_frequency_hz);
    a.modal.tolerance = r.optional_number("tolerance").value_or(a.modal.tolerance);
  }
  if (const toml::table* pairs = r.optional_table("pairs")) {
    if (a.type == AnalysisType::static_linear || a.type == AnalysisType::hbm || a.type == AnalysisType::time ||
        a.type == AnalysisType::contact_loop)
      r.fail("pairs", "[analysis.pairs] labels modes; it needs type = \"modal\" or \"frf\"");
    TomlReader p(*pairs, r.path() + ".pairs", r.file());
    a.pairs_at = p.location();
    ModePairSpec& spec = a.pairs.emplace();
    spec.left = p.string("left");
    spec.right = p.string("right");
    spec.direction = parse_direction(p, "direction", p.string("direction"));
    spec.left_tip = p.string("left_tip");
    spec.right_tip = p.string("right_tip");
    p.finish();
  }
  r.finish();
  return a;
}

CheckSpec parse_check(TomlReader r, const fs::path& folder) {
  CheckSpec c;
  c.at = r.location();
  c.name = r.string("name");
  c.result = r.string("result");  // whether the analysis makes it is known only when it runs
  if (r.has("reference") == r.has("reference_result"))
    r.fail("reference", "give either 'reference' (a CSV file) or 'reference_result' (a result table of this run)");
  if (r.has("reference")) c.reference = folder / r.string("reference");
  else c.reference_result = r.string("reference_result");
  c.key = r.string("key");
  TomlReader compare(r.table("compare"), r.path() + ".compare", r.file());
  for (const auto& [k, v] : r.table("compare")) {
    const std::string result_column(k.str());
    c.compare.emplace_back(result_column, compare.string(result_column));
  }
  if (c.compare.empty()) r.fail("compare", "needs at least one 'result_column = \"reference_column\"' pair");
  if (r.has("keys")) {
    c.keys = r.integer_array("keys");
    if (c.keys.empty()) r.fail("keys", "empty list (leave 'keys' out to compare every reference row)");
    std::vector<long> sorted = c.keys;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) r.fail("keys", "a key is listed twice");
  }
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

HbmHarmonicsStudySpec parse_hbm_study(TomlReader r, const HbmSpec& hbm) {
  HbmHarmonicsStudySpec s;
  s.at = r.location();
  r.choice("kind", {"hbm_harmonics"});
  for (long h : r.integer_array("harmonics")) {
    if (h < 1 || h > 50) r.fail("harmonics", "each H must lie in [1, 50]");
    s.harmonics.push_back(static_cast<int>(h));
  }
  if (s.harmonics.size() < 2) r.fail("harmonics", "needs at least two values; the largest is the reference");
  s.force_levels = r.number_array("force_levels");
  for (double f : s.force_levels)
    if (std::find(hbm.force_levels.begin(), hbm.force_levels.end(), f) == hbm.force_levels.end())
      r.fail("force_levels", fmt::format("{} N is not one of the analysis's force_levels", f));
  if (s.force_levels.empty()) r.fail("force_levels", "needs at least one level");
  const long samples = r.optional_integer("time_samples").value_or(0);
  const int h_max = *std::max_element(s.harmonics.begin(), s.harmonics.end());
  if (samples != 0 && samples < 2 * h_max + 1) r.fail("time_samples", fmt::format("must be 0 or at least 2 H + 1 = {}", 2 * h_max + 1));
  s.time_samples = static_cast<int>(samples);
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

TimeStepStudySpec parse_time_study(TomlReader r) {
  TimeStepStudySpec s;
  s.at = r.location();
  r.choice("kind", {"time_steps"});
  for (long n : r.integer_array("steps_per_period")) {
    if (n < 8 || n > 100000) r.fail("steps_per_period", "each value must lie in [8, 100000]");
    s.steps_per_period.push_back(static_cast<int>(n));
  }
  s.steady_tolerances = r.number_array("steady_tolerances");
  for (double t : s.steady_tolerances)
    if (!(t > 0 && t < 0.1)) r.fail("steady_tolerances", "each value must lie in (0, 0.1)");
  if (s.steps_per_period.empty() || s.steady_tolerances.empty() || s.steps_per_period.size() * s.steady_tolerances.size() < 2)
    r.fail("steps_per_period", "needs at least two variants; the finest (most steps, smallest tolerance) is the reference");
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

RomStudySpec parse_rom_study(TomlReader r) {
  RomStudySpec s;
  s.at = r.location();
  r.choice("kind", {"rom_modes"});
  for (long m : r.integer_array("modes")) {
    if (m < 0 || m > 1000) r.fail("modes", "mode counts must lie in 0..1000");
    s.modes.push_back(static_cast<int>(m));
  }
  if (s.modes.empty()) r.fail("modes", "needs at least one mode count");
  TomlReader sets(r.table("master_sets"), r.path() + ".master_sets", r.file());
  for (const auto& [k, v] : r.table("master_sets")) {
    const std::string name(k.str());
    s.master_sets.emplace_back(name, sets.string_array(name));
    if (s.master_sets.back().second.empty()) sets.fail(name, "needs at least one master point");
  }
  sets.finish();
  if (s.master_sets.empty()) r.fail("master_sets", "needs at least one set, e.g. { thesis = [\"T1\", \"T2\"] }");
  if (const auto m = r.optional_integer("compare_modes")) {
    if (*m < 1) r.fail("compare_modes", "must be >= 1");
    s.compare_modes = static_cast<int>(*m);
  }
  s.note = r.optional_string("note").value_or("");
  r.finish();
  return s;
}

ModalRefinementStudySpec parse_modal_study(TomlReader r) {
  ModalRefinementStudySpec s;
  s.at = r.location();
  r.choice("kind", {"modal_refinement"});
  for (long level : r.integer_array("refinements")) {
    if (level < 1 || level > 16) r.fail("refinements", "levels must lie in 1..16");
    s.refinements.push_back(static_cast<int>(level));
  }
  if (s.refinements.size() < 2) r.fail("refinements", "need at least 2 levels");
  for (const std::string& e : r.string_array("elements")) {
    bool known = false;
    for (ElementType t : {ElementType::hex8, ElementType::hex8i, ElementType::hex20})
      if (element_name(t) == e) {
        s.elements.push_back(t);
        known = true;
      }
    if (!known) r.fail("elements", fmt::format("unknown solid element '{}'; expected hex8, hex8i or hex20", e));
  }
  if (s.elements.empty()) r.fail("elements", "needs at least one element type");
  if (const auto m = r.optional_integer("modes")) {
    if (*m < 1) r.fail("modes", "must be >= 1");
    s.modes = static_cast<int>(*m);
  }
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

namespace {

// Material, mesh, section, node sets, constraints and loads: the model when it has a mesh.
void parse_model_sections(TomlReader& top, const fs::path& folder, CaseSpec& spec) {
  const fs::path& file = spec.file;
  {
    TomlReader m(top.table("material"), "material", file);
    spec.section.youngs_modulus = m.positive("E");
    spec.section.poisson_ratio = m.number("nu");
    if (!(spec.section.poisson_ratio > -1 && spec.section.poisson_ratio < 0.5))
      m.fail("nu", fmt::format("must lie in (-1, 0.5), found {}", spec.section.poisson_ratio));
    spec.section.density = m.non_negative("rho", 0.0);
    if (spec.analysis.type != AnalysisType::static_linear && !(spec.section.density > 0))
      m.fail("rho", "must be > 0 for a modal analysis or a forced response");
    m.finish();
  }
  spec.mesh = parse_mesh(TomlReader(top.table("mesh"), "mesh", file), folder);
  if (spec.mesh.dim() == 2) {
    TomlReader s(top.table("section"), "section", file);
    spec.section.thickness = s.positive("thickness");
    s.finish();
  } else if (top.has("section")) {
    top.fail("section", "a solid mesh takes no [section] (thickness is for plane stress)");
  }
  if (const toml::table* sets = top.optional_table("sets")) {
    for (const auto& [k, v] : *sets) {
      const std::string name(k.str());
      if (!v.is_table()) top.fail("sets", fmt::format("set '{}' must be a table [sets.{}]", name, name));
      spec.sets.push_back(parse_set(TomlReader(*v.as_table(), "sets." + name, file), name));
      if (spec.mesh.kind == MeshSpec::Kind::two_blade) {
        const auto reserved = two_blade_set_names();
        if (std::find(reserved.begin(), reserved.end(), name) != reserved.end())
          throw InputError(fmt::format("{}: 'sets.{}': the two_blade mesh defines this set itself ({}); choose another name",
                                       spec.sets.back().at.where(), name, fmt::join(reserved, ", ")));
      }
    }
  }
  for_each_table_in_array(top, "bc", [&](TomlReader r) { spec.constraints.push_back(parse_constraint(std::move(r))); });
  for_each_table_in_array(top, "load", [&](TomlReader r) { spec.loads.push_back(parse_load(std::move(r))); });
}

toml::table read_case_table(const fs::path& file, int depth) {
  if (!fs::is_regular_file(file)) throw InputError(fmt::format("{}: case file not found", file.string()));
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: TOML syntax error: {}", file.string(), e.source().begin.line, e.description()));
  }
  // [case] model_from: material, mesh, sets, constraints and section of another case, so that
  // several analyses of one article share a single description of it.
  const toml::node* from = root.at_path("case.model_from").node();
  if (!from) return root;
  const SourceLocation at{file, static_cast<int>(from->source().begin.line)};
  if (!from->is_string()) throw InputError(fmt::format("{}: 'case.model_from': expected a case file name", at.where()));
  if (depth > 8) throw InputError(fmt::format("{}: 'case.model_from': more than 8 levels (a cycle?)", at.where()));
  const fs::path base_file = file.parent_path() / from->value<std::string>().value();
  const toml::table base = read_case_table(base_file, depth + 1);
  parse_case_table(base, base_file);  // errors in the base name the base file and its lines
  for (const char* key : {"material", "mesh", "sets", "bc", "section"}) {
    if (root.contains(key))
      throw InputError(fmt::format("{}: '{}' is given here and by model_from = \"{}\"; keep one", at.where(), key,
                                   base_file.filename().string()));
    if (const toml::node* n = base.get(key)) root.insert(key, *n);
  }
  return root;
}

}  // namespace

toml::table read_case_table(const fs::path& file) { return read_case_table(file, 0); }

CaseSpec parse_case_file(const fs::path& file) { return parse_case_table(read_case_table(file), file); }

CaseSpec parse_case_table(const toml::table& root, const fs::path& file) {
  const fs::path folder = file.parent_path();
  TomlReader top(root, "", file);
  CaseSpec spec;
  spec.file = file;
  {
    TomlReader c(top.table("case"), "case", file);
    spec.name = c.optional_string("name").value_or(file.stem().string());
    spec.title = c.optional_string("title").value_or(spec.name);
    spec.description = c.optional_string("description").value_or("");
    if (const auto from = c.optional_string("model_from")) spec.model_from = folder / *from;
    c.finish();
  }
  spec.analysis = parse_analysis(TomlReader(top.table("analysis"), "analysis", file), folder);
  // A model given by matrices alone (reduced models read from files or written inline) needs no mesh.
  const FrfSpec& frf = spec.analysis.frf;
  const bool matrices_only = (spec.analysis.type == AnalysisType::frf && !frf.full_model &&
                              std::all_of(frf.roms.begin(), frf.roms.end(), [](const RomSpec& r) { return r.masters.empty(); })) ||
                             (spec.analysis.type == AnalysisType::hbm && spec.analysis.hbm.model.masters.empty()) ||
                             (spec.analysis.type == AnalysisType::time && spec.analysis.time.system.model.masters.empty());
  if (spec.analysis.type == AnalysisType::contact_loop) {
    for (const char* key : {"material", "mesh", "section", "sets", "bc", "load"})
      if (top.has(key)) top.fail(key, "a contact_loop analysis drives one contact by an imposed motion: it takes no model data");
    spec.mesh.kind = MeshSpec::Kind::none;
  } else if (matrices_only && !top.has("mesh")) {
    for (const char* key : {"material", "section", "sets", "bc", "load"})
      if (top.has(key)) top.fail(key, "the model is given by matrices only (a reduced model from a file or written in the case): it takes no mesh data");
    spec.mesh.kind = MeshSpec::Kind::none;
  } else {
    parse_model_sections(top, folder, spec);
  }
  for_each_table_in_array(top, "check", [&](TomlReader r) { spec.checks.push_back(parse_check(std::move(r), folder)); });
  if (const toml::table* study = top.optional_table("study")) {
    const toml::node* kind = study->get("kind");
    if (kind && kind->value<std::string>() == "rom_modes") {
      spec.rom_study = parse_rom_study(TomlReader(*study, "study", file));
      if (spec.analysis.type != AnalysisType::frf || !spec.analysis.frf.full_model)
        top.fail("study", "a rom_modes study needs an frf analysis with the full model");
      if (spec.rom_study->compare_modes > spec.analysis.frf.full_modes)
        top.fail("study", "compare_modes exceeds the analysis's full_modes");
    } else if (kind && kind->value<std::string>() == "time_steps") {
      if (spec.analysis.type != AnalysisType::time) top.fail("study", "a time_steps study needs a time analysis");
      spec.time_study = parse_time_study(TomlReader(*study, "study", file));
    } else if (kind && kind->value<std::string>() == "hbm_harmonics") {
      if (spec.analysis.type != AnalysisType::hbm) top.fail("study", "an hbm_harmonics study needs an hbm analysis");
      spec.hbm_study = parse_hbm_study(TomlReader(*study, "study", file), spec.analysis.hbm);
    } else if (kind && kind->value<std::string>() == "modal_refinement") {
      spec.modal_study = parse_modal_study(TomlReader(*study, "study", file));
      const bool solid = spec.mesh.kind == MeshSpec::Kind::two_blade || spec.mesh.kind == MeshSpec::Kind::hex_blocks;
      if (!solid || spec.analysis.type != AnalysisType::modal)
        top.fail("study", "a modal_refinement study needs a two_blade or hex_blocks mesh and a modal analysis");
    } else {
      spec.study = parse_study(TomlReader(*study, "study", file));
      if (spec.mesh.kind != MeshSpec::Kind::mapped_quad || spec.analysis.type != AnalysisType::static_linear)
        top.fail("study", "a refinement study needs a mapped_quad mesh and a static analysis");
    }
  }
  top.has("calibration");  // read by `bladebench calibrate` (cases/calibration_spec.hpp)
  top.finish();
  return spec;
}

}  // namespace bb
