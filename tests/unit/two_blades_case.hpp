// Two identical blades coupled by a friction contact, as a lumped hbm case: shared by the tests of
// the analysis and of its levels' byte records.
#pragma once

namespace bb::test {

// Two 1 kg blades, each grounded by k = 1e6 N/m, coupled by kc = 1e5 N/m and by a contact on
// q_A - q_B (kt = 2e5 N/m, mu = 0.3, n0 = 20 N), forced on B.
inline constexpr const char* kTwoBladesCase = R"(
[case]
name = "blades"
[analysis]
type = "hbm"
frequency_hz = [140.0, 215.0]
step_hz = 0.2
harmonics = 1
time_samples = 128
tolerance = 1e-12
modal_damping = 0.01
forces = [{ dof = "B.x", amplitude = 1.0 }]
force_levels = [0.01, 10.0, 1000.0]
responses = ["B.x", "A.x"]
ip_oop = { left = "A.x", right = "B.x" }
[analysis.model]
name = "blades"
dofs = ["A.x", "B.x"]
stiffness = [[1.1e6, -1.0e5], [-1.0e5, 1.1e6]]
mass = [[1.0, 0.0], [0.0, 1.0]]
[[analysis.contact]]
name = "platform"
tangential = { "A.x" = 1.0, "B.x" = -1.0 }
kn = 1.0e6
kt = 2.0e5
mu = 0.3
n0 = 20.0
)";

}  // namespace bb::test
