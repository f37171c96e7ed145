#!/usr/bin/env python3
"""Exact periodic response of the Coulomb oscillator at friction ratios Ff / F0 = 0.1 ... 0.9, below and
above resonance, for cases/verification/coulomb_oscillator_shooting_ratios.toml; writes one
coulomb_den_hartog_fp<ratio>_<band>.csv per ratio and band (below: 80-140 Hz, above: 180-400 Hz;
columns point, frequency_hz, max_m, first_harmonic_m, motion; points numbered from 1 in each band).

m x'' + k x + Ff sgn(x') = F0 cos(w t), m = 1 kg, k = 1e6 N/m, Ff = 3 N (the model of
coulomb_den_hartog.py), F0 = Ff / ratio. The symmetric periodic motion, x(t + T/2) = -x(t), is built
from closed-form pieces (no time stepping):
  slip with x' > 0 from rest at x = -X at time tb:
    x = A cos(wn s) + B sin(wn s) + a cos(w t) - c,  s = t - tb,  a = (F0/k) / (1 - r^2),  c = Ff / k,
    A = -X - a cos(w tb) + c,  B = a r sin(w tb)  (x(tb) = -X, x'(tb) = 0);
  non-stop motion (Den Hartog 1931): the slip lasts exactly T/2 and X is his closed form;
  motion with one stop per half period: the mass breaks away where F0 cos(w tb) + k X = Ff (the
    spring and the load overcome friction), slips until x' = 0 at tr, and must arrive there at
    x(tr) = X and stay stuck, |F0 cos(w t) - k X| <= Ff, until tb + T/2 (the symmetric breakaway).
    One unknown, tb (X follows from the breakaway), found by bisection on x(tr) - X.
A point is written only where one of the two motions exists and passes every check (the velocity
keeps its sign while slipping, the stop holds, the four boundary conditions to 1e-9); else it is
left out and counted on stderr. Frequencies 80-140 Hz (r = 0.50-0.88) and 180-400 Hz (r = 1.13-2.51),
4 Hz apart; near r = 1 the undamped amplitude is unbounded below Ff / F0 = pi / 4.
"""
import math
import sys

m, k, Ff = 1.0, 1.0e6, 3.0
wn = math.sqrt(k / m)
RATIOS = (0.1, 0.3, 0.5, 0.7, 0.9)
BANDS = {"below": [80.0 + 4.0 * i for i in range(16)], "above": [180.0 + 4.0 * i for i in range(56)]}


def slip(F0, w, tb, X):
    """x(t), x'(t) of the positive slip from rest at x = -X, time tb."""
    r = w / wn
    a = (F0 / k) / (1 - r * r)
    c = Ff / k
    A = -X - a * math.cos(w * tb) + c
    B = a * r * math.sin(w * tb)
    x = lambda t: A * math.cos(wn * (t - tb)) + B * math.sin(wn * (t - tb)) + a * math.cos(w * t) - c
    v = lambda t: -A * wn * math.sin(wn * (t - tb)) + B * wn * math.cos(wn * (t - tb)) - a * w * math.sin(w * t)
    return x, v


def first_rest(v, tb, T):
    """First t in (tb, tb + T) where the positive velocity returns to zero (None if it never does)."""
    n = 800
    h = T / n
    for i in range(1, n + 1):
        t1 = tb + i * h
        v1 = v(t1)
        if v1 <= 0.0 and i > 1:
            lo, hi = t1 - h, t1
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                (lo, hi) = (mid, hi) if v(mid) > 0.0 else (lo, mid)
            return 0.5 * (lo + hi)
    return None


def first_harmonic(x_of_t, w):
    """|first harmonic| of a motion given over one period [0, T) with x(t + T/2) = -x(t)."""
    T = 2 * math.pi / w
    n = 20000
    a1 = b1 = 0.0
    for i in range(n):
        t = (i + 0.5) * (T / 2) / n
        a1 += 2 * x_of_t(t) * math.cos(w * t) * (T / 2) / n
        b1 += 2 * x_of_t(t) * math.sin(w * t) * (T / 2) / n
    return math.hypot(a1, b1) * 2 / T


