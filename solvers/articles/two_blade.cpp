// Block decomposition of the two-blade test article. Units: SI (m).
#include "articles/two_blade.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bb {
namespace {

// The smallest clearance that stays open when blocks merge at 1e-7 m (cases/build_model).
constexpr double kMinClearance = 1e-6;

using Vec2 = Eigen::Vector2d;

// Adds planar quadrilaterals (corners counterclockwise seen from +z) extruded over [0, t].
class BlockList {
 public:
  BlockList(TwoBladeArticle& article, double t, int nz, ElementType element)
      : article_(article), t_(t), nz_(nz), element_(element) {}

  void quad(TwoBladeBody body, const std::string& label, const Vec2& c1, const Vec2& c2, const Vec2& c3, const Vec2& c4,
            int nx, int ny) {
    HexBlockSpec b;
    const std::array<Vec2, 4> c = {c1, c2, c3, c4};
    for (size_t a = 0; a < 4; ++a) {
      b.corners[a] = Eigen::Vector3d(c[a].x(), c[a].y(), 0.0);
      b.corners[a + 4] = Eigen::Vector3d(c[a].x(), c[a].y(), t_);
    }
    b.nx = nx;
    b.ny = ny;
    b.nz = nz_;
    b.element = element_;
    article_.blocks.push_back(b);
    article_.body.push_back(body);
    article_.label.push_back(label);
  }

