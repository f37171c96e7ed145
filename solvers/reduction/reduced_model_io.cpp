// Reduced-model files. Units: SI (K in N/m on nodal rows, M in kg; modal coordinates are
// mass-normalized, so their rows carry K in 1/s^2 and M = 1).
//
// The Matrix Market and CSV readers are our own rather than Eigen's unsupported MarketIO or the
// project's fast-cpp-csv-parser: MarketIO reports no line numbers (a malformed export fails
// silently or with a bare "false"), and the CSV parser wants a header row and a column count
// fixed at compile time. Exported reduced matrices are small and dense, so a line-by-line
// reader that names file and line on every error costs nothing.
#include "reduction/reduced_model_io.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>
#include <vector>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "reduction/harwell_boeing.hpp"

namespace bb {
namespace fs = std::filesystem;
namespace {

// The most DOFs a reduced-model file may name (documented in cases/README.md): its K and M are
// dense, 800 MB each at this size, far beyond any Craig-Bampton model of a blade.
constexpr size_t kMaxFileDofs = 10'000;

// ---------------------------------------------------------------- writing

void write_matrix_market(const Eigen::MatrixXd& a, const fs::path& file, const std::string& what) {
  std::ofstream out(file);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing", file.string()));
  // Zeros are left out, but not -0.0: the round trip is meant to be bitwise.
  const auto stored = [&](Eigen::Index i, Eigen::Index j) { return a(i, j) != 0.0 || std::signbit(a(i, j)); };
  Eigen::Index nnz = 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = j; i < a.rows(); ++i) nnz += stored(i, j) ? 1 : 0;
  out << "%%MatrixMarket matrix coordinate real symmetric\n";
  out << fmt::format("% bladebench reduced {} (SI units); lower triangle, %.17g round-trips exactly\n", what);
  out << fmt::format("{} {} {}\n", a.rows(), a.cols(), nnz);
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = j; i < a.rows(); ++i)
      if (stored(i, j)) out << fmt::format("{} {} {:.17g}\n", i + 1, j + 1, a(i, j));
  if (!out) throw InputError(fmt::format("{}: write failed", file.string()));
}

// ---------------------------------------------------------------- reading: shared helpers

std::vector<std::string_view> split_whitespace(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

// A finite double, the whole token; from_chars is locale-independent (a "," decimal comma locale
// must not change what a file means).
double parse_value(std::string_view token, const LineSource& src, const std::string& what) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec == std::errc::result_out_of_range) src.fail(fmt::format("{} '{}' is out of the double range", what, token));
  if (ec != std::errc() || end != token.data() + token.size() || token.empty())
    src.fail(fmt::format("{} '{}' is not a number", what, token));
  if (!std::isfinite(v)) src.fail(fmt::format("{} '{}' is not finite", what, token));
  return v;
}

long parse_count(std::string_view token, const LineSource& src, const std::string& what) {
  long v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc() || end != token.data() + token.size() || token.empty())
    src.fail(fmt::format("{} '{}' is not an integer", what, token));
  return v;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// ---------------------------------------------------------------- Matrix Market