def non_stop(F0, w):
    r = w / wn
    a = (F0 / k) / (1 - r * r)
    c = Ff / k
    s = c * math.tan(math.pi / (2 * r)) / (a * r)
    if abs(s) >= 1:
        return None
    cphi = math.sqrt(1 - s * s) * (1 if a < 0 else -1)
    phi = math.atan2(s, cphi)
    X = -a * cphi
    T = 2 * math.pi / w
    tb = (phi / w) % T  # Den Hartog's t = 0 (x = -X, x' = 0), where the load's phase is phi
    x, v = slip(F0, w, tb, X)
    h = T / 2
    for value, target in ((x(tb), -X), (v(tb), 0.0), (x(tb + h), X), (v(tb + h) / (w * X), 0.0)):
        if abs(value - target) > 1e-9 * X:
            return None
    for i in range(1, 4000):
        if v(tb + i * h / 4000) < -1e-9 * w * X:
            return None  # the mass stops: not a non-stop motion
    # the reversal must not stick: at x = X the load and spring exceed friction
    if abs(F0 * math.cos(w * (tb + h)) - k * X) <= Ff:
        return None
    xt = lambda t: x(tb + (t - tb) % h) if ((t - tb) % T) < h else -x(tb + (t - tb - h) % h)
    return X, first_harmonic(xt, w)


def with_stops(F0, w):
    T = 2 * math.pi / w
    h = T / 2

    def mismatch(tb):
        X = (Ff - F0 * math.cos(w * tb)) / k
        if X <= 0:
            return None
        x, v = slip(F0, w, tb, X)
        tr = first_rest(v, tb, T)
        if tr is None or tr >= tb + h:
            return None
        return x(tr) - X, X, tr, x

    n = 400
    found = []
    prev = None
    for i in range(n + 1):
        tb = i * T / n
        cur = mismatch(tb)
        if prev is not None and cur is not None and prev[1][0] * cur[0] < 0:
            lo, hi = prev[0], tb
            glo = prev[1][0]
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                g = mismatch(mid)
                if g is None:
                    break
                if (g[0] < 0) == (glo < 0):
                    lo, glo = mid, g[0]
                else:
                    hi = mid
            g = mismatch(0.5 * (lo + hi))
            if g is not None and abs(g[0]) <= 1e-9 * g[1]:
                found.append((0.5 * (lo + hi), g))
        prev = (tb, cur) if cur is not None else None
    for tb, (_, X, tr, x) in found:
        # breakaway with positive acceleration, stuck from tr to tb + T/2
        if F0 * math.cos(w * tb) + k * X < Ff - 1e-9 * Ff:
            continue
        if any(abs(F0 * math.cos(w * (tr + (tb + h - tr) * j / 400)) - k * X) > Ff * (1 + 1e-9) for j in range(401)):
            continue

        def xt(t, tb=tb, tr=tr, X=X, x=x):
            u = (t - tb) % T
            sign = 1.0 if u < h else -1.0
            u = u % h
            return sign * (x(tb + u) if u < tr - tb else X)

        return X, first_harmonic(xt, w)
    return None


for ratio in RATIOS:
    F0 = Ff / ratio
    for band, frequencies in BANDS.items():
        skipped = 0
        name = f"coulomb_den_hartog_fp{ratio:.1f}_{band}.csv"
        with open(name, "w") as out:
            out.write(f"# Exact periodic response of the Coulomb oscillator, Ff/F0 = {ratio:.1f} (F0 = {F0:.10g} N), "
                      f"{frequencies[0]:.0f}-{frequencies[-1]:.0f} Hz; generated by coulomb_den_hartog_ratios.py\n")
            out.write("# motion: 0 = non-stop (Den Hartog's closed form), 1 = one stop per half period\n")
            out.write("point,frequency_hz,max_m,first_harmonic_m,motion\n")
            for i, f in enumerate(frequencies):
                w = 2 * math.pi * f
                res, motion = non_stop(F0, w), 0
                if res is None:
                    res, motion = with_stops(F0, w), 1
                if res is None:
                    skipped += 1
                    continue
                out.write(f"{i + 1},{f:.1f},{res[0]:.12e},{res[1]:.12e},{motion}\n")
        print(f"{name}: {len(frequencies) - skipped} points, {skipped} without a motion of either kind",
              file=sys.stderr)
