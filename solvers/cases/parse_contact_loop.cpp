#include "cases/parse_contact_loop.hpp"

#include <fmt/format.h>

#include "cases/parse_friction_law.hpp"

namespace bb {

ContactLoopSpec parse_contact_loop(TomlReader& r) {
  ContactLoopSpec s;
  s.at = r.location();
  s.tangential_amplitude = r.positive("tangential_amplitude_m");
  s.normal_amplitude = r.non_negative("normal_amplitude_m", 0.0);
  s.normal_phase_deg = r.optional_number("normal_phase_deg").value_or(0.0);
  if (const auto n = r.optional_integer("samples")) {
    // >= 16: the loop's corners need a few samples per stick/slip segment; the cap bounds memory.
    if (*n < 16 || *n > 1'000'000)
      r.fail("samples", fmt::format("must lie in [16, 1000000] (samples per period), found {}", *n));
    s.samples = static_cast<int>(*n);
  }
  // Every law value is required: a rig states its contact, no silent default.
  TomlReader c(r.table("contact"), r.path() + ".contact", r.file());
  s.point.kn = c.number("kn");
  if (!(s.point.kn >= 0.0)) c.fail("kn", fmt::format("must be >= 0, found {}", s.point.kn));
  s.point.kt = c.positive("kt");
  s.point.mu = c.number("mu");
  if (!(s.point.mu >= 0.0)) c.fail("mu", fmt::format("must be >= 0, found {}", s.point.mu));
  s.point.n0 = c.number("n0");
  if (!(s.point.n0 >= 0.0)) c.fail("n0", fmt::format("must be >= 0, found {}", s.point.n0));
  s.distribution = parse_slider_distribution(c, s.point);
  c.finish();
  if (s.normal_amplitude > 0.0 && s.point.kn == 0.0)
    r.fail("normal_amplitude_m", "a normal motion needs kn > 0 in [analysis.contact] (kn = 0 keeps N = n0)");
  return s;
}

}  // namespace bb