// Supported: "coordinate real general|symmetric" and "array real general" (the NIST format,
// math.nist.gov/MatrixMarket/formats.html). Symmetric files hold the lower triangle only.
Eigen::MatrixXd read_matrix_market(const fs::path& file, Eigen::Index n) {
  LineSource src(file);
  std::string_view line;
  if (!src.next(line)) src.fail("empty file; expected a '%%MatrixMarket matrix ...' header");
  const std::vector<std::string_view> header = split_whitespace(line);
  const bool banner = header.size() == 5 && header[0] == "%%MatrixMarket" && lower(header[1]) == "matrix";
  const std::string format = banner ? lower(header[2]) : "", field = banner ? lower(header[3]) : "",
                    symmetry = banner ? lower(header[4]) : "";
  const bool coordinate = format == "coordinate";
  const bool supported = banner && field == "real" &&
                         ((coordinate && (symmetry == "general" || symmetry == "symmetric")) ||
                          (format == "array" && symmetry == "general"));
  if (!supported)
    src.fail(
        fmt::format("unsupported Matrix Market header '{}'; expected '%%MatrixMarket matrix coordinate real "
                    "general|symmetric' or '%%MatrixMarket matrix array real general'",
                    trim(line)));
  const bool symmetric = symmetry == "symmetric";

  // Comments ('%') and blank lines may precede the size line.
  auto next_data_line = [&](std::string_view& out) {
    const std::optional<std::string_view> content = src.next_content('%');
    if (content) out = *content;
    return content.has_value();
  };
  if (!next_data_line(line)) src.fail("missing the size line");
  const std::vector<std::string_view> size = split_whitespace(line);
  if (size.size() != (coordinate ? 3u : 2u))
    src.fail(coordinate ? "expected the size line 'rows columns entries'" : "expected the size line 'rows columns'");
  const long rows = parse_count(size[0], src, "row count"), cols = parse_count(size[1], src, "column count");
  if (rows != n || cols != n) src.fail(fmt::format("matrix is {} x {} but the sidecar names {} DOFs", rows, cols, n));
  const long expected = coordinate ? parse_count(size[2], src, "entry count") : n * n;
  const long capacity = symmetric ? n * (n + 1) / 2 : n * n;
  if (expected < 0 || expected > capacity)
    src.fail(fmt::format("{} entries cannot fit a {} x {} {} matrix", expected, n, n, symmetry));

  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXi first_line = Eigen::MatrixXi::Zero(n, n);  // where each entry was set, for duplicates
  long count = 0;
  while (next_data_line(line)) {
    if (count == expected) src.fail(fmt::format("more entries than the {} the size line announces", expected));
    const std::vector<std::string_view> tokens = split_whitespace(line);
    if (coordinate) {
      if (tokens.size() != 3) src.fail("expected an entry 'row column value'");
      const long i = parse_count(tokens[0], src, "row index"), j = parse_count(tokens[1], src, "column index");
      if (i < 1 || i > n || j < 1 || j > n)
        src.fail(fmt::format("entry ({}, {}) is out of range for a {} x {} matrix", i, j, n, n));
      if (symmetric && i < j)
        src.fail(fmt::format("entry ({}, {}) is above the diagonal; a symmetric file holds the lower triangle", i, j));
      const double v = parse_value(tokens[2], src, "value");
      if (first_line(i - 1, j - 1) != 0)
        src.fail(fmt::format("entry ({}, {}) repeats line {}", i, j, first_line(i - 1, j - 1)));
      first_line(i - 1, j - 1) = src.line_number();
      a(i - 1, j - 1) = v;
      if (symmetric) a(j - 1, i - 1) = v;
    } else {
      if (tokens.size() != 1) src.fail("expected one value per line in array format");
      a(count % n, count / n) = parse_value(tokens[0], src, "value");  // column-major
    }
    ++count;
  }
  if (count < expected) src.fail(fmt::format("found {} entries, the size line announces {}", count, expected));
  return a;
}

// ---------------------------------------------------------------- CSV

// Dense rows, comma-separated, no header; '#' starts a comment, blank lines are skipped.
Eigen::MatrixXd read_csv_matrix(const fs::path& file, Eigen::Index n) {
  LineSource src(file);
  Eigen::MatrixXd a(n, n);
  Eigen::Index row = 0;
  std::string_view line;
  while (src.next(line)) {
    const std::string_view content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    if (row == n) src.fail(fmt::format("more than {} rows (the sidecar names {} DOFs)", n, n));
    Eigen::Index col = 0;
    for (std::string_view field : split_csv(content)) {
      if (col == n) src.fail(fmt::format("more than {} values in the row (the sidecar names {} DOFs)", n, n));
      a(row, col) = parse_value(field, src, fmt::format("column {}", col + 1));
      ++col;
    }
    if (col != n) src.fail(fmt::format("found {} values in the row, expected {} (one per DOF)", col, n));
    ++row;
  }
  if (row < n) src.fail(fmt::format("found {} rows, expected {} (one per DOF)", row, n));
  return a;
}

// ---------------------------------------------------------------- sidecar

toml::table parse_sidecar(const fs::path& sidecar) {
  if (const std::string why = file_problem(sidecar); !why.empty())
    throw InputError(fmt::format("{}: reduced-model sidecar not found ({})", sidecar.string(), why));
  try {
    return toml::parse_file(sidecar.string());
  } catch (const toml::parse_error& e) {
    throw InputError(
        fmt::format("{}:{}: TOML syntax error: {}", sidecar.string(), e.source().begin.line, e.description()));
  }
}

}  // namespace

