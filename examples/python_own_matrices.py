"""Your own matrices in Python: a Harwell-Boeing export read, a friction contact added, the response swept.

An Ansys HBMAT export (stiffness and mass in Harwell-Boeing files, the DOF map in a .mapping file)
of a fixed-free chain of 8 masses (cases/verification/data/hb_chain/, written by
references/verification/harwell_boeing_chain.py) is read with bladebench.read_reduced_model; a
Jenkins contact to the ground at the free end (DOF 108.x) and a force there make it a friction
problem, solved by harmonic balance over the first mode. Below the slip force the contact sticks
(a spring kt in parallel); at 40 N against a 60 N slip force it slips near resonance, so the peak
lies between the free and the stuck chain's first frequency. Exit 0 when it does.
PYTHONPATH=build/python python3 examples/python_own_matrices.py
"""
import pathlib
import sys

import numpy as np

import bladebench

sidecar = pathlib.Path(__file__).resolve().parents[1] / "cases/verification/data/hb_chain/chain.toml"
rom = bladebench.read_reduced_model(str(sidecar))
K, M, dofs = rom["stiffness"], rom["mass"], rom["dofs"]
tip = dofs.index("108.x")
kt = 2.0e6  # [N/m] the contact's stick stiffness


def first_frequency(stiffness):
    return np.sqrt(np.linalg.eigvals(np.linalg.solve(M, stiffness)).real.min()) / (2 * np.pi)


stuck = K.copy()
stuck[tip, tip] += kt
free_hz, stuck_hz = first_frequency(K), first_frequency(stuck)
a_t = np.zeros(len(dofs))
a_t[tip] = 1.0
force = np.zeros(len(dofs), dtype=complex)
force[tip] = 40.0  # [N]
C = 2 * 0.005 * 2 * np.pi * free_hz * M  # light mass-proportional damping
frequencies = np.arange(0.8 * free_hz, 1.2 * stuck_hz, 0.25)
sweep = bladebench.hbm_sweep(mass=M, stiffness=K, damping=C, force=force, frequencies_hz=frequencies,
                             contacts=[{"tangential": a_t, "kt": kt, "mu": 0.3, "n0": 200.0}], harmonics=3)
amplitude = sweep["amplitude"][:, tip]
peak = frequencies[np.nanargmax(amplitude)]
print(f"{len(dofs)} DOFs from {sidecar.name}; first mode free {free_hz:.2f} Hz, stuck {stuck_hz:.2f} Hz")
print(f"friction peak at {peak:.2f} Hz, {np.nanmax(amplitude):.4e} m; {int(sweep['converged'].sum())} of "
      f"{len(frequencies)} frequencies converged")
sys.exit(0 if sweep["converged"].all() and free_hz < peak < stuck_hz else 1)
