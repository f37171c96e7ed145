"""A friction oscillator's frequency response from Python, as examples/friction_oscillator_hbm.cpp.

A mass on a spring rubbing on the ground through a Jenkins contact (a spring kt in series with a
Coulomb slider, slip force mu n0), driven by a harmonic force: below the slip force it is linear
with stiffness k + kt; at 5 N against a 9 N slip force it slips over part of each cycle near
resonance, so its peak lies between the free (k) and the stuck (k + kt) resonances. Exit 0 when it
does. Run with the built module on the path: PYTHONPATH=build/python python3 examples/python_friction_sweep.py
"""
import math
import sys

import numpy as np

import bladebench

mass, k, c = 1.0, 1.0e6, 10.0  # [kg, N/m, N s/m]: 159.2 Hz free, 0.5 % damping
frequencies = np.arange(140.0, 241.0, 1.0)  # [Hz]
sweep = bladebench.hbm_sweep(
    mass=np.array([[mass]]), stiffness=np.array([[k]]), damping=np.array([[c]]),
    force=np.array([5.0 + 0j]),  # [N], complex amplitude of the first harmonic
    frequencies_hz=frequencies,
    contacts=[{"tangential": np.array([1.0]), "kn": 1.0e6, "kt": 1.0e6, "mu": 0.3, "n0": 30.0}],
    harmonics=5)

amplitude = sweep["amplitude"][:, 0]  # first harmonic of the one DOF [m]
for f, a in zip(frequencies[::10], amplitude[::10]):
    print(f"{f:6.1f} Hz  {a:.4e} m")
peak = frequencies[np.argmax(amplitude)]
free, stuck = math.sqrt(k / mass) / (2 * math.pi), math.sqrt((k + 1.0e6) / mass) / (2 * math.pi)
print(f"peak: {peak:.1f} Hz, {amplitude.max():.4e} m (free {free:.1f} Hz, stuck {stuck:.1f} Hz)")
sys.exit(0 if sweep["converged"].all() and free < peak < stuck else 1)
