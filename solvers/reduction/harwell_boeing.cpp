// Harwell-Boeing: four header cards (title and key; card counts; type and sizes; Fortran formats),
// then the column pointers, the row indices and the values in fixed-width fields. The fields are cut
// by the formats' widths, as Fortran reads them: values may touch ("-1.0E+00-2.0E+00").
#include "reduction/harwell_boeing.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "common/csv_reader.hpp"
#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace bb {
namespace fs = std::filesystem;
namespace harwell_boeing_impl {
namespace {

struct FortranFormat {
  int per_line = 0;
  int width = 0;
};

std::string upper_compact(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// "(10I8)", "(5E16.8)", "(1P,4E20.12)", "(1P4D25.16)", "(3ES26.16E3)": repeat count and field width.
std::optional<FortranFormat> parse_format(std::string_view text) {
  std::string f = upper_compact(text);
  if (f.size() < 3 || f.front() != '(' || f.back() != ')') return std::nullopt;
  f = f.substr(1, f.size() - 2);
  if (const size_t p = f.find('P'); p != std::string::npos && p + 1 < f.size() && f.find_first_of("IEDFG") > p) {
    f = f.substr(p + 1);  // a scale factor "1P" changes how values print, not how they read
    if (!f.empty() && f.front() == ',') f = f.substr(1);
  }
  size_t i = 0;
  int repeat = 0;
  while (i < f.size() && std::isdigit(static_cast<unsigned char>(f[i]))) repeat = repeat * 10 + (f[i++] - '0');
  if (i == f.size() || std::string_view("IEDFG").find(f[i]) == std::string_view::npos) return std::nullopt;
  ++i;
  if (i < f.size() && (f[i] == 'S' || f[i] == 'N')) ++i;  // ES, EN
  int width = 0;
  while (i < f.size() && std::isdigit(static_cast<unsigned char>(f[i]))) width = width * 10 + (f[i++] - '0');
  if (width < 1 || width > 100) return std::nullopt;
  return FortranFormat{repeat == 0 ? 1 : repeat, width};
}

// The fields of `count` numbers over `cards` lines in `format`; every line but the last is full.
class FieldReader {
 public:
  FieldReader(LineSource& src, FortranFormat format, std::string_view what) : src_(src), f_(format), what_(what) {}

  std::vector<std::string> read(long count, long cards) {
    std::vector<std::string> out;
    out.reserve(static_cast<size_t>(count));
    const long needed = (count + f_.per_line - 1) / f_.per_line;
    if (needed != cards)
      src_.fail(fmt::format("the header gives {} cards of {}, but {} numbers at {} per card take {}", cards, what_,
                            count, f_.per_line, needed));
    std::string_view line;
    for (long card = 0; card < cards; ++card) {
      if (!src_.next(line)) src_.fail(fmt::format("the file ends inside the {} ({} of {} cards)", what_, card, cards));
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      const long on_line = std::min<long>(f_.per_line, count - static_cast<long>(out.size()));
      for (long k = 0; k < on_line; ++k) {
        const size_t start = static_cast<size_t>(k * f_.width);
        const std::string_view field =
            start < line.size() ? trim(line.substr(start, static_cast<size_t>(f_.width))) : "";
        if (field.empty())
          src_.fail(fmt::format("{}: field {} is empty; the format says {} per card, {} characters each", what_, k + 1,
                                f_.per_line, f_.width));
        out.emplace_back(field);
      }
      if (line.size() > static_cast<size_t>(on_line * f_.width) &&
          !trim(line.substr(static_cast<size_t>(on_line * f_.width))).empty())
        src_.fail(fmt::format("{}: more than {} numbers on the card (the header's format)", what_, on_line));
    }
    return out;
  }

 private:
  LineSource& src_;
  FortranFormat f_;
  std::string_view what_;
};

long to_long(const LineSource& src, std::string_view s, std::string_view what) {
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size())
    src.fail(fmt::format("{} '{}' is not an integer", what, printable(s)));
  return v;
}

double to_double(const LineSource& src, std::string s) {
  for (char& c : s)
    if (c == 'D' || c == 'd') c = 'E';  // Fortran's double-precision exponent
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(v))
    src.fail(fmt::format("value '{}' is not a finite number", printable(s)));
  return v;
}

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  for (size_t i = 0; i < s.size();) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

}  // namespace
}  // namespace harwell_boeing_impl

