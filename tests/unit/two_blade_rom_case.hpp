// The Table XI model as a case file: the committed 28-DOF reduced blades
// (cases/thesis/data/two_blade_rom/) with the rigid underplatform damper of
// cases/thesis/table11_calibrate_contact.toml (CF = 300 N), the force on F, responses T2.x, T1.x.
#pragma once
#include <string>

namespace bb::test {

struct TwoBladeRomCase {
  std::string kt = "1.0e8", mu = "0.5";
  std::string levels = "[300.0]";        // force levels [N]
  std::string range = "[172.0, 182.0]";  // frequency_hz
  std::string step = "0.05";
  std::string samples = "64";
  std::string harmonics = "1";
  std::string tolerance;  // empty: the default
  bool ip_oop = false;
  std::string analysis_extra;  // more [analysis] keys
  std::string extra;           // appended: [calibration], data blocks
};

inline std::string two_blade_rom_case_text(const TwoBladeRomCase& c) {
  return "[case]\nname = \"two_blade_rom\"\n[analysis]\ntype = \"hbm\"\nfrequency_hz = " + c.range +
         "\nstep_hz = " + c.step + "\nharmonics = " + c.harmonics + "\ntime_samples = " + c.samples + "\n" +
         (c.tolerance.empty() ? "" : "tolerance = " + c.tolerance + "\n") +
         "modal_damping = 0.01\nforces = [{ dof = \"F.x\", amplitude = 1.0 }]\nforce_levels = " + c.levels +
         "\nresponses = [\"T2.x\", \"T1.x\"]\n" + (c.ip_oop ? "ip_oop = { left = \"T1.x\", right = \"T2.x\" }\n" : "") +
         c.analysis_extra + "\n[analysis.model]\nname = \"blades\"\nfile = \"" + BB_SOURCE_DIR +
         "/cases/thesis/data/two_blade_rom/blades.toml\"\n"
         "[analysis.damper]\nmass = 0.07\ninertia = 4.95e-6\ncentre = [0.0415, 0.0345]\nleft_face_deg = "
         "45.0\nright_face_deg = 45.0\n"
         "centrifugal_force = 300.0\nkn = 1.0e8\nkt = " +
         c.kt + "\nmu = " + c.mu +
         "\n"
         "points = [{ name = \"L1\", face = \"left\", point = \"L1\", position = [0.025625, 0.034125] },\n"
         "          { name = \"L2\", face = \"left\", point = \"L2\", position = [0.031875, 0.040375] },\n"
         "          { name = \"R\", face = \"right\", point = \"R\", position = [0.05625, 0.03725] }]\n" +
         c.extra;
}

}  // namespace bb::test
