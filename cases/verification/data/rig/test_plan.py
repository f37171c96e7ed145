"""The stepped sines of the synthetic rig test (rig_joint_truth.toml): frequencies and the force
a force-controlled shaker actually held at each of them, then the response-controlled curves.
Prints the [[analysis.stepped_sine]] and [[analysis.response_control]] blocks pasted into
rig_joint_truth.toml; run again to check they are unchanged.

Assumptions, each a habit of real rigs rather than data of one: 41 points per curve, 0.05 Hz
apart, around the resonance of each level; the force dips by up to 25 % of its nominal value at
resonance (the shaker's armature sees the structure's low impedance there), drifts slowly by
+-5 % along the curve and jitters by 2 % from point to point (seeded, reproducible).
"""
import math
import random

random.seed(33)
# (name, nominal force [N], first and last frequency [Hz], resonance [Hz] at that level)
CURVES = [
    ("up_0.03N", 0.03, 77.55, 79.55, 78.55),
    ("down_0.1N", 0.10, 79.40, 77.40, 78.40),
    ("up_0.25N", 0.25, 77.25, 79.25, 78.23),
    ("down_0.5N", 0.50, 79.05, 77.05, 78.05),
]
for name, force, f0, f1, fr in CURVES:
    n = 41
    freqs = [round(f0 + (f1 - f0) * i / (n - 1), 4) for i in range(n)]
    forces = []
    for i, f in enumerate(freqs):
        dip = 0.25 * math.exp(-(((f - fr) / 0.25) ** 2))
        drift = 0.05 * math.sin(2 * math.pi * i / (n - 1))
        jitter = random.gauss(0.0, 0.02)
        forces.append(round(force * (1.0 - dip + drift + jitter), 6))
    print("[[analysis.stepped_sine]]")
    print(f'name = "{name}"')
    print("frequency_hz = [" + ", ".join(f"{f:g}" for f in freqs) + "]")
    print("force = [" + ", ".join(f"{F:g}" for F in forces) + "]")
    print()

# Response-controlled curves: the acceleration of the driving point held at each level while the
# rig adjusts the force, 61 points 0.05 Hz apart over 77-80 Hz, alternately up and down.
for k, level in enumerate([5, 7.5, 10, 15, 20, 30, 50, 80]):
    first, last = (77.0, 80.0) if k % 2 == 0 else (80.0, 77.0)
    print("[[analysis.response_control]]")
    print(f'name = "rc_{level:g}"')
    print('dof = "A.x"')
    print(f"acceleration = {float(level)}  # [m/s^2]")
    print(f"frequency_hz = [{first}, {last}]")
    print("step_hz = 0.05")
    print()
