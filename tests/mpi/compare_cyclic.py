"""Two runs of a cyclic_modal case agree: every family's eigenvalue (2 pi f)^2 in nodal_diameter_map.csv
and campbell.csv (when written) to a relative TOL, and each nodal diameter's Sturm count in
cyclic_completeness.csv exactly. Usage: compare_cyclic.py OLD_DIR NEW_DIR TOL"""
import csv
import math
import os
import sys


def rows(folder, table):
    path = os.path.join(folder, table + ".csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


old_dir, new_dir, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
worst = 0.0
for table in ("nodal_diameter_map", "campbell"):
    old, new = rows(old_dir, table), rows(new_dir, table)
    if old is None and new is None:
        continue
    if old is None or new is None or len(old) != len(new):
        sys.exit(f"{table}: the runs wrote different tables")
    for a, b in zip(old, new):
        for key in a:
            if not (key.startswith("f") and key.endswith("_hz")):
                continue
            x, y = (2 * math.pi * float(a[key])) ** 2, (2 * math.pi * float(b[key])) ** 2
            change = abs(x - y) / abs(x)
            worst = max(worst, change)
            if change > tol:
                sys.exit(f"{table} {key} (nodal diameter {a['nodal_diameter']}): eigenvalue {x:.12g} -> {y:.12g}, "
                         f"relative change {change:.2e} > {tol:g}")
old, new = rows(old_dir, "cyclic_completeness"), rows(new_dir, "cyclic_completeness")
for a, b in zip(old, new):
    if a["sturm_count"] != b["sturm_count"]:
        sys.exit(f"nodal diameter {a['nodal_diameter']}: Sturm count {a['sturm_count']} -> {b['sturm_count']}")
print(f"{len(old)} nodal diameters: same counts; largest relative change of an eigenvalue {worst:.2e}")