Eigen::MatrixXd read_harwell_boeing(const fs::path& file, Eigen::Index n, std::string_view named_by) {
  using namespace harwell_boeing_impl;  // this file's helpers, in this scope only (unity builds)
  LineSource src(file);
  std::string_view line;
  if (!src.next(line)) src.fail("empty file; expected the Harwell-Boeing title card");
  if (!src.next(line)) src.fail("missing the card counts (TOTCRD PTRCRD INDCRD VALCRD RHSCRD)");
  const std::vector<std::string_view> counts = words(line);
  if (counts.size() < 4 || counts.size() > 5) src.fail("expected the card counts TOTCRD PTRCRD INDCRD VALCRD [RHSCRD]");
  const long total = to_long(src, counts[0], "TOTCRD"), ptr_cards = to_long(src, counts[1], "PTRCRD"),
             ind_cards = to_long(src, counts[2], "INDCRD"), val_cards = to_long(src, counts[3], "VALCRD"),
             rhs_cards = counts.size() == 5 ? to_long(src, counts[4], "RHSCRD") : 0;
  if (total != ptr_cards + ind_cards + val_cards + rhs_cards || ptr_cards < 0 || ind_cards < 0 || val_cards < 0 ||
      rhs_cards < 0)
    src.fail(fmt::format("TOTCRD {} is not PTRCRD + INDCRD + VALCRD + RHSCRD = {}", total,
                         ptr_cards + ind_cards + val_cards + rhs_cards));
  if (!src.next(line)) src.fail("missing the type card (MXTYPE NROW NCOL NNZERO NELTVL)");
  const std::vector<std::string_view> type_card = words(line);
  if (type_card.size() < 4) src.fail("expected MXTYPE NROW NCOL NNZERO [NELTVL]");
  const std::string type = upper_compact(type_card[0]);
  if (type.size() != 3 || type[0] != 'R' || (type[1] != 'S' && type[1] != 'U') || type[2] != 'A')
    src.fail(
        fmt::format("matrix type '{}': bladebench reads real assembled matrices, RSA (symmetric, one triangle) or "
                    "RUA (every entry); complex, pattern-only, skew, Hermitian and elemental ones are not read",
                    printable(type_card[0])));
  const long rows = to_long(src, type_card[1], "NROW"), cols = to_long(src, type_card[2], "NCOL"),
             nnz = to_long(src, type_card[3], "NNZERO");
  if (rows != n || cols != n) src.fail(fmt::format("the matrix is {} x {}, but {}", rows, cols, named_by));
  if (nnz < 0 || nnz > n * n) src.fail(fmt::format("NNZERO {} cannot fit a {} x {} matrix", nnz, n, n));
  if (!src.next(line)) src.fail("missing the format card (PTRFMT INDFMT VALFMT)");
  const std::vector<std::string_view> formats = words(line);
  if (formats.size() < 3) src.fail("expected the formats PTRFMT INDFMT VALFMT [RHSFMT]");
  std::array<FortranFormat, 3> fmts{};
  for (size_t k = 0; k < 3; ++k) {
    const auto f = parse_format(formats[k]);
    if (!f)
      src.fail(
          fmt::format("'{}' is not a Fortran format bladebench reads (e.g. (10I8), (4E20.12))", printable(formats[k])));
    fmts[k] = *f;
  }
  if (rhs_cards > 0 && !src.next(line)) src.fail("missing the right-hand-side card (RHSTYP NRHS NRHSIX)");

  const std::vector<std::string> pointers = FieldReader(src, fmts[0], "column pointers").read(cols + 1, ptr_cards);
  const std::vector<std::string> indices = FieldReader(src, fmts[1], "row indices").read(nnz, ind_cards);
  const std::vector<std::string> values = FieldReader(src, fmts[2], "values").read(nnz, val_cards);
  for (long card = 0; card < rhs_cards; ++card)
    if (!src.next(line)) src.fail("the file ends inside the right-hand sides the header announces");
  const unsigned last_card = src.line_number();
  if (src.next_content('\0')) src.fail(fmt::format("data after the {} cards the header announces (TOTCRD)", total));

  // Pointers and indices are checked where they were read: name the card by its number.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  bool lower = false, upper = false;
  long previous = 1;
  auto fail_at = [&](const std::string& message) {
    throw InputError(fmt::format("{}: {} (cards end at line {})", file.string(), message, last_card));
  };
  if (to_long(src, pointers[0], "the first column pointer") != 1) fail_at("the first column pointer must be 1");
  for (long j = 0; j < cols; ++j) {
    const long begin = to_long(src, pointers[static_cast<size_t>(j)], "a column pointer");
    const long end = to_long(src, pointers[static_cast<size_t>(j + 1)], "a column pointer");
    if (begin != previous || end < begin || end > nnz + 1)
      fail_at(fmt::format("column pointers {} and {} of column {} do not run from 1 up to NNZERO + 1 = {}", begin, end,
                          j + 1, nnz + 1));
    previous = end;
    long last_row = 0;
    for (long k = begin - 1; k < end - 1; ++k) {
      const long i = to_long(src, indices[static_cast<size_t>(k)], "a row index");
      if (i < 1 || i > rows) fail_at(fmt::format("row index {} of column {} is out of 1..{}", i, j + 1, rows));
      if (i <= last_row) fail_at(fmt::format("row index {} of column {} repeats or runs backwards", i, j + 1));
      last_row = i;
      const double v = to_double(src, values[static_cast<size_t>(k)]);
      a(i - 1, j) = v;
      lower |= i - 1 > j;
      upper |= i - 1 < j;
    }
  }
  if (previous != nnz + 1) fail_at(fmt::format("the last column pointer is {}, NNZERO + 1 is {}", previous, nnz + 1));
  if (type[1] == 'S') {
    if (lower && upper)
      fail_at("an RSA (symmetric) file holds one triangle, this one has entries on both sides of the diagonal");
    const Eigen::MatrixXd half = a;
    a = half + half.transpose();
    a.diagonal() = half.diagonal();
    return a;
  }
  const double largest = a.cwiseAbs().maxCoeff();
  Eigen::Index worst_i = 0, worst_j = 0;
  const double asymmetry = (a - a.transpose()).cwiseAbs().maxCoeff(&worst_i, &worst_j);
  if (asymmetry > 1e-8 * largest)
    fail_at(
        fmt::format("the RUA matrix is not symmetric: entries ({0}, {1}) and ({1}, {0}) differ by {2:.3g}, "
                    "{3:.3g} of the largest entry; stiffness and mass must be symmetric",
                    worst_i + 1, worst_j + 1, asymmetry, asymmetry / largest));
  return a;
}

