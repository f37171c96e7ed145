"""Calibrating a friction contact from Python: bladebench.calibrate on a rig's hysteresis loop.

cases/verification/jenkins_loop_identify.toml holds a loop measured (here: synthesized with noise
and two outliers) on a contact rig at kt = 5e7 N/m, mu = 0.5, kn = 1e8 N/m, and a Jenkins contact
with variable normal load started 4x, 1.6x and 5x away. The fit returns the identified values,
their covariance, every start, the fitted points and the predicted loop. Exit 0 when each truth
lies within 4 standard deviations of its estimate. Run with the built module on the path:
PYTHONPATH=build/python python3 examples/python_calibration.py
"""
import pathlib
import sys

import numpy as np

import bladebench

case = pathlib.Path(__file__).resolve().parents[1] / "cases/verification/jenkins_loop_identify.toml"
fit = bladebench.calibrate(str(case))
truth = {"analysis.contact.kt": 5.0e7, "analysis.contact.mu": 0.5, "analysis.contact.kn": 1.0e8}
ok = fit["converged"]
for name, value, sigma in zip(fit["parameters"], fit["values"], fit["std_devs"]):
    z = (value - truth[name]) / sigma
    ok = ok and abs(z) < 4
    print(f"{name:22s} {value:.5g} +- {sigma:.2g}  (truth {truth[name]:.5g}, {z:+.2f} sigma)")
print("correlation:\n", np.array2string(fit["correlation"], precision=3))
loop = fit["curves"]["hysteresis"]  # the predicted loop at the identified values (a bladebench.Table)
print(f"{len(fit['starts'])} starts, cost {fit['initial_cost']:.4g} -> {fit['final_cost']:.4g}; "
      f"predicted loop: {loop.shape[0]} points, columns {', '.join(loop.dtype.names[:3])}, ...")
for warning in fit["warnings"]:
    print("warning:", warning)
sys.exit(0 if ok else 1)
