#include "forced/hbm_level_bytes.hpp"

#include <complex>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "distributed/byte_record.hpp"

namespace bb {
namespace {

// One list of fields per type, read by both directions: what is written is what is read back.
// A field added to one of these types must be added to its list; the sizes below stop the build
// until it is (x86-64, GCC's layout).
static_assert(sizeof(HbmLevel) == 512);
static_assert(sizeof(HbmPeak) == 472);
static_assert(sizeof(hbm::HbmSolution) == 112);
static_assert(sizeof(friction::AftResult) == 288);
static_assert(sizeof(hbm::ContinuationResult) == 96);
static_assert(sizeof(hbm::ContinuationPoint) == 56);
static_assert(sizeof(hbm::HillStability) == 120);
static_assert(sizeof(hbm::HarmonicTruncation) == 40);
static_assert(sizeof(hbm::CycleEnergy) == 32);
static_assert(sizeof(HbmLevel::SamplingTrial) == 32);
static_assert(sizeof(HbmLevel::HarmonicTrial) == 64);

template <class T>
concept Number = std::is_arithmetic_v<T>;
template <class T>
concept Enum = std::is_enum_v<T>;

struct Writer {
  distributed::ByteWriter out;

  template <class... T>
  void operator()(T&... values) {
    (io(values), ...);
  }
  void io(Number auto& v) { out.put(v); }
  void io(Enum auto& v) { out.put(static_cast<std::underlying_type_t<std::remove_reference_t<decltype(v)>>>(v)); }
  void io(std::string& s) { out.put(s); }
  template <class S, int R, int C, int O, int MR, int MC>
  void io(Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    out.put(static_cast<std::int64_t>(m.rows())).put(static_cast<std::int64_t>(m.cols()));
    for (Eigen::Index k = 0; k < m.size(); ++k) io(m.data()[k]);
  }
  void io(std::complex<double>& z) { out.put(z.real()).put(z.imag()); }
  template <class T>
  void io(std::vector<T>& v) {
    out.put(static_cast<std::uint64_t>(v.size()));
    for (T& e : v) io(e);
  }
  template <class T>
  void io(std::optional<T>& o) {
    out.put(static_cast<int>(o.has_value()));
    if (o) io(*o);
  }
  template <class S>
  requires std::is_class_v<S>
  void io(S& s) { fields(*this, s); }
};

struct Reader {
  distributed::ByteReader in;

  template <class... T>
  void operator()(T&... values) {
    (io(values), ...);
  }
  void io(Number auto& v) { in.get(v); }
  void io(Enum auto& v) {
    std::underlying_type_t<std::remove_reference_t<decltype(v)>> u{};
    in.get(u);
    v = static_cast<std::remove_reference_t<decltype(v)>>(u);
  }
  void io(std::string& s) { in.get(s); }
  template <class S, int R, int C, int O, int MR, int MC>
  void io(Eigen::Matrix<S, R, C, O, MR, MC>& m) {
    std::int64_t rows = 0, cols = 0;
    in.get(rows);
    in.get(cols);
    if (rows < 0 || cols < 0 || (R != Eigen::Dynamic && rows != R) || (C != Eigen::Dynamic && cols != C))
      throw std::runtime_error("a rank's level holds a matrix of the wrong shape");
    m.resize(rows, cols);
    for (Eigen::Index k = 0; k < m.size(); ++k) io(m.data()[k]);
  }
  void io(std::complex<double>& z) {
    double re = 0.0, im = 0.0;
    in.get(re);
    in.get(im);
    z = {re, im};
  }
  template <class T>
  void io(std::vector<T>& v) {
    std::uint64_t n = 0;
    in.get(n);
    v.clear();
    for (std::uint64_t k = 0; k < n; ++k) io(v.emplace_back());
  }
  template <class T>
  void io(std::optional<T>& o) {
    int has = 0;
    in.get(has);
    o.reset();
    if (has) io(o.emplace());
  }
  template <class S>
  requires std::is_class_v<S>
  void io(S& s) { fields(*this, s); }
};

template <class A>
void fields(A& a, friction::AftResult& r) {
  a(r.tangential, r.normal, r.dtangential_du, r.dtangential_dv, r.dnormal_dv, r.dtangential_dlaw, r.dnormal_dlaw, r.u,
    r.u_2, r.v, r.t, r.n, r.w, r.state, r.periods, r.closed, r.closure_mismatch);
}
template <class A>
void fields(A& a, hbm::HbmSolution& s) {
  a(s.x, s.omega, s.iterations, s.residual, s.converged, s.failure, s.contacts, s.start);
}
template <class A>
void fields(A& a, hbm::ContinuationPoint& p) {
  a(p.omega, p.x, p.residual, p.iterations, p.step, p.tangent_omega);
}
template <class A>
void fields(A& a, hbm::ContinuationResult& r) {
  a(r.points, r.converged, r.failure, r.turned_back, r.turning_points, r.corrector_iterations, r.rejected_steps,
    r.jumps, r.corners, r.amplitude_scale);
}
template <class A>
void fields(A& a, hbm::CycleEnergy& e) {
  a(e.excitation, e.viscous, e.friction, e.normal);
}
template <class A>
void fields(A& a, hbm::HarmonicTruncation& t) {
  a(t.harmonics, t.probe_harmonics, t.share, t.ok);
}
template <class A>
void fields(A& a, hbm::HillStability& s) {
  a(s.ok, s.failure, s.stable, s.max_real, s.unresolved, s.unresolved_real, s.exponents, s.growing);
}
template <class A>
void fields(A& a, HbmPeak& p) {
  a(p.kind, p.frequency_hz, p.amplitude, p.component, p.solution, p.energy, p.trusted, p.doubt, p.sampling_error,
    p.truncation, p.stability, p.harmonics, p.frequency_hz_dlog, p.amplitude_dlog);
}
template <class A>
void fields(A& a, HbmLevel::SamplingTrial& t) {
  a(t.samples, t.aft_error, t.reached_end, t.trusted, t.seconds);
}
template <class A>
void fields(A& a, HbmLevel::HarmonicTrial& t) {
  a(t.harmonics, t.samples, t.share, t.change, t.estimated_error, t.reached_end, t.trusted, t.chosen, t.seconds,
    t.window_hz, t.band_change);
}
template <class A>
void fields(A& a, HbmLevel& l) {
  a(l.force, l.path, l.frequency_hz, l.amplitude, l.phase_deg, l.excursion, l.components, l.stable, l.floquet_max_real,
    l.amplitude_dlog, l.phase_dlog_deg, l.peaks, l.harmonic_share, l.harmonics_needed, l.point_harmonics,
    l.point_change, l.failed_hz, l.samples, l.harmonics, l.seconds, l.sampling_trials, l.harmonic_trials);
}

}  // namespace

std::string to_bytes(const HbmLevel& level) {
  Writer w;
  w.io(const_cast<HbmLevel&>(level));  // the writer reads only
  return w.out.bytes();
}

HbmLevel level_from_bytes(const std::string& bytes) {
  Reader r{distributed::ByteReader(bytes)};
  HbmLevel level;
  r.io(level);
  if (!r.in.done()) throw std::runtime_error("a rank's level runs on past its fields");
  return level;
}

}  // namespace bb
