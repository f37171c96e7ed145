#!/usr/bin/env python3
"""Writes a fixed-free spring-mass chain as an Ansys-style HBMAT export, for
cases/verification/harwell_boeing_chain.toml, and its closed-form natural frequencies.

Model (SI): n = 8 equal masses m = 0.5 kg in a line along x, mass j joined to mass j - 1 by a spring
k = 2e6 N/m, mass 1 to the ground; mass 8 free. Nodes are numbered 101..108 as an FE export would.
K = k tridiag(-1, 2, -1) with K[n, n] = k, M = m I. Closed form (e.g. Gantmakher & Krein; any text on
the fixed-free lumped chain): w_j = 2 sqrt(k / m) sin((2 j - 1) pi / (2 (2 n + 1))), j = 1..n.

Files written to cases/verification/data/hb_chain/ (Harwell-Boeing after Duff, Grimes & Lewis 1992):
  chain.K.rsa   K as RSA, the lower triangle by columns, values 17 digits in (3E26.17)
  chain.M.rua   M as RUA, every entry (the diagonal), (4D20.12): Fortran's D exponent
  chain.mapping the DOF map as Ansys HBMAT writes it ("Matrix Eqn  Node  DOF")
and references/verification/harwell_boeing_chain_modes.csv (mode, frequency_hz), and
harwell_boeing_chain_receptance.csv: the chain's response to 1 N at its free end (node 108, x) with
modal damping 0.01 on every mode, C = M Phi diag(2 zeta w_r) Phi^T M (numpy's eigh of the pencil),
at 40-120 Hz every 5 Hz, the amplitudes at nodes 108 and 101 (cases/verification/
harwell_boeing_chain_hbm.toml: the harmonic balance of the same export with a frictionless contact).
"""
import math
from pathlib import Path

import numpy as np

N, MASS, K_SPRING = 8, 0.5, 2.0e6
FIRST_NODE = 101

here = Path(__file__).resolve().parent
data = here.parent.parent / "cases" / "verification" / "data" / "hb_chain"


def chain():
    k = [[0.0] * N for _ in range(N)]
    for j in range(N):
        k[j][j] = 2.0 * K_SPRING if j < N - 1 else K_SPRING
        if j > 0:
            k[j][j - 1] = k[j - 1][j] = -K_SPRING
    m = [[MASS if i == j else 0.0 for j in range(N)] for i in range(N)]
    return k, m


def cards(items, per_line, width, fmt):
    lines = []
    for start in range(0, len(items), per_line):
        lines.append("".join(fmt(v).rjust(width) for v in items[start:start + per_line]))
    return lines


def write_hb(path, a, kind, title, key, val_per_line, val_width, val_fmt, val_format_text):
    """Column-compressed storage of `a`: RSA keeps row >= column, RUA every nonzero."""
    ptr, ind, val = [1], [], []
    for j in range(N):
        for i in range(N):
            if a[i][j] != 0.0 and (kind == "RUA" or i >= j):
                ind.append(i + 1)
                val.append(a[i][j])
        ptr.append(len(ind) + 1)
    ptr_lines = cards(ptr, 10, 8, str)
    ind_lines = cards(ind, 10, 8, str)
    val_lines = cards(val, val_per_line, val_width, val_fmt)
    total = len(ptr_lines) + len(ind_lines) + len(val_lines)
    header = [
        f"{title:<72}{key:<8}",
        f"{total:14d}{len(ptr_lines):14d}{len(ind_lines):14d}{len(val_lines):14d}{0:14d}",
        f"{kind:<3}{'':11}{N:14d}{N:14d}{len(val):14d}{0:14d}",
        f"{'(10I8)':<16}{'(10I8)':<16}{val_format_text:<20}{'':<20}",
    ]
    path.write_text("\n".join(header + ptr_lines + ind_lines + val_lines) + "\n")


def main():
    data.mkdir(parents=True, exist_ok=True)
    k, m = chain()
    write_hb(data / "chain.K.rsa", k, "RSA", "fixed-free chain, stiffness [N/m]", "CHAINK", 3, 26,
             lambda v: format(v, ".17E"), "(3E26.17)")
    write_hb(data / "chain.M.rua", m, "RUA", "fixed-free chain, mass [kg]", "CHAINM", 4, 20,
             lambda v: format(v, ".12E").replace("E", "D"), "(4D20.12)")
    rows = [" Matrix Eqn   Node   DOF"]
    rows += [f"{j + 1:11d}{FIRST_NODE + j:7d}    UX" for j in range(N)]
    (data / "chain.mapping").write_text("\n".join(rows) + "\n")
    out = ["# Closed-form natural frequencies of the fixed-free chain of harwell_boeing_chain.py:",
           "# w_j = 2 sqrt(k/m) sin((2j-1) pi / (2 (2n+1))), n = 8, k = 2e6 N/m, m = 0.5 kg",
           "mode,frequency_hz"]
    for j in range(1, N + 1):
        w = 2.0 * math.sqrt(K_SPRING / MASS) * math.sin((2 * j - 1) * math.pi / (2 * (2 * N + 1)))
        out.append(f"{j},{w / (2 * math.pi):.15g}")
    (here / "harwell_boeing_chain_modes.csv").write_text("\n".join(out) + "\n")

    kk, mm = np.array(k), np.array(m)
    lam, phi = np.linalg.eigh(np.linalg.solve(np.linalg.cholesky(mm), kk) @ np.linalg.inv(np.linalg.cholesky(mm)).T)
    phi = np.linalg.inv(np.linalg.cholesky(mm)).T @ phi  # mass-normalized
    w = np.sqrt(lam)
    c = mm @ phi @ np.diag(2 * 0.01 * w) @ phi.T @ mm
    f = np.zeros(N)
    f[N - 1] = 1.0
    rows = ["# Receptance of the chain of harwell_boeing_chain.py at 1 N on node 108 x, modal damping 0.01",
            "# (C = M Phi diag(2 zeta w) Phi^T M); amplitudes [m] at nodes 108 and 101 (x)",
            "point,frequency_hz,tip_amp_m,root_amp_m"]
    for i, hz in enumerate(np.arange(40.0, 120.0 + 1e-9, 5.0)):
        om = 2 * math.pi * hz
        u = np.linalg.solve(kk - om**2 * mm + 1j * om * c, f)
        rows.append(f"{i + 1},{hz:g},{abs(u[N - 1]):.15g},{abs(u[0]):.15g}")
    (here / "harwell_boeing_chain_receptance.csv").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
