"""Two runs' result tables are the same text, cell for cell, but for the wall times (columns named
"seconds"): every CSV of OLD is in NEW and no other. Usage: compare_tables.py OLD NEW"""
import csv
import pathlib
import sys


def cells(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    keep = [k for k, name in enumerate(rows[0]) if name != "seconds"] if rows else []
    return [[row[k] for k in keep if k < len(row)] for row in rows]


old, new = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
names = sorted(p.name for p in old.glob("*.csv"))
if names != sorted(p.name for p in new.glob("*.csv")):
    sys.exit(f"the tables differ: {names} against {sorted(p.name for p in new.glob('*.csv'))}")
for name in names:
    a, b = cells(old / name), cells(new / name)
    if a != b:
        where = next((k for k, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
        sys.exit(f"{name} differs at line {where + 1}: {a[where] if where < len(a) else None} "
                 f"against {b[where] if where < len(b) else None}")
print(f"{len(names)} tables the same")
