// What bladebench reads of a deck, keyword by keyword (Abaqus Keywords Reference; ccx manual section 7):
// everything else is refused naming its line, so that nothing that changes the model is skipped.
#include "mesh/abaqus_inp.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <span>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/user_text.hpp"
#include "mesh/element_topology.hpp"
#include "mesh/inp_lines.hpp"

namespace bb {
namespace abaqus_inp_impl {
namespace {

using inp::InpLines;
using inp::Keyword;
using inp::Line;

// Read and not used: output requests and the deck's analysis procedure (the case's [analysis] runs).
constexpr std::array<std::string_view, 15> kSkipped = {
    "HEADING",        "PREPRINT",     "NODE FILE", "EL FILE", "NODE PRINT", "EL PRINT",      "OUTPUT", "NODE OUTPUT",
    "ELEMENT OUTPUT", "CONTACT FILE", "FREQUENCY", "STATIC",  "END STEP",   "ENERGY OUTPUT", "RESTART"};
constexpr std::array<std::string_view, 3> kProcedures = {"FREQUENCY", "STATIC", "STEP"};

bool one_of(std::span<const std::string_view> names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Our element for a deck's element type; C3D20R is read as hex20, whose 27-point integration is
// stated in a note (the deck's solver integrates it with 8 points).
std::optional<ElementType> element_of(std::string_view deck_type) {
  if (deck_type == "C3D20R") return ElementType::hex20;
  for (ElementType t : element_types())
    if (topology(t).calculix == deck_type) return t;
  return std::nullopt;
}

std::string read_types() {
  std::string out;
  for (ElementType t : element_types()) out += fmt::format("{} ({}), ", topology(t).calculix, topology(t).name);
  return out + "C3D20R (hex20, integrated with 27 points)";
}

struct RawBlock {
  ElementType type;
  std::vector<long> ids;
  std::vector<long> nodes;    // ids, nodes_per_element per element
  std::vector<size_t> lines;  // the line of each element, for messages
};

struct Section {
  std::string elset, material;
  size_t line = 0;
};

class DeckReader {
 public:
  DeckReader(InpLines& deck, bool header_only) : deck_(deck), header_only_(header_only) {}

  InpDeck read();

 private:
  const Line& line(size_t i) const { return deck_.lines()[i]; }
  size_t data_end(size_t i) const {
    while (i < deck_.lines().size() && !line(i).keyword()) ++i;
    return i;
  }
  [[noreturn]] void fail(size_t i, const std::string& keyword, std::string_view message) const {
    deck_.fail(line(i), fmt::format("*{}: {}", keyword, message));
  }
  void refuse_parameters(size_t at, const Keyword& k, std::initializer_list<std::string_view> known) const {
    for (const auto& [key, value] : k.parameters)
      if (std::find(known.begin(), known.end(), key) == known.end())
        fail(at, k.name,
             fmt::format("parameter {} is not read by bladebench (it reads {})", printable(key),
                         known.size() == 0 ? "none" : fmt::format("{}", fmt::join(known, ", "))));
  }
  std::string required(size_t at, const Keyword& k, std::string_view key) const {
    const std::string* v = k.find(key);
    if (!v || v->empty()) fail(at, k.name, fmt::format("needs {}=<name>", key));
    return inp::upper(*v);
  }

  size_t node(size_t at, const Keyword& k);
  size_t element(size_t at, const Keyword& k);
  size_t set(size_t at, const Keyword& k, bool nodes);
  size_t material(size_t at, const Keyword& k);
  size_t section(size_t at, const Keyword& k);
  size_t boundary(size_t at, const Keyword& k);
  void finish_mesh(InpDeck& out);

  InpLines& deck_;
  bool header_only_;
  std::vector<long> node_ids_;
  std::vector<std::array<double, 3>> coords_;
  std::vector<size_t> node_lines_;
  std::unordered_map<long, size_t> node_index_;
  std::vector<RawBlock> blocks_;
  std::map<std::string, std::vector<long>> nsets_, elsets_;  // user ids
  std::map<std::string, size_t> nset_lines_;
  std::vector<InpMaterial> materials_;
  std::vector<Section> sections_;
  InpDeck out_;
  bool in_step_ = false, noted_step_ = false, c3d20r_ = false;
};

size_t DeckReader::node(size_t at, const Keyword& k) {
  refuse_parameters(at, k, {"NSET"});
  const std::string* nset = k.find("NSET");
  const size_t end = data_end(at + 1);
  if (nset) nsets_[inp::upper(*nset)];
  if (header_only_) return end;
  for (size_t i = at + 1; i < end; ++i) {
    const auto f = inp::fields(line(i).text);
    if (f.size() < 3 || f.size() > 4) fail(i, k.name, "a node line is: number, x, y[, z]");
    const long id = inp::integer_field(deck_, line(i), f[0], "a node number");
    std::array<double, 3> x{0, 0, 0};
    for (size_t d = 1; d < f.size(); ++d) x[d - 1] = inp::number_field(deck_, line(i), f[d], "a coordinate");
    if (const auto [it, fresh] = node_index_.emplace(id, node_ids_.size()); !fresh)
      fail(i, k.name,
           fmt::format("node {} is defined twice (first at line {})", id, line(node_lines_[it->second]).number));
    node_ids_.push_back(id);
    coords_.push_back(x);
    node_lines_.push_back(i);
    if (nset) nsets_[inp::upper(*nset)].push_back(id);
  }
  return end;
}

size_t DeckReader::element(size_t at, const Keyword& k) {
  refuse_parameters(at, k, {"TYPE", "ELSET"});
  const std::string type_name = required(at, k, "TYPE");
  const std::optional<ElementType> type = element_of(type_name);
  if (!type)
    fail(at, k.name,
         fmt::format("element type {} is not one bladebench has (it reads {})", printable(type_name), read_types()));
  if (type_name == "C3D20R") c3d20r_ = true;
  const size_t end = data_end(at + 1);
  RawBlock& b = blocks_.emplace_back(RawBlock{*type, {}, {}, {}});
  if (header_only_) return end;
  const auto per = static_cast<size_t>(nodes_per_element(*type));
  const std::string* elset = k.find("ELSET");
  std::vector<std::string_view> entries;
  size_t first = at + 1;
  for (size_t i = at + 1; i < end; ++i) {
    if (entries.empty()) first = i;
    for (const std::string_view f : inp::fields(line(i).text))
      if (!f.empty()) entries.push_back(f);
    if (entries.size() < per + 1) continue;  // the element goes on on the next line
    if (entries.size() > per + 1)
      fail(i, k.name,
           fmt::format("{} numbers for a {}-node {}: the element number and {} nodes", entries.size(), per, type_name,
                       per));
    b.ids.push_back(inp::integer_field(deck_, line(first), entries[0], "an element number"));
    for (size_t a = 1; a <= per; ++a)
      b.nodes.push_back(inp::integer_field(deck_, line(first), entries[a], "a node number"));
    b.lines.push_back(first);
    if (elset) elsets_[inp::upper(*elset)].push_back(b.ids.back());
    entries.clear();
  }
  if (!entries.empty())
    fail(first, k.name, fmt::format("the last element has {} of its {} numbers", entries.size(), per + 1));
  return end;
}

// *NSET / *ELSET: numbers, names of sets defined before, or GENERATE's first, last[, step].
size_t DeckReader::set(size_t at, const Keyword& k, bool nodes) {
  const char* key = nodes ? "NSET" : "ELSET";
  refuse_parameters(at, k, {key, "GENERATE"});
  const std::string name = required(at, k, key);
  const size_t end = data_end(at + 1);
  auto& sets = nodes ? nsets_ : elsets_;
  std::vector<long>& members = sets[name];
  if (nodes) nset_lines_.emplace(name, at);
  if (header_only_) return end;
  const bool generate = k.find("GENERATE") != nullptr;
  for (size_t i = at + 1; i < end; ++i) {
    const auto f = inp::fields(line(i).text);
    if (generate) {
      if (f.size() < 2 || f.size() > 3) fail(i, k.name, "with GENERATE a line is: first, last[, increment]");
      const long a = inp::integer_field(deck_, line(i), f[0], "the first number");
      const long b = inp::integer_field(deck_, line(i), f[1], "the last number");
      const long step = f.size() == 3 ? inp::integer_field(deck_, line(i), f[2], "the increment") : 1;
      if (step < 1 || b < a || (b - a) / step > 100'000'000)
        fail(i, k.name, fmt::format("GENERATE {}, {}, {}: needs first <= last and an increment >= 1", a, b, step));
      for (long v = a; v <= b; v += step) members.push_back(v);
      continue;
    }
    for (const std::string_view f1 : f) {
      if (f1.empty()) continue;
      if (std::isdigit(static_cast<unsigned char>(f1.front())) || f1.front() == '-') {
        members.push_back(inp::integer_field(deck_, line(i), f1, "a number"));
        continue;
      }
      const auto other = sets.find(inp::upper(f1));
      if (other == sets.end() || &other->second == &members)
        fail(i, k.name, fmt::format("'{}' is neither a number nor a {} defined above", printable(f1), key));
      const std::vector<long> copy = other->second;
      members.insert(members.end(), copy.begin(), copy.end());
    }
  }
  return end;
}

size_t DeckReader::material(size_t at, const Keyword& k) {
  refuse_parameters(at, k, {"NAME"});
  InpMaterial& m = materials_.emplace_back();
  m.name = required(at, k, "NAME");
  m.where = deck_.where(line(at));
  size_t i = data_end(at + 1);
  if (i != at + 1) fail(at + 1, k.name, "takes no data lines");
  // The material's own keywords follow it; the first other keyword ends it.
  while (i < deck_.lines().size()) {
    const Keyword p = inp::parse_keyword(deck_, line(i));
    const size_t end = data_end(i + 1);
    if (p.name == "ELASTIC" || p.name == "DENSITY") {
      const bool elastic = p.name == "ELASTIC";
      if (elastic) {
        refuse_parameters(i, p, {"TYPE"});
        if (const std::string* t = p.find("TYPE"); t && inp::upper(*t) != "ISO" && inp::upper(*t) != "ISOTROPIC")
          fail(i, p.name, fmt::format("TYPE={}: bladebench's material is isotropic (TYPE=ISO)", printable(*t)));
      } else {
        refuse_parameters(i, p, {});
      }
      if (end != i + 2)
        fail(i, p.name,
             end == i + 1 ? "needs one data line"
                          : "has several data lines (temperature-dependent data): bladebench's material "
                            "takes one value of each constant");
      const auto f = inp::fields(line(i + 1).text);
      const size_t count = elastic ? 2 : 1;
      if (f.size() < count || (f.size() > count && !f[count].empty()))
        fail(i + 1, p.name,
             elastic ? "the data line is: E, nu (no temperature)" : "the data line is: rho (no temperature)");
      if (elastic) {
        m.youngs_modulus = inp::number_field(deck_, line(i + 1), f[0], "Young's modulus");
        m.poisson_ratio = inp::number_field(deck_, line(i + 1), f[1], "Poisson's ratio");
      } else {
        m.density = inp::number_field(deck_, line(i + 1), f[0], "the density");
      }
    } else if (p.name == "EXPANSION" || p.name == "CONDUCTIVITY" || p.name == "SPECIFIC HEAT") {
      out_.notes.push_back(fmt::format("{}: *{} not used (no thermal load)", deck_.where(line(i)), p.name));
    } else {
      return i;
    }
    i = end;
  }
  return i;
}

size_t DeckReader::section(size_t at, const Keyword& k) {
  refuse_parameters(at, k, {"ELSET", "MATERIAL"});
  sections_.push_back({required(at, k, "ELSET"), required(at, k, "MATERIAL"), at});
  const size_t end = data_end(at + 1);
  if (end > at + 2) fail(at + 2, k.name, "takes at most one data line (the thickness of plane elements)");
  if (end == at + 2) {
    const auto f = inp::fields(line(at + 1).text);
    if (!f[0].empty()) {
      const double t = inp::number_field(deck_, line(at + 1), f[0], "the thickness");
      if (!(t > 0)) fail(at + 1, k.name, fmt::format("thickness {} must be > 0", t));
      if (out_.thickness && *out_.thickness != t)
        fail(at + 1, k.name,
             fmt::format("thickness {} differs from {} at {}: bladebench's plane model has one", t, *out_.thickness,
                         out_.thickness_where));
      out_.thickness = t;
      out_.thickness_where = deck_.where(line(at + 1));
    }
  }
  return end;
}

size_t DeckReader::boundary(size_t at, const Keyword& k) {
  refuse_parameters(at, k, {"OP"});
  if (const std::string* op = k.find("OP"); op && inp::upper(*op) != "MOD")
    fail(at, k.name, "OP=NEW (removing the conditions given before) is not read: write the conditions that hold");
  const size_t end = data_end(at + 1);
  for (size_t i = at + 1; i < end; ++i) {
    const auto f = inp::fields(line(i).text);
    if (f.size() < 2 || f[0].empty()) fail(i, k.name, "a line is: node or set, first DOF[, last DOF[, value]]");
    InpBoundary b;
    b.where = deck_.where(line(i));
    if (std::isdigit(static_cast<unsigned char>(f[0].front()))) {
      const long id = inp::integer_field(deck_, line(i), f[0], "a node number");
      b.set = fmt::format("INP_NODE_{}", id);
      if (!header_only_) nsets_[b.set] = {id};
      nset_lines_.emplace(b.set, i);
    } else {
      b.set = inp::upper(f[0]);
      if (!nsets_.count(b.set)) fail(i, k.name, fmt::format("node set {} is not defined above", printable(f[0])));
    }
    const std::string kind = inp::upper(f[1]);
    if (kind == "ENCASTRE" || kind == "PINNED") {
      b.first = 1, b.last = 3;
    } else if (kind == "XSYMM" || kind == "YSYMM" || kind == "ZSYMM") {
      b.first = b.last = kind[0] - 'X' + 1;
    } else {
      b.first = static_cast<int>(inp::integer_field(deck_, line(i), f[1], "the first DOF"));
      b.last = f.size() > 2 && !f[2].empty()
                   ? static_cast<int>(inp::integer_field(deck_, line(i), f[2], "the last DOF"))
                   : b.first;
      if (f.size() > 3 && !f[3].empty()) b.value = inp::number_field(deck_, line(i), f[3], "the value");
      if (f.size() > 4) fail(i, k.name, "a line is: node or set, first DOF[, last DOF[, value]]");
      if (b.first < 1 || b.last < b.first || b.last > 3)
        fail(i, k.name,
             fmt::format("DOFs {} to {}: a solid or plane element has DOFs 1-3 (translations) only", b.first, b.last));
    }
    out_.boundaries.push_back(b);
  }
  return end;
}

InpDeck DeckReader::read() {
  const auto& lines = deck_.lines();
  size_t i = 0;
  if (!lines.empty() && !lines.front().keyword()) deck_.fail(lines.front(), "data before the first keyword");
  while (i < lines.size()) {
    const Keyword k = inp::parse_keyword(deck_, lines[i]);
    if (k.name == "NODE" && !in_step_) {
      i = node(i, k);
    } else if (k.name == "ELEMENT" && !in_step_) {
      i = element(i, k);
    } else if ((k.name == "NSET" || k.name == "ELSET") && !in_step_) {
      i = set(i, k, k.name == "NSET");
    } else if (k.name == "MATERIAL" && !in_step_) {
      i = material(i, k);
    } else if (k.name == "SOLID SECTION" && !in_step_) {
      i = section(i, k);
    } else if (k.name == "BOUNDARY") {
      i = boundary(i, k);
    } else if (k.name == "STEP" && !in_step_) {
      in_step_ = true;
      i = data_end(i + 1);
    } else if (one_of(kSkipped, k.name) && (in_step_ || !one_of(kProcedures, k.name))) {
      if (one_of(kProcedures, k.name) && !noted_step_) {
        out_.notes.push_back(
            fmt::format("{}: the deck's *{} step is not run; the case's [analysis] is", deck_.where(lines[i]), k.name));
        noted_step_ = true;
      }
      if (k.name == "END STEP") in_step_ = false;
      i = data_end(i + 1);
    } else {
      deck_.fail(
          lines[i],
          fmt::format("*{} is not read by bladebench{}. It reads *NODE, *ELEMENT, *NSET, *ELSET, *MATERIAL "
                      "(*ELASTIC, *DENSITY), *SOLID SECTION, *BOUNDARY, *INCLUDE and skips steps' procedures and "
                      "output requests; a keyword that changes the model (loads, contact, constraints, other "
                      "sections) is not skipped silently",
                      k.name, in_step_ ? " inside a step (loads are the case's [[load]])" : ""));
    }
  }
  if (c3d20r_)
    out_.notes.push_back(
        "C3D20R elements are read as hex20 and integrated with 3 x 3 x 3 points (the deck's solver uses 2 x 2 x 2)");
  for (const RawBlock& b : blocks_)
    if (element_dimension(b.type) != element_dimension(blocks_.front().type))
      throw InputError(fmt::format("{}: the deck mixes plane and solid elements", deck_.where(lines.front())));
  if (blocks_.empty()) throw InputError(fmt::format("{}: the deck has no *ELEMENT", deck_.where(lines.front())));
  out_.mesh.dim = element_dimension(blocks_.front().type);
  for (const RawBlock& b : blocks_) out_.mesh.blocks.push_back(ElementBlock{b.type, {}, {}});
  // The materials the sections name, each once.
  std::vector<InpMaterial> used;
  for (const Section& s : sections_) {
    const auto m =
        std::find_if(materials_.begin(), materials_.end(), [&](const InpMaterial& x) { return x.name == s.material; });
    if (m == materials_.end())
      deck_.fail(line(s.line), fmt::format("*SOLID SECTION: material {} is not defined by a *MATERIAL", s.material));
    if (std::none_of(used.begin(), used.end(), [&](const InpMaterial& x) { return x.name == m->name; }))
      used.push_back(*m);
    if (!header_only_ && !elsets_.count(s.elset))
      deck_.fail(line(s.line), fmt::format("*SOLID SECTION: element set {} is not defined", s.elset));
  }
  out_.materials = std::move(used);
  if (!header_only_) finish_mesh(out_);
  return std::move(out_);
}

// Internal nodes are the elements' nodes, in the deck's order; every element is in a section when the
// deck has sections, and every set names defined nodes.
void DeckReader::finish_mesh(InpDeck& out) {
  Mesh& mesh = out.mesh;
  std::vector<int> internal(node_ids_.size(), -1);
  auto index_of = [&](long id, size_t at, const char* what) {
    const auto it = node_index_.find(id);
    if (it == node_index_.end())
      deck_.fail(line(at), fmt::format("{} names node {}, which no *NODE defines", what, id));
    return it->second;
  };
  for (const RawBlock& b : blocks_)
    for (size_t e = 0; e < b.ids.size(); ++e)
      for (size_t a = 0; a < static_cast<size_t>(nodes_per_element(b.type)); ++a)
        internal[index_of(b.nodes[e * static_cast<size_t>(nodes_per_element(b.type)) + a], b.lines[e], "*ELEMENT")] = 0;
  for (size_t n = 0; n < node_ids_.size(); ++n)
    if (internal[n] == 0) {
      internal[n] = mesh.n_nodes();
      mesh.node_ids.push_back(node_ids_[n]);
    }
  if (const size_t unused = node_ids_.size() - mesh.node_ids.size(); unused > 0)
    out.notes.push_back(fmt::format(
        "{} node(s) that no element uses are left out (first: node {} at {})", unused,
        node_ids_[static_cast<size_t>(std::find(internal.begin(), internal.end(), -1) - internal.begin())],
        deck_.where(line(
            node_lines_[static_cast<size_t>(std::find(internal.begin(), internal.end(), -1) - internal.begin())]))));
  mesh.coords.resize(mesh.n_nodes(), mesh.dim);
  for (size_t n = 0; n < node_ids_.size(); ++n) {
    if (internal[n] < 0) continue;
    if (mesh.dim == 2 && coords_[n][2] != 0.0)
      deck_.fail(line(node_lines_[n]),
                 fmt::format("*NODE: node {} of a plane mesh has z = {}; plane elements lie in z = 0", node_ids_[n],
                             coords_[n][2]));
    for (int d = 0; d < mesh.dim; ++d) mesh.coords(internal[n], d) = coords_[n][static_cast<size_t>(d)];
  }
  mesh.rebuild_index();
  std::unordered_map<long, size_t> element_line;
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const RawBlock& b = blocks_[k];
    ElementBlock& block = mesh.blocks[k];
    const int per = nodes_per_element(b.type);
    block.ids = b.ids;
    block.conn.resize(static_cast<Eigen::Index>(b.ids.size()), per);
    for (size_t e = 0; e < b.ids.size(); ++e) {
      if (const auto [it, fresh] = element_line.emplace(b.ids[e], b.lines[e]); !fresh)
        deck_.fail(line(b.lines[e]), fmt::format("*ELEMENT: element {} is defined twice (first at line {})", b.ids[e],
                                                 line(it->second).number));
      for (int a = 0; a < per; ++a)
        block.conn(static_cast<Eigen::Index>(e), a) =
            internal[node_index_.at(b.nodes[e * static_cast<size_t>(per) + static_cast<size_t>(a)])];
    }
  }
  if (!sections_.empty()) {
    std::set<long> covered;
    for (const Section& s : sections_) {
      for (const long id : elsets_.at(s.elset)) {
        if (!element_line.count(id))
          deck_.fail(line(s.line), fmt::format("*SOLID SECTION: element set {} names element {}, which no *ELEMENT "
                                               "defines",
                                               s.elset, id));
        covered.insert(id);
      }
    }
    for (const auto& [id, at] : element_line)
      if (!covered.count(id))
        deck_.fail(line(at), fmt::format("*ELEMENT: element {} lies in no *SOLID SECTION's set (it would have no "
                                         "material)",
                                         id));
  }
  for (const auto& [name, ids] : nsets_) {
    std::set<int> members;
    for (const long id : ids) {
      const size_t at = nset_lines_.count(name) ? nset_lines_.at(name) : node_lines_.front();
      const int n = internal[index_of(id, at, fmt::format("node set {}", name).c_str())];
      if (n >= 0) members.insert(n);
    }
    out.node_sets[name] = std::vector<int>(members.begin(), members.end());
  }
}

}  // namespace
}  // namespace abaqus_inp_impl

InpDeck read_abaqus_inp(const std::filesystem::path& file, const std::filesystem::path& folder, bool header_only) {
  using namespace abaqus_inp_impl;  // this file's helpers, in this scope only (unity builds)
  InpLines deck(file, folder);
  if (deck.lines().empty()) throw InputError(fmt::format("{}: the deck is empty", file.string()));
  return DeckReader(deck, header_only).read();
}

}  // namespace bb
