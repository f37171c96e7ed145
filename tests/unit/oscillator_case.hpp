// The lumped friction oscillator of the harmonic-balance tests as a case file: m = 1 kg on
// k = 1e6 N/m to the ground, a Jenkins contact to the ground along x with kn = 1e6 N/m and the
// constant normal load n0 = 30 N, the force F cos(w t) on the mass, the response of the mass.
#pragma once
#include <string>

namespace bb::test {

struct OscillatorCase {
  std::string kt = "1.0e6", mu = "0.3", zeta = "0.01";
  std::string levels = "[1.0]";          // force levels [N]
  std::string range = "[130.0, 260.0]";  // frequency_hz
  std::string step = "0.2";              // step_hz
  std::string samples = "128";           // AFT samples
  std::string tolerance;                 // empty: the default
  std::string analysis_extra;            // more [analysis] keys
  std::string extra;                     // appended: checks, [calibration], data blocks
};

inline std::string oscillator_case_text(const OscillatorCase& c) {
  return "[case]\nname = \"oscillator\"\n[analysis]\ntype = \"hbm\"\nfrequency_hz = " + c.range +
         "\nstep_hz = " + c.step + "\nharmonics = 1\ntime_samples = " + c.samples + "\n" +
         (c.tolerance.empty() ? "" : "tolerance = " + c.tolerance + "\n") + "modal_damping = " + c.zeta +
         "\nforces = [{ dof = \"A.x\", amplitude = 1.0 }]\nforce_levels = " + c.levels + "\nresponses = [\"A.x\"]\n" +
         c.analysis_extra +
         "\n[analysis.model]\nname = \"oscillator\"\ndofs = [\"A.x\"]\nstiffness = [[1.0e6]]\nmass = [[1.0]]\n"
         "[[analysis.contact]]\nname = \"ground\"\ntangential = { \"A.x\" = 1.0 }\nkn = 1.0e6\nkt = " +
         c.kt + "\nmu = " + c.mu + "\nn0 = 30.0\n" + c.extra;
}

}  // namespace bb::test
