#!/usr/bin/env python3
"""Closed-form first-harmonic (describing-function) peaks of the lumped friction oscillator of
cases/verification/friction_oscillator_hbm.toml; writes hbm_friction_oscillator_peaks.csv.

Model (SI): m q'' + c q' + k q + T(q) = F cos(w t), T a Jenkins element to the ground (kt, slip
force Fs = mu N0, constant normal load). c = 2 zeta sqrt(k m) (modal damping zeta on the only mode).
For u = a cos(theta) with a > xs = Fs / kt the first harmonic of T is (Griffin 1980, Menq):
  in phase      k_eq(a) a, k_eq = kt / pi (beta - sin(2 beta) / 2), cos(beta) = 1 - 2 xs / a
  in quadrature q(a)      = 4 Fs (1 - xs / a) / pi   (energy 4 Fs (a - xs) per cycle)
(verified against a sampled hysteresis loop to 1e-9). The single-harmonic balance (H = 1) is then
  F^2 = ((k + k_eq(a) - m w^2) a)^2 + (c w a + q(a))^2,
exactly what the HBM solves with H = 1, up to the AFT sampling. For each a the force needed is
least at one w (d/dw = 0); the peak amplitude for force F is the a whose least force is F, the
peak frequency that w. For a <= xs (stuck) the oscillator is linear with stiffness k + kt.
"""
import math

m, k, zeta = 1.0, 1.0e6, 0.01
kt, mu, n0 = 1.0e6, 0.3, 30.0
c = 2 * zeta * math.sqrt(k * m)
Fs = mu * n0
xs = Fs / kt


def contact(a):
    if a <= xs:
        return kt, 0.0
    beta = math.acos(1 - 2 * xs / a)
    return kt / math.pi * (beta - math.sin(2 * beta) / 2), 4 * Fs * (1 - xs / a) / math.pi


def least_force(a, contact=contact):
    """The least force holding amplitude a, and its w; `contact(a)` gives the contact's in-phase
    stiffness and quadrature force (the Jenkins element here; other scripts pass their joint's)."""
    ke, q = contact(a)
    K = k + ke
    # d/dw [((K - m w^2) a)^2 + (c w a + q)^2] = 0: bisection on the derivative near sqrt(K/m)
    def dg(w):
        return -4 * m * w * (K - m * w * w) * a * a + 2 * c * a * (c * w * a + q)
    lo, hi = 0.5 * math.sqrt(K / m), math.sqrt(K / m)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if dg(lo) * dg(mid) <= 0:
            hi = mid
        else:
            lo = mid
    w = 0.5 * (lo + hi)
    return math.hypot((K - m * w * w) * a, c * w * a + q), w


def peak(F, contact=contact):
    lo, hi = 1e-12, 10 * F / (c * math.sqrt(k / m))
    for _ in range(300):
        mid = math.sqrt(lo * hi)
        if least_force(mid, contact)[0] < F:
            lo = mid
        else:
            hi = mid
    a = math.sqrt(lo * hi)
    return least_force(a, contact)[1] / (2 * math.pi), a / F


def free_peak():
    # linear oscillator without the contact (mu = 0): max of 1 / |k - w^2 m + i w c|
    w = math.sqrt(k / m) * math.sqrt(1 - 2 * zeta ** 2)
    return w / (2 * math.pi), 1 / (2 * zeta * k * math.sqrt(1 - zeta ** 2))


if __name__ == "__main__":
    levels = [0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 1000.0, 10000.0]
    for i, F in enumerate(levels, 1):
        f, r = peak(F)
        print(f"{i},{F:g},{f:.10g},{r:.10g}")
    print("free", *free_peak())
