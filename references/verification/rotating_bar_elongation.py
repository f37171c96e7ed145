#!/usr/bin/env python3
"""Radial elongation of a uniform bar spinning about one end, the closed forms that
cases/verification/rotating_bar_elongation.toml checks. Writes rotating_bar_elongation.csv beside
this script. Units: SI. Run: python3 references/verification/rotating_bar_elongation.py

A bar of length L clamped at the axis (x = 0), free at x = L, density rho, modulus E, spinning at
Omega, axial displacement u(x) in the rotating frame:
  without spin softening (the load of the undeformed positions only; code_aster test SDLL104 /
  V3.04.104, "Reference solution"):  E u'' + rho Omega^2 x = 0,
      u(x) = rho Omega^2 / (2 E) (L^2 x - x^3 / 3);
  with spin softening (the load follows the deformed position):  E u'' + rho Omega^2 (x + u) = 0,
      u(0) = 0, u'(L) = 0:  u(x) = sin(k x) / (k cos(k L)) - x,  k = Omega sqrt(rho / E).
The axial stress of the softened steady state (what stiffens a blade), sigma = E u' =
E (cos(k x) / cos(k L) - 1), goes to rotating_bar_stress.csv, keyed by the node ids of the case's
q4 64 x 2 mesh (rows numbering: node 66 at (0, 0.01), node 98 at (0.5, 0.01)).
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
L, RHO, E, OMEGA = 1.0, 7800.0, 2.0e11, 1000.0
K = OMEGA * math.sqrt(RHO / E)


def linear(x):
    return RHO * OMEGA ** 2 / (2 * E) * (L * L * x - x ** 3 / 3)


def softened(x):
    return math.sin(K * x) / (K * math.cos(K * L)) - x


with open(os.path.join(HERE, "rotating_bar_elongation.csv"), "w") as out:
    out.write("# Bar spinning about one end: L = 1 m, rho = 7800 kg/m^3, E = 2e11 Pa, Omega = 1000 rad/s.\n")
    out.write("# linear: E u'' + rho Omega^2 x = 0 (code_aster V3.04.104, SDLL104, reference solution);\n")
    out.write("# softened: E u'' + rho Omega^2 (x + u) = 0 (spin softening), u(0) = 0, u'(L) = 0.\n")
    out.write("# Written by rotating_bar_elongation.py. set_number 1: the tip x = L, 2: the middle x = L / 2.\n")
    out.write("set_number,x_m,linear_ux_m,softened_ux_m\n")
    for number, x in ((1, L), (2, L / 2)):
        out.write(f"{number},{x:.17g},{linear(x):.17g},{softened(x):.17g}\n")
print(open(os.path.join(HERE, "rotating_bar_elongation.csv")).read())


def softened_stress(x):
    return E * (math.cos(K * x) / math.cos(K * L) - 1)


with open(os.path.join(HERE, "rotating_bar_stress.csv"), "w") as out:
    out.write("# Bar spinning about one end (see rotating_bar_elongation.csv): the axial stress of the steady state\n")
    out.write("# with spin softening, sigma = E u' = E (cos(k x) / cos(k L) - 1), k = Omega sqrt(rho / E) [Pa].\n")
    out.write("# Written by rotating_bar_elongation.py. Key: node id of the case's q4 64 x 2 mesh (mid-height nodes).\n")
    out.write("node,x_m,sxx\n")
    for node, x in ((66, 0.0), (98, L / 2)):
        out.write(f"{node},{x:.17g},{softened_stress(x):.17g}\n")
print(open(os.path.join(HERE, "rotating_bar_stress.csv")).read())
