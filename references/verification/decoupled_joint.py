#!/usr/bin/env python3
"""Synthetic stepped-sine measurements of a jointed structure whose damping grows 5.5-fold while its
resonance moves by 0.1 % (down, then up), and the response-controlled minima they hold; for
cases/verification/nonlinear_modal_identify.toml and nonlinear_modal_predict.toml (issue 68).

Independent of bladebench: the truth is a first-harmonic (describing-function) model written out
here with numpy. Model (SI): one mode, m = 1 kg, at the driven point,
    (k0 + kj(a) + kg(a) + i (c w + hj(a)) - m w^2) X = F,   a = |X|,
  - kj + i hj: 24 Jenkins sliders in parallel (stiffness 20000/24 N/m each, slip displacements
    log-spaced 25 um - 1 mm): the classic describing function (Griffin 1980), in-phase
    kt/pi (b - sin 2b / 2), cos b = 1 - 2 xs / a, quadrature 4 kt xs (a - xs) / (pi a^2). A Masing
    law: alone it would soften by 2.4 Hz over the range.
  - kg: 24 dead-zone springs (stiffness 22000/24 N/m each, gaps the sliders' slip displacements):
    contact stiffening as asperities engage, describing function
    k (1 - 2/pi (asin r + r sqrt(1 - r^2))), r = gap / a. It hardens as the sliders soften, so the
    stiffness and the damping decouple (no single Masing law does this).
  - k0 = m (2 pi (78.5 + drift))^2 - 20000 N/m; c = 2 * 0.0013 * m * 2 pi 78.5.
Each curve has its own drift of the linear frequency, uniform in [-0.1, 0.1] Hz (temperature
between runs of a rig), drawn with the seed below and printed in its file's header.

Curves: 4 force-controlled stepped sines (41 points, 0.05 Hz apart over 77.45-79.45 Hz, nominal
forces 0.02 N up, 0.08 N down, 0.3 N up, 1.0 N down; the measured force jitters 1 % about it and
is written per point; each point reached from the one before, the stable amplitude nearest the
previous one): acceleration amplitude with 2 % noise and its phase to the force with 1 degree.
8 response-controlled curves (acceleration held at 5-80 m/s^2, 61 points over 77-80 Hz,
alternately up and down): the force with 2 % noise and its phase with 1 degree.

Reference (decoupled_joint_minima.csv): the smallest force of each response-controlled level and
its frequency (golden section to 1e-9 Hz), of the joint itself (no drift: what a model of the joint
can predict) and of the measured curve's noise-free form with its drift (what a rig with a perfect
transducer reads that day). Also decoupled_joint_backbone.csv: the truth's
natural frequency and damping ratio at zero drift, f0 where the in-phase term vanishes and
z = (c w0 + hj) / (2 m w0^2).
"""
import numpy as np
from pathlib import Path

HERE = Path(__file__).resolve().parent
DATA = HERE.parent.parent / "cases" / "verification" / "data" / "joint"

M = 1.0
F_LIN = 78.5
XS = np.logspace(np.log10(25e-6), np.log10(1e-3), 24)
KT = np.full(XS.size, 20000.0 / XS.size)
GAPS = XS.copy()
KG = np.full(XS.size, 22000.0 / XS.size)
C = 2.0 * 0.0013 * M * 2.0 * np.pi * F_LIN
SEED = 68


def describing(a):
    """In-phase and quadrature stiffness of the joint at amplitude(s) a [m]."""
    a = np.atleast_1d(np.asarray(a, dtype=float))
    k = np.zeros_like(a)
    h = np.zeros_like(a)
    for xs, kt in zip(XS, KT):
        stuck = a <= xs
        b = np.arccos(np.clip(1.0 - 2.0 * xs / a, -1.0, 1.0))
        k += np.where(stuck, kt, kt / np.pi * (b - np.sin(2.0 * b) / 2.0))
        h += np.where(stuck, 0.0, 4.0 * kt * xs * (a - xs) / (np.pi * a * a))
    for g, kg in zip(GAPS, KG):
        r = np.clip(g / a, 0.0, 1.0)
        k += kg * (1.0 - 2.0 / np.pi * (np.arcsin(r) + r * np.sqrt(1.0 - r * r)))
    return k, h


def dynamic(a, f, drift):
    """Complex dynamic stiffness K(a) - m w^2 at amplitude a and frequency f [Hz]."""
    w = 2.0 * np.pi * f
    k0 = M * (2.0 * np.pi * (F_LIN + drift)) ** 2 - KT.sum()
    k, h = describing(a)
    return k0 + k - M * w * w + 1j * (C * w + h)


def stable_amplitude(force, f, drift, previous):
    """Roots of a |D(a)| = F on a fine log grid; the stable one (slope > 0) nearest the previous."""
    s = np.linspace(np.log(1e-8), np.log(1e-1), 6001)
    a = np.exp(s)
    g = np.log(a * np.abs(dynamic(a, f, drift)) / force)
    roots = []
    for i in np.nonzero(np.sign(g[:-1]) != np.sign(g[1:]))[0]:
        lo, hi = s[i], s[i + 1]
        glo = g[i]
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            gm = np.log(np.exp(mid) * abs(dynamic(np.exp(mid), f, drift)[0]) / force)
            if np.sign(gm) == np.sign(glo):
                lo, glo = mid, gm
            else:
                hi = mid
        roots.append((np.exp(0.5 * (lo + hi)), g[i + 1] > g[i]))
    stable = [r for r, up in roots if up]
    if previous is None:
        return min(stable)
    return min(stable, key=lambda r: abs(np.log(r / previous)))


