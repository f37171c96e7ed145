#!/usr/bin/env python3
"""Phase-only stepped sines for friction_oscillator_identify_phase.toml, from the synthetic FRFs
frf_0.1N.csv and frf_3N.csv beside this script (bladebench synthesize; see their headers): the
form a rig with an accelerometer and a phase meter, and no calibrated amplitude, gives.

Each row keeps its noisy phase and sigma; the amplitude columns are dropped; the phase is made the
acceleration's (the displacement's + 180 deg, wrapped to (-180, 180]); the frequency is written as
its ratio to the oscillator's free natural frequency sqrt(k / m) / 2 pi = 159.154943091895 Hz
(k = 1e6 N/m, m = 1 kg). Writes frf_0.1N_phase.csv and frf_3N_phase.csv.
"""
import csv
import math
from pathlib import Path

HERE = Path(__file__).resolve().parent
F_N = math.sqrt(1.0e6 / 1.0) / (2.0 * math.pi)

for level in ("0.1N", "3N"):
    rows = list(csv.reader(line for line in open(HERE / f"frf_{level}.csv") if not line.startswith("#")))
    header = [h.split("[")[0].strip() for h in rows[0]]
    f, phase, sigma = (header.index(c) for c in ("frequency", "phase", "phase_sigma"))
    with open(HERE / f"frf_{level}_phase.csv", "w") as out:
        out.write(f"# phase-only form of frf_{level}.csv, written by phase_only.py: acceleration phase,\n")
        out.write(f"# frequency as the ratio to the free natural frequency {F_N:.12g} Hz\n")
        out.write("frequency [-],phase [deg],phase_sigma [deg]\n")
        for r in rows[1:]:
            p = math.remainder(float(r[phase]) + 180.0, 360.0)
            p = p + 360.0 if p <= -180.0 else p
            out.write(f"{float(r[f]) / F_N:.12g},{p:.10g},{r[sigma]}\n")