  void rect(TwoBladeBody body, const std::string& label, double x0, double x1, double y0, double y1, int nx, int ny) {
    quad(body, label, {x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, nx, ny);
  }

 private:
  TwoBladeArticle& article_;
  double t_;
  int nz_;
  ElementType element_;
};

}  // namespace

double TwoBladeDimensions::contact_rise() const {
  return 0.5 * (B_p - w_n) * std::tan(beta_deg * std::numbers::pi / 180.0);
}

std::array<double, 9> TwoBladeDimensions::levels() const {
  std::array<double, 9> y{};
  y[0] = -(h_w + t_fb);
  y[1] = -h_w;
  y[2] = 0.0;
  y[3] = H_r;
  y[4] = H_r + t_a;
  y[5] = H_r + H_n;
  y[6] = y[5] + contact_rise();
  y[7] = y[6] + e_p;
  y[8] = y[7] + L_a;
  return y;
}

std::span<const TwoBladeDimensionField> two_blade_dimension_fields() {
  using D = TwoBladeDimensions;
  static const TwoBladeDimensionField fields[] = {
      {"t", &D::t},     {"B_r", &D::B_r},   {"H_r", &D::H_r}, {"x_n1", &D::x_n1},
      {"w_n", &D::w_n}, {"H_n", &D::H_n},   {"B_p", &D::B_p}, {"beta_deg", &D::beta_deg},
      {"e_p", &D::e_p}, {"w", &D::w},       {"w_t", &D::w_t}, {"L_a", &D::L_a},
      {"p", &D::p},     {"t_a", &D::t_a},   {"g_s", &D::g_s}, {"g_r", &D::g_r},
      {"h_w", &D::h_w}, {"t_fb", &D::t_fb}, {"m_f", &D::m_f},
  };
  return fields;
}

std::span<const char* const> two_blade_set_names() {
  static const char* const names[] = {
      "T1", "T2", "F", "L1", "L2", "R", "C1", "C2", "fixture_base", "fixture_left", "fixture_right", "tip1", "tip2"};
  return names;
}

std::span<const char* const> two_blade_contact_set_names() {
  static const char* const names[] = {"root1_top", "arm1_bottom", "root1_bottom", "wedge1_top",
                                      "root2_top", "arm2_bottom", "root2_bottom", "wedge2_top"};
  return names;
}

void TwoBladeDimensions::validate() const {
  for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
    if (std::string_view(f.name) != "w_t") require_positive_size(f.name, this->*f.member);
  if (!(w_t >= 0) || !std::isfinite(w_t))
    throw DimensionError("w_t", fmt::format("w_t must be >= 0 (0 = equal to w), found {}", w_t));
  if (!(beta_deg > 0 && beta_deg < 90))
    throw DimensionError("beta_deg", fmt::format("beta_deg must lie in (0, 90) degrees, found {}", beta_deg));
  if (refinement < 1 || refinement > 64)
    throw DimensionError("refinement", fmt::format("refinement must lie in 1..64, found {}", refinement));
  if (thickness_divisions < 0 || thickness_divisions > 1000)
    throw DimensionError(
        "thickness_divisions",
        fmt::format("thickness_divisions must lie in 0..1000 (0 = 4 x refinement), found {}", thickness_divisions));
  if (nz() % 2 != 0)
    throw DimensionError(
        "thickness_divisions",
        fmt::format("thickness_divisions must be even so that the mid-thickness points are nodes, found {}", nz()));
  if (airfoil_divisions < 1 || airfoil_divisions > 1000 || (airfoil_divisions * refinement) % 4 != 0)
    throw DimensionError(
        "airfoil_divisions",
        fmt::format("airfoil_divisions x refinement must be a positive multiple of 4 so that F (at L_a / 4) "
                    "is a node, found {} x {}",
                    airfoil_divisions, refinement));
  for (const char* name : {"g_s", "g_r"}) {
    const double g = std::string_view(name) == "g_s" ? g_s : g_r;
    if (g < kMinClearance)
      throw DimensionError(name,
                           fmt::format("{} = {} m: a clearance must be at least {} m so that gluing at coincident "
                                       "nodes does not close it",
                                       name, g, kMinClearance));
  }
  if (!(x_n1 + g_s < B_r))
    throw DimensionError("x_n1", fmt::format("x_n1 + g_s = {} must be < B_r = {}: no right root shoulder under the arm",
                                             x_n1 + g_s, B_r));
  if (!(x_n0() - g_s > 0))
    throw DimensionError(
        "w_n", fmt::format("x_n1 - w_n - g_s = {} must be > 0: no left root shoulder under the arm", x_n0() - g_s));
  if (!(H_n > t_a))
    throw DimensionError("H_n", fmt::format("H_n = {} must exceed the arm thickness t_a = {}: the platform would sit "
                                            "inside the fixture",
                                            H_n, t_a));
  if (!(B_p > w_n)) throw DimensionError("B_p", fmt::format("B_p = {} must exceed the neck width w_n = {}", B_p, w_n));
  if (!(w < B_p)) throw DimensionError("w", fmt::format("w = {} must be narrower than the platform, B_p = {}", w, B_p));
  if (!(p > B_p))
    throw DimensionError("p", fmt::format("the pitch p = {} must exceed the platform width B_p = {}: the platforms "
                                          "would overlap",
                                          p, B_p));
  if (!(p - B_r - 2 * g_r > 0))
    throw DimensionError("p", fmt::format("p - B_r - 2 g_r = {} must be > 0: no fixture wall between the root "
                                          "cavities",
                                          p - B_r - 2 * g_r));
  if (!(tip_width() < p))
    throw DimensionError("w_t", fmt::format("the tip width {} must be smaller than the pitch p = {}", tip_width(), p));
}

TwoBladeArticle two_blade_article(const TwoBladeDimensions& d, ElementType element) {
  if (element_dimension(element) != 3)
    throw std::invalid_argument("two_blade_article needs a solid element (hex8, hex8i or hex20)");
  d.validate();
  TwoBladeArticle a;
  a.levels = d.levels();
  const auto& Y = a.levels;
  const int r = d.refinement;
  const double x_n0 = d.x_n0(), x_n1 = d.x_n1, x_c = d.x_c();
  const double x_pl = x_c - 0.5 * d.B_p, x_pr = x_c + 0.5 * d.B_p;  // platform edges
  const double x_a0 = x_c - 0.5 * d.w, x_a1 = x_c + 0.5 * d.w;      // airfoil faces at its root
  const double half_tip = 0.5 * d.tip_width();
  BlockList list(a, d.t, d.nz(), element);

  // The root's x-intervals: left shoulder (under the arm), slot clearance, neck, slot
  // clearance, right shoulder. The wedge below and the fixture floor below that repeat them so
  // that the faces they share have the same nodes.
  struct Interval {
    const char* name;
    double x0, x1;
    int n;
    bool shoulder;  // under a fixture arm
  };
  const std::array<Interval, 5> root = {{{"1", 0.0, x_n0 - d.g_s, 1, true},
                                         {"2", x_n0 - d.g_s, x_n0, 1, false},
                                         {"3", x_n0, x_n1, 2, false},
                                         {"4", x_n1, x_n1 + d.g_s, 1, false},
                                         {"5", x_n1 + d.g_s, d.B_r, 1, true}}};
  for (int b = 0; b < 2; ++b) {
    const double o = b * d.p;
    const auto blade = b == 0 ? TwoBladeBody::blade1 : TwoBladeBody::blade2;
    const auto wedge = b == 0 ? TwoBladeBody::wedge1 : TwoBladeBody::wedge2;
    const std::string bl = fmt::format("blade{}.", b + 1), wl = fmt::format("wedge{}.", b + 1);
    for (const Interval& i : root) {
      list.rect(blade, bl + "R" + i.name, o + i.x0, o + i.x1, Y[2], Y[3], i.n * r, 2 * r);
      list.rect(wedge, wl + "W" + i.name, o + i.x0, o + i.x1, Y[1], Y[2], i.n * r, r);
    }
    list.rect(blade, bl + "N1", o + x_n0, o + x_n1, Y[3], Y[4], 2 * r, r);  // neck inside the arm slot
    list.rect(blade, bl + "N2", o + x_n0, o + x_n1, Y[4], Y[5], 2 * r, r);  // free neck
    // Platforms: edge c1-c2 of PL and PR is the contact face of the damper (4 r divisions, so
    // L1, L2 at 1/4 and 3/4 and R at 1/2 are nodes).
    list.quad(blade, bl + "PL", {o + x_pl, Y[6]}, {o + x_n0, Y[5]}, {o + x_a0, Y[7]}, {o + x_pl, Y[7]}, 4 * r, 2 * r);
    list.quad(blade, bl + "PC", {o + x_n0, Y[5]}, {o + x_n1, Y[5]}, {o + x_a1, Y[7]}, {o + x_a0, Y[7]}, 2 * r, 2 * r);
    list.quad(blade, bl + "PR", {o + x_n1, Y[5]}, {o + x_pr, Y[6]}, {o + x_pr, Y[7]}, {o + x_a1, Y[7]}, 4 * r, 2 * r);
    list.quad(blade, bl + "A", {o + x_a0, Y[7]}, {o + x_a1, Y[7]}, {o + x_c + half_tip, Y[8]},
              {o + x_c - half_tip, Y[8]}, 2 * r, d.airfoil_divisions * r);
    a.tips[static_cast<size_t>(b)] = {Y[8], o + x_c - half_tip, o + x_c + half_tip};
  }

  // Fixture: one body of rectangular cells. Columns from left to right; the walls stand on the
  // base row, the arms cover the root shoulders and leave the slot around the neck open.
  a.fixture_left_x = d.fixture_left_x();
  a.fixture_right_x = d.fixture_right_x();
  a.fixture_base_y = Y[0];
  struct Column {
    double x0, x1;
    int n;
    bool wall;  // solid from the floor to the top
    bool arm;   // solid in the arm row only
  };
  std::vector<Column> columns;
  columns.push_back({a.fixture_left_x, -d.g_r, 2, true, false});
  for (int b = 0; b < 2; ++b) {
    const double o = b * d.p;
    columns.push_back({o - d.g_r, o, 1, false, true});
    for (const Interval& i : root) columns.push_back({o + i.x0, o + i.x1, i.n, false, i.shoulder});
    columns.push_back({o + d.B_r, o + d.B_r + d.g_r, 1, false, true});
    if (b == 0) columns.push_back({d.B_r + d.g_r, d.p - d.g_r, 2, true, false});
  }
  columns.push_back({d.p + d.B_r + d.g_r, a.fixture_right_x, 2, true, false});
  int k = 0;
  for (const Column& c : columns) {
    ++k;
    list.rect(TwoBladeBody::fixture, fmt::format("fixture.base{}", k), c.x0, c.x1, Y[0], Y[1], c.n * r, 2 * r);
    if (c.wall)
      list.rect(TwoBladeBody::fixture, fmt::format("fixture.wall{}", k), c.x0, c.x1, Y[1], Y[3], c.n * r, 3 * r);
    if (c.wall || c.arm)
      list.rect(TwoBladeBody::fixture, fmt::format("fixture.arm{}", k), c.x0, c.x1, Y[3], Y[4], c.n * r, r);
  }

  // Master nodes at mid-thickness (thesis: every master node lies on the middle plane).
  const double zm = 0.5 * d.t;
  const double a_c = x_pr - x_n1, c = Y[6] - Y[5];  // horizontal and vertical extent of a contact face
  const double w_F = d.w + 0.25 * (d.tip_width() - d.w);
  a.points["T1"] = {x_c, Y[8], zm};
  a.points["T2"] = {d.p + x_c, Y[8], zm};
  a.points["F"] = {d.p + x_c + 0.5 * w_F, Y[7] + 0.25 * d.L_a, zm};
  a.points["L1"] = {x_n1 + 0.25 * a_c, Y[5] + 0.25 * c, zm};
  a.points["L2"] = {x_n1 + 0.75 * a_c, Y[5] + 0.75 * c, zm};
  a.points["R"] = {d.p + x_n0 - 0.5 * a_c, Y[5] + 0.5 * c, zm};
  // Tip corners, off the torsion axis: the thesis's remedy for torsional modes that mid-plane
  // masters cannot see (section 3.3.1.3).
  a.points["C1"] = {a.tips[0].x_max, Y[8], 0.0};
  a.points["C2"] = {a.tips[1].x_max, Y[8], 0.0};
  return a;
}

}  // namespace bb