def smallest_force(level, drift):
    """The smallest force holding the acceleration level over 77-80 Hz, and its frequency (golden section)."""
    def held_force(fi):
        a = level / (2.0 * np.pi * fi) ** 2
        return a * abs(dynamic(a, fi, drift)[0])

    grid = np.linspace(77.0, 80.0, 3001)
    i = int(np.argmin([held_force(x) for x in grid]))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    g = (np.sqrt(5.0) - 1.0) / 2.0
    while hi - lo > 1e-9:
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if held_force(x1) < held_force(x2):
            hi = x2
        else:
            lo = x1
    fm = 0.5 * (lo + hi)
    return fm, held_force(fm)


def write(path, header, columns, rows):
    with open(path, "w") as out:
        for line in header:
            out.write(f"# {line}\n")
        out.write(",".join(columns) + "\n")
        for r in rows:
            out.write(",".join(f"{v:.10g}" for v in r) + "\n")


def wrap_deg(x):
    return (x + 180.0) % 360.0 - 180.0 if not (x + 180.0) % 360.0 == 0.0 else 180.0


def main():
    rng = np.random.default_rng(SEED)
    gen = "generated by references/verification/decoupled_joint.py (numpy); truth and noise described there"
    forces = [(0.02, "up"), (0.08, "down"), (0.3, "up"), (1.0, "down")]
    for nominal, direction in forces:
        drift = rng.uniform(-0.1, 0.1)
        f = 77.45 + 0.05 * np.arange(41)
        if direction == "down":
            f = f[::-1]
        rows, prev = [], None
        for fi in f:
            force = nominal * (1.0 + 0.01 * rng.standard_normal())
            a = stable_amplitude(force, fi, drift, prev)
            prev = a
            phase = -np.degrees(np.angle(dynamic(a, fi, drift)[0]))
            acc = (2.0 * np.pi * fi) ** 2 * a * (1.0 + 0.02 * rng.standard_normal())
            rows.append([fi, acc, wrap_deg(phase + 180.0 + rng.standard_normal()), force, 0.02 * acc, 1.0])
        name = f"fc_{nominal:g}N_{direction}.csv"
        write(DATA / name, [gen, f"force-controlled, nominal {nominal:g} N, {direction}; drift of the linear "
                                 f"frequency {drift:+.4f} Hz; 2 % amplitude noise, 1 deg phase noise"],
              ["frequency [Hz]", "amplitude [m/s^2]", "phase [deg]", "force [N]", "amplitude_sigma [m/s^2]",
               "phase_sigma [deg]"], rows)
    minima = []
    for k, level in enumerate([5.0, 7.5, 10.0, 15.0, 20.0, 30.0, 50.0, 80.0]):
        drift = rng.uniform(-0.1, 0.1)
        f = 77.0 + 0.05 * np.arange(61)
        if k % 2:
            f = f[::-1]
        rows = []
        for fi in f:
            w = 2.0 * np.pi * fi
            a = level / w**2
            d = dynamic(a, fi, drift)[0]
            force = M * 0 + a * abs(d)
            noisy = force * (1.0 + 0.02 * rng.standard_normal())
            phase = -np.degrees(np.angle(d))
            rows.append([fi, level, wrap_deg(phase + 180.0 + rng.standard_normal()), noisy, 1.0, 0.02 * force])
        write(DATA / f"rc_{level:g}.csv", [gen, f"response-controlled, acceleration held at {level:g} m/s^2; drift "
                                                 f"of the linear frequency {drift:+.4f} Hz; 2 % force noise, 1 deg "
                                                 f"phase noise"],
              ["frequency [Hz]", "amplitude [m/s^2]", "phase [deg]", "force [N]", "phase_sigma [deg]",
               "force_sigma [N]"], rows)

        fm, fmin = smallest_force(level, 0.0)
        dm, dmin = smallest_force(level, drift)
        minima.append([k + 1, level, fm, fmin, dm, dmin, drift])
    write(HERE / "decoupled_joint_minima.csv",
          ["Smallest force of each response-controlled level of the synthetic decoupled joint and its frequency:",
           "min_*: the joint's own (noise-free, no drift: what a model of the joint predicts); curve_min_*: those",
           "of the measured curve's noise-free form with its drift (cases/verification/data/joint/rc_<level>.csv),",
           "drift_hz that curve's drift of the linear frequency. Generated by decoupled_joint.py (the truth, its",
           "drifts and noise are described there). Key: control (the order of the case's",
           "[[analysis.response_control]])."],
          ["control", "acceleration_m_s2", "min_frequency_hz", "min_force_n", "curve_min_frequency_hz",
           "curve_min_force_n", "drift_hz"], minima)
    rows = []
    for i, a in enumerate(np.logspace(np.log10(2e-5), np.log10(3.2e-4), 9)):
        k, h = describing(a)
        w0 = np.sqrt((M * (2.0 * np.pi * F_LIN) ** 2 - KT.sum() + k[0]) / M)
        rows.append([i + 1, a, w0 / (2.0 * np.pi), (C * w0 + h[0]) / (2.0 * M * w0 * w0)])
    write(HERE / "decoupled_joint_backbone.csv",
          ["Natural frequency and damping ratio of the synthetic decoupled joint at zero drift, against the",
           "displacement amplitude at the driven point. Generated by decoupled_joint.py."],
          ["point", "amplitude_m", "frequency_hz", "damping_ratio"], rows)


if __name__ == "__main__":
    main()
