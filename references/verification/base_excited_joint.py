#!/usr/bin/env python3
"""The held-out peak of cases/verification/base_excited_joint_identify_check.toml; writes
base_excited_joint_held_out_peak.csv.

The friction oscillator (m = 1 kg, k = 1e6 N/m, c = 20 N s/m, Jenkins contact to the table with
kt = 1e6 N/m, mu = 0.3, N0 = 30 N) on a shaker table accelerating at a_b cos(w t). Relative to the
table, z = q - u_b, the mass obeys m z'' + c z' + k z + T(z) = -m a_b cos(w t): the force-driven
oscillator with F = m a_b in antiphase, whose single-harmonic peak is the describing function's
(hbm_friction_oscillator_describing_function.py, Griffin 1980). The antiphase moves the phase and
nothing else, so the peak per m/s^2 of table acceleration is m times the force-driven one per newton.
"""
import importlib.util
from pathlib import Path

_spec = importlib.util.spec_from_file_location(
    "df", Path(__file__).resolve().parent / "hbm_friction_oscillator_describing_function.py")
df = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(df)

A_B = 30.0  # [m/s^2], the held-out level

if __name__ == "__main__":
    hz, per_n = df.peak(df.m * A_B)
    out = Path(__file__).resolve().parent / "base_excited_joint_held_out_peak.csv"
    with open(out, "w") as f:
        f.write("# The 30 m/s^2 peak of the friction oscillator on a shaker table (m = 1 kg, k = 1e6 N/m,\n")
        f.write("# c = 20 N s/m, kt = 1e6 N/m, mu = 0.3, N0 = 30 N), relative to the table: the force-driven\n")
        f.write("# oscillator's at F = m a_b = 30 N by the describing function (base_excited_joint.py), keyed 1\n")
        f.write("# for cases/verification/base_excited_joint_identify_check.toml; amplitude per m/s^2. Key: level.\n")
        f.write("level,table_acceleration_m_s2,peak_hz,peak_amp_per_n\n")
        f.write(f"1,{A_B:g},{hz:.12g},{per_n * df.m:.12g}\n")
    print(out.read_text())
