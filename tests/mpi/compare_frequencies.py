"""Two runs' frequencies.csv agree to a relative TOL (default 1e-9) in the eigenvalue (2 pi f)^2; an
eigenvalue below 1e-8 of the largest (a rigid-body mode, as the modal report counts them) is
compared against that scale, since its value is rounding. Usage: compare_frequencies.py OLD NEW [TOL]"""
import csv
import math
import sys


def eigenvalues(path):
    with open(path, newline="") as f:
        return [(2 * math.pi * float(row["frequency_hz"])) ** 2 for row in csv.DictReader(f)]


old, new = eigenvalues(sys.argv[1]), eigenvalues(sys.argv[2])
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-9
if len(old) != len(new):
    sys.exit(f"{len(old)} modes in {sys.argv[1]}, {len(new)} in {sys.argv[2]}")
floor = 1e-8 * max(old + new)
worst = 0.0
for k, (a, b) in enumerate(zip(old, new), start=1):
    change = abs(a - b) / max(abs(a), floor)
    worst = max(worst, change)
    if change > tol:
        sys.exit(f"mode {k}: eigenvalue {a:.12g} -> {b:.12g} rad^2/s^2, relative change {change:.2e} > {tol:g}")
print(f"{len(old)} modes agree; largest relative change of an eigenvalue {worst:.2e}")
