#!/usr/bin/env python3
"""Reference for cases/verification/nonlinear_modal_two_modes.toml: two uncoupled nonlinear modes
at one co-located driven point, solved from their amplitude equations alone (numpy).

Each mode k answers the force F on its own,
    m_k (w_k(a_k)^2 - w^2 + 2 i z_k(a_k) w_k(a_k) w) x_k = F,   a_k = |x_k|,   w_k = 2 pi f_k(a_k),
and the point moves by x = x_0 + x_1. The backbones are the case's: a quantity with two knots
(a_0, y_0), (a_1, y_1) is y_0 + (y_1 - y_0) (3 t^2 - 2 t^3), t = log(a / a_0) / log(a_1 / a_0) clipped
to [0, 1] (the only cubic in log a through both knots with zero slope at each, constant beyond:
what the case's clamped spline is for two knots); with one knot, a constant.

Force-controlled stepped sine: for each frequency, every root a_k of m_k a |D_k(a)| = F on a log
grid of 1500 amplitudes over 1e-10 to 1 m (sign changes refined by bisection); the stable root nearest the previous
point's amplitude in log a (the smallest from rest). The case's modes have one root everywhere
(checked below), so the choice never matters.
Response-controlled: the force F whose |x(F)| equals the held displacement, by bisection in log F
(|x| grows with F here: checked on a scan); each curve's smallest force over its grid refined
between the neighbours of the grid's smallest point by a parabola through three points, shrunk
until the points are 1e-7 Hz apart (a smooth minimum: the parabola's vertex is exact to O(h^3)).

Writes nonlinear_modal_two_modes.csv (key point: selected points of the stepped sine) and
nonlinear_modal_two_modes_minima.csv (key control: each response-controlled curve's smallest
force and its frequency).

With --identify: the data of nonlinear_modal_two_modes_identify.toml instead, three stepped sines
(0.05 N up, 0.3 N down, 1.2 N up over 101.5-104.5 Hz in 0.05 Hz steps) of the same mode 0 and
a mode 1 that softens and damps more (TRUTH_1 below), noise-free, in
cases/verification/data/two_modes/; and nonlinear_modal_two_modes_truth.csv, the truth's mode 1
backbone on the grid of the case's backbone_1 table (81 amplitudes, log-spaced from a tenth of the
first knot to ten times the last) that the fit's cross-check compares with.
"""
import math
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

# (knot amplitudes [m], values) per quantity, and the mass [kg]: the case's [[analysis.mode]].
MODES = [
    {"f": ([1.0e-5, 1.0e-4], [100.0, 99.6]), "z": ([1.0e-5, 1.0e-4], [0.002, 0.005]), "m": 1.0},
    {"f": ([1.0e-5], [103.0]), "z": ([2.0e-5, 2.0e-4], [0.003, 0.004]), "m": 1.5},
]
FORCE = 0.15  # [N], the stepped sine's
SWEEP = (97.0, 106.0, 0.1)  # first, last, step [Hz]: up
POINTS = [1, 21, 28, 31, 35, 45, 55, 58, 61, 65, 91]  # the stepped sine's points checked (1-based)
HELD = [(1, 2.0e-5), (2, 6.0e-5)]  # (control, held displacement [m])
HELD_SWEEP = (96.0, 106.0, 0.1)