void write_reduced_model(const ReducedModel& model, const fs::path& sidecar) {
  // Only the lower triangles are written, so a model that is not symmetric would not survive.
  validate_reduced_model(model, sidecar.string());
  const std::string stem = sidecar.stem().string();
  const fs::path folder = sidecar.parent_path();
  const std::string k_name = stem + ".K.mtx", m_name = stem + ".M.mtx";
  write_matrix_market(model.stiffness, folder / k_name, "stiffness K");
  write_matrix_market(model.mass, folder / m_name, "mass M");

  toml::array dofs;
  for (const ReducedDof& d : model.dofs) dofs.push_back(d.name());
  toml::table table{{"format", "matrix_market"}, {"stiffness", k_name}, {"mass", m_name}, {"dofs", std::move(dofs)}};
  std::ofstream out(sidecar);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing", sidecar.string()));
  out << "# bladebench reduced model (SI units): matrices relative to this file, one name per DOF.\n";
  out << toml::table{{"reduced_model", std::move(table)}} << "\n";
  if (!out) throw InputError(fmt::format("{}: write failed", sidecar.string()));
}

ReducedModel read_reduced_model(const fs::path& sidecar) {
  const toml::table root = parse_sidecar(sidecar);
  TomlReader top(root, "", sidecar);
  TomlReader r(top.table("reduced_model"), "reduced_model", sidecar);
  top.finish();
  const std::string format = r.choice("format", {"matrix_market", "csv", "harwell_boeing"});
  const std::string k_file = r.string("stiffness"), m_file = r.string("mass");
  ReducedModel model;
  if (r.has("dofs") == r.has("dof_map"))
    r.fail("dofs", "name the DOFs either inline (dofs = [...]) or by a DOF map file (dof_map = \"...\"), one of the two");
  fs::path dof_map;
  if (r.has("dof_map")) {
    const fs::path map = dof_map = sidecar.parent_path() / r.string("dof_map");
    if (const std::string why = file_problem(map); !why.empty())
      r.fail("dof_map", fmt::format("DOF map '{}' not found ({})", map.string(), why));
    model.dofs = read_dof_map(map);
    if (model.dofs.size() > kMaxFileDofs)
      throw InputError(fmt::format("{}: names {} DOFs; a reduced-model file holds at most {}", map.string(),
                                   model.dofs.size(), kMaxFileDofs));
  }
  const std::vector<std::string> names = r.has("dofs") ? r.string_array("dofs") : std::vector<std::string>{};
  // The matrices are read into dense n x n arrays: a count taken from the file must not be able to
  // ask for gigabytes before a single entry is read.
  if (names.size() > kMaxFileDofs)
    r.fail("dofs", fmt::format("names {} DOFs; a reduced-model file holds at most {} (dense matrices of {} MB each)",
                               names.size(), kMaxFileDofs, kMaxFileDofs * kMaxFileDofs * 8 / 1'000'000));
  for (size_t i = 0; i < names.size(); ++i) {
    const auto dof = ReducedDof::parse(names[i]);
    if (!dof)
      r.fail("dofs", fmt::format("entry {} '{}' is not a DOF name ('<node>.x|y|z' or 'mode <n>')", i + 1, names[i]));
    model.dofs.push_back(*dof);
  }
  if (model.dofs.empty()) r.fail("dofs", "names no DOF");
  r.finish();

  const auto n = static_cast<Eigen::Index>(model.dofs.size());
  const std::string named_by = dof_map.empty()
                                   ? fmt::format("the sidecar's dofs name {} DOFs", n)
                                   : fmt::format("the DOF map {} names {} DOFs", dof_map.string(), n);
  auto read_matrix = [&](const std::string& key, const std::string& name) {
    const fs::path file = sidecar.parent_path() / name;
    if (const std::string why = file_problem(file); why == "it is a directory")
      r.fail(key, fmt::format("matrix file '{}' is a folder", file.string()));
    else if (!why.empty())
      r.fail(key, fmt::format("matrix file '{}' not found ({})", file.string(), why));
    if (format == "harwell_boeing") return read_harwell_boeing(file, n, named_by);
    return format == "csv" ? read_csv_matrix(file, n) : read_matrix_market(file, n);
  };
  model.stiffness = read_matrix("stiffness", k_file);
  model.mass = read_matrix("mass", m_file);
  validate_reduced_model(model, sidecar.string());
  return model;
}

}  // namespace bb
