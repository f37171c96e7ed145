#!/usr/bin/env python3
"""First flapwise natural frequency of a rotating uniform cantilever (hub radius 0), published
dimensionless values converted to Hz for the beam of cases/verification/rotating_cantilever_modal.toml.
Writes rotating_cantilever_flapwise.csv beside this script. Run: python3 references/verification/rotating_cantilever_flapwise.py

Dimensionless speed lambda = Omega T and frequency omega_bar = omega T with T = sqrt(rho A L^4 / E I)
(Euler-Bernoulli, flapwise bending out of the plane of rotation; the centrifugal tension stiffens
it, Southwell). Values: lambda = 0: 3.5160 (the clamped-free beam, 1.8751^2; Thomson, Theory of
Vibration with Applications, App. D); lambda = 2..10: Hamza-Cherif & Houmat, "Free vibration of
rotating beams", ICAS 2004, Table 2 (the Wright et al. 1982 / Hodges & Rutkowski 1981 values).
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
# The beam of the case: L = 1 m, 0.08 m wide in the plane of rotation (y), 0.02 m thick (z, flapwise).
L, B, H, RHO, E = 1.0, 0.08, 0.02, 7800.0, 2.0e11
A, I_FLAP = B * H, B * H ** 3 / 12.0
T = math.sqrt(RHO * A * L ** 4 / (E * I_FLAP))
PUBLISHED = [(0.0, 3.5160), (2.0, 4.1373), (4.0, 5.5850), (6.0, 7.3603), (8.0, 9.2568), (10.0, 11.2023)]
MODES = 4  # modes per speed in the case's Campbell table: point = speed index * MODES + mode

with open(os.path.join(HERE, "rotating_cantilever_flapwise.csv"), "w") as out:
    out.write("# First flapwise frequency of a rotating cantilever, omega_bar(lambda) published (see the script),\n")
    out.write(f"# in Hz for L = {L} m, b = {B} m, h = {H} m, rho = {RHO}, E = {E}: T = sqrt(rho A L^4 / E I) = {T:.12g} s.\n")
    out.write("# point = the case's campbell.csv row of mode 1 at each speed. Written by rotating_cantilever_flapwise.py.\n")
    out.write("point,lambda,omega_rad_s,omega_bar,frequency_hz\n")
    for i, (lam, wbar) in enumerate(PUBLISHED):
        out.write(f"{i * MODES + 1},{lam},{lam / T:.12g},{wbar},{wbar / T / (2 * math.pi):.12g}\n")
    print("speeds_rad_s =", [round(lam / T, 9) for lam, _ in PUBLISHED])
print(open(os.path.join(HERE, "rotating_cantilever_flapwise.csv")).read())