def bisect(g, lo, hi):
    """The root of g in [lo, hi] (a sign change) to the last bit."""
    glo = g(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        gm = g(mid)
        if (gm < 0.0) == (glo < 0.0):
            lo, glo = mid, gm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def curve(knots, a):
    """The quantity at amplitude(s) a (a float or a numpy array)."""
    amps, values = knots
    if len(amps) == 1:
        return values[0] + 0.0 * a
    t = np.clip(np.log(a / amps[0]) / math.log(amps[1] / amps[0]), 0.0, 1.0)
    return values[0] + (values[1] - values[0]) * (3.0 * t * t - 2.0 * t**3)


def dynamic(mode, a, f_exc):
    w0 = 2.0 * math.pi * curve(mode["f"], a)
    w = 2.0 * math.pi * f_exc
    return (w0 * w0 - w * w) + 2j * curve(mode["z"], a) * w0 * w


def force_of(mode, a, f_exc):
    return mode["m"] * a * abs(dynamic(mode, a, f_exc))


def roots(mode, force, f_exc):
    s = np.linspace(math.log(1e-10), math.log(1.0), 1500)
    r = np.log(force_of(mode, np.exp(s), f_exc) / force)
    out = []
    for i in range(len(s) - 1):
        if (r[i] < 0.0) != (r[i + 1] < 0.0):
            g = lambda x: math.log(force_of(mode, math.exp(x), f_exc) / force)
            out.append(math.exp(bisect(g, s[i], s[i + 1])))
    return out


def stable(mode, a, f_exc):
    h = 1e-6 * a
    return force_of(mode, a + h, f_exc) > force_of(mode, a - h, f_exc)


def mode_response(mode, force, f_exc, previous):
    rs = roots(mode, force, f_exc)
    assert len(rs) == 1, f"a fold at {f_exc} Hz, {force} N: {rs}"
    ok = [a for a in rs if stable(mode, a, f_exc)]
    a = min(ok, key=lambda a: a if previous is None else abs(math.log(a / previous)))
    return a, force / (mode["m"] * dynamic(mode, a, f_exc))


def grid(first, last, step):
    n = int(math.floor(abs(last - first) / step + 1e-9))
    return [first + i * step for i in range(n + 1)]


def stepped_sine():
    rows, previous = [], [None] * len(MODES)
    for i, f in enumerate(grid(*SWEEP)):
        x = 0.0
        for k, mode in enumerate(MODES):
            previous[k], xk = mode_response(mode, FORCE, f, previous[k])
            x += xk
        rows.append((i + 1, f, abs(x), math.degrees(math.atan2(x.imag, x.real)), previous[0], previous[1]))
    return rows


def held_force(held, f_exc):
    amp = lambda force: abs(sum(mode_response(m, force, f_exc, None)[1] for m in MODES))
    scan = np.exp(np.linspace(math.log(1e-4), math.log(20.0), 40))
    values = [amp(F) for F in scan]
    assert all(np.diff(values) > 0.0), f"|x| does not grow with F at {f_exc} Hz"
    i = next(j for j, v in enumerate(values) if v >= held)
    return math.exp(bisect(lambda x: math.log(amp(math.exp(x)) / held), math.log(scan[i - 1]), math.log(scan[i])))


def smallest_force(held):
    fs = grid(*HELD_SWEEP)
    forces = [held_force(held, f) for f in fs]
    k = int(np.argmin(forces))
    assert 0 < k < len(fs) - 1, "the smallest force is at the band's edge"
    centre, h = fs[k], 0.5 * (fs[k + 1] - fs[k - 1])
    while h > 1e-7:
        fm, f0, fp = (held_force(held, centre + d) for d in (-h, 0.0, h))
        centre += 0.5 * h * (fm - fp) / (fm - 2.0 * f0 + fp)  # the parabola's vertex
        h *= 0.1
    return held_force(held, centre), centre


TRUTH_1 = {"f": ([2.0e-5, 2.0e-4], [103.0, 102.7]), "z": ([2.0e-5, 2.0e-4], [0.003, 0.005]), "m": 1.5}
IDENTIFY = [("fc_0.05N_up", 0.05, (101.5, 104.5, 0.05)), ("fc_0.3N_down", 0.3, (104.5, 101.5, 0.05)),
            ("fc_1.2N_up", 1.2, (101.5, 104.5, 0.05))]


def identify_data():
    modes = [MODES[0], TRUTH_1]
    folder = os.path.join(HERE, "..", "..", "cases", "verification", "data", "two_modes")
    os.makedirs(folder, exist_ok=True)
    for name, force, (first, last, step) in IDENTIFY:
        n = int(math.floor(abs(last - first) / step + 1e-9))
        fs = [first + (1.0 if last > first else -1.0) * i * step for i in range(n + 1)]
        previous = [None, None]
        with open(os.path.join(folder, name + ".csv"), "w") as out:
            out.write("# generated by references/verification/nonlinear_modal_two_modes.py --identify (numpy):\n")
            out.write(f"# two uncoupled modes, mode 0 {MODES[0]}, mode 1 {TRUTH_1}; {force} N, noise-free\n")
            out.write("frequency [Hz],amplitude [m],phase [deg],force [N]\n")
            for f in fs:
                x = 0.0
                for k, mode in enumerate(modes):
                    previous[k], xk = mode_response(mode, force, f, previous[k])
                    x += xk
                out.write(f"{f:.10g},{abs(x):.15g},{math.degrees(math.atan2(x.imag, x.real)):.15g},{force:.15g}\n")
    knots = TRUTH_1["f"][0] + TRUTH_1["z"][0]
    lo, hi = min(knots) / 10.0, max(knots) * 10.0
    with open(os.path.join(HERE, "nonlinear_modal_two_modes_truth.csv"), "w") as out:
        out.write("# source: references/verification/nonlinear_modal_two_modes.py --identify (numpy): the truth of\n")
        out.write("# mode 1 of nonlinear_modal_two_modes_identify.toml, f and z as smoothsteps in log a (the\n")
        out.write("# two-knot clamped spline) on the grid of the backbone_1 table\n")
        out.write("point,amplitude_m,frequency_hz,damping_ratio\n")
        for k in range(81):
            a = lo * (hi / lo) ** (k / 80.0)
            out.write(f"{k + 1},{a:.15g},{float(curve(TRUTH_1['f'], a)):.15g},{float(curve(TRUTH_1['z'], a)):.15g}\n")


def main():
    import sys

    if "--identify" in sys.argv:
        identify_data()
        return
    rows = stepped_sine()
    with open(os.path.join(HERE, "nonlinear_modal_two_modes.csv"), "w") as out:
        out.write("# source: references/verification/nonlinear_modal_two_modes.py (numpy), its own solution of\n")
        out.write("# two uncoupled nonlinear modes at one point (two-knot backbones as smoothsteps in log a); the\n")
        out.write(f"# stepped sine of {FORCE} N up over {SWEEP[0]}-{SWEEP[1]} Hz in {SWEEP[2]} Hz steps, each mode\n")
        out.write("# on its one root. amp_m, phase_deg: |x| and arg x to the force; a0_m, a1_m: each mode's amplitude\n")
        out.write("point,frequency_hz,amp_m,phase_deg,a0_m,a1_m\n")
        for r in rows:
            if r[0] in POINTS:
                out.write(",".join(f"{v:.15g}" for v in r) + "\n")
    with open(os.path.join(HERE, "nonlinear_modal_two_modes_minima.csv"), "w") as out:
        out.write("# source: references/verification/nonlinear_modal_two_modes.py (numpy): each held\n")
        out.write("# displacement's smallest force over 96-106 Hz (0.1 Hz grid, then the vertex of parabolas between\n")
        out.write("# the grid minimum's neighbours, shrunk to 1e-7 Hz), the force from |x_0(F) + x_1(F)| = held by bisection\n")
        out.write("control,held_m,min_force_n,min_frequency_hz\n")
        for control, held in HELD:
            force, freq = smallest_force(held)
            out.write(f"{control},{held:.15g},{force:.15g},{freq:.15g}\n")
    for r in rows:
        if r[0] in POINTS:
            print(" ".join(f"{v:.10g}" for v in r))


if __name__ == "__main__":
    main()