std::vector<ReducedDof> read_dof_map(const fs::path& file) {
  using namespace harwell_boeing_impl;  // this file's helpers, in this scope only (unity builds)
  LineSource src(file);
  std::optional<std::string_view> content = src.next_content('#');
  if (!content) src.fail("empty DOF map; expected a header (Ansys: 'Matrix Eqn  Node  DOF', CSV: 'node,direction')");
  const std::string header = upper_compact(*content);
  const bool ansys = header.starts_with("MATRIXEQN");
  if (!ansys && header != "NODE,DIRECTION")
    src.fail(fmt::format("header '{}': expected Ansys's 'Matrix Eqn  Node  DOF' or the CSV header node,direction",
                         printable(*content)));
  std::vector<ReducedDof> dofs;
  std::set<std::string> seen;
  while ((content = src.next_content('#'))) {
    std::vector<std::string_view> cells = ansys ? words(*content) : split_csv(*content);
    if (cells.size() != (ansys ? 3u : 2u))
      src.fail(ansys ? "expected a row 'equation node DOF'" : "expected a row node,direction");
    if (ansys && to_long(src, cells[0], "the equation number") != static_cast<long>(dofs.size()) + 1)
      src.fail(fmt::format("equation {} where {} comes next: the map lists the rows in order", trim(cells[0]),
                           dofs.size() + 1));
    const std::string_view node = trim(cells[ansys ? 1 : 0]);
    to_long(src, node, "the node number");
    const std::string dir = upper_compact(cells[ansys ? 2 : 1]);
    const int direction = dir == "UX" || dir == "X"   ? 0
                          : dir == "UY" || dir == "Y" ? 1
                          : dir == "UZ" || dir == "Z" ? 2
                                                      : -1;
    if (direction < 0)
      src.fail(fmt::format("DOF '{}': bladebench's reduced models hold translations (UX, UY, UZ or x, y, z)",
                           printable(cells[ansys ? 2 : 1])));
    const ReducedDof dof{std::string(node), direction, 0};
    if (!seen.insert(dof.name()).second) src.fail(fmt::format("DOF {} is listed twice", dof.name()));
    dofs.push_back(dof);
  }
  if (dofs.empty()) src.fail("the DOF map names no DOF");
  return dofs;
}

}  // namespace bb
