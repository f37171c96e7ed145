#!/usr/bin/env python3
"""Runs `bladebench run CASE --vtk` and reads every .vtu back with meshio (Debian's python3-meshio, a
reader independent of bladebench): each point array must equal its CSV column as the CSV prints it
(12 significant digits, the same rounding), the mode shapes mode_shapes.csv, the field data
frequency_hz frequencies.csv (a whole disk's: nodal_diameter_map.csv, its waves continuous across
every seam), and the cells the element count and VTK type of the mesh.

An analysis with no field over the mesh (expect mesh.vtu) must write the mesh alone and warn.

A forced response's operating deflection (ods=NODE:AXIS:FRF_COLUMN) equals the sweep at its peaks;
a harmonic balance's peak recovered on the mesh (hbm=NODE:AXIS:PEAKS_COLUMN) the peaks table's, and
its contacts' states over the period the shares of contact_states.csv.

Usage: check_vtk_output.py BLADEBENCH CASE WORK CELL_TYPE [expect files...] [ods=|hbm=NODE:AXIS:COLUMN]"""
import csv
import subprocess
import sys
from pathlib import Path

import meshio
import numpy as np


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def table(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {name: [row[k] for row in body] for k, name in enumerate(header)}


def same_as_csv(name, values, column):
    printed = ["%.12g" % v for v in values]
    # The CSV writes -0 as "-0"; both sides print through the same %.12g rounding.
    for k, (a, b) in enumerate(zip(printed, column)):
        if float(a) != float(b):
            fail(f"{name}: row {k + 1} is {a} in the .vtu, {b} in the CSV")
    if len(printed) != len(column):
        fail(f"{name}: {len(printed)} values in the .vtu, {len(column)} in the CSV")


def check_disk(vtu, diameter_map):
    """A whole-disk file: every family's wave continuous across the seams between sectors (coincident
    points of neighbouring copies move alike, to 1e-12 of the largest motion), its frequencies those
    of nodal_diameter_map.csv."""
    mesh = meshio.read(vtu)
    key = np.round(mesh.points / 1e-9).astype(np.int64)
    order = np.lexsort(key.T)
    same = np.all(key[order][1:] == key[order][:-1], axis=1)
    first, second = order[:-1][same], order[1:][same]
    if len(first) == 0:
        fail(f"{vtu.name}: no seam between sectors")
    waves = [name for name in mesh.point_data if name.startswith("family")]
    for name in waves:
        u = mesh.point_data[name]
        mismatch = np.abs(u[first] - u[second]).max() / np.abs(u).max()
        if not mismatch < 1e-12:
            fail(f"{vtu.name}: {name} jumps by {mismatch:.3g} of its largest motion across a seam")
    k = int(mesh.field_data["nodal_diameter"][0])
    row = [int(v) for v in diameter_map["nodal_diameter"]].index(k)
    columns = [c for c in diameter_map if c.startswith("f") and c.endswith("_hz")]
    for f, column in enumerate(columns):
        same_as_csv(f"{vtu.name} frequency {f + 1}", [mesh.field_data["frequency_hz"][f]], [diameter_map[column][row]])
    return len(waves)


def check_deflection(out, node, axis, column):
    """ods.vtu: at each peak, |U| at the response node equals the sweep's amplitude at that frequency
    (frf.csv, residual_flexibility off); one period of the first peak as 16 frames in a .pvd, frame 0
    = Re(U) and frame 4 (a quarter period) = -Im(U)."""
    mesh = meshio.read(out / "vtk" / "ods.vtu")
    row = list(mesh.point_data["node_id"]).index(node)
    d = "xyz".index(axis)
    sweep = table(out / "frf.csv")
    grid = [float(f) for f in sweep["frequency_hz"]]
    checked = 0
    for f, key in zip(mesh.field_data["frequency_hz"], mesh.field_data["peak"]):
        u = mesh.point_data[f"peak{int(key)}_re"][row, d] + 1j * mesh.point_data[f"peak{int(key)}_im"][row, d]
        same_as_csv(f"ods peak {int(key)} at {f} Hz", [abs(u)], [sweep[column][grid.index(f)]])
        checked += 1
    first = int(mesh.field_data["peak"][0])
    import xml.etree.ElementTree as ElementTree
    frames = [e.get("file") for e in ElementTree.parse(out / "vtk" / f"ods_peak{first}.pvd").getroot().iter("DataSet")]
    if len(frames) != 16:
        fail(f"ods_peak{first}.pvd lists {len(frames)} frames, expected 16")
    re, im = mesh.point_data[f"peak{first}_re"], mesh.point_data[f"peak{first}_im"]
    for k, expected in ((0, re), (4, -im)):
        u = meshio.read(out / "vtk" / frames[k]).point_data["displacement"]
        if not np.abs(u - expected).max() <= 1e-15 * np.abs(expected).max():
            fail(f"frame {k} of ods_peak{first}.pvd is not the deflection at its phase")
    return checked + 2


def check_hbm(out, node, axis, column):
    """hbm_peaks.vtu: the first harmonic of the first peak at the response node equals the peaks
    table's amplitude there; its period's frame 0 is the sum of its harmonics' cosine parts."""
    mesh = meshio.read(out / "vtk" / "hbm_peaks.vtu")
    row = list(mesh.point_data["node_id"]).index(node)
    d = "xyz".index(axis)
    u1 = mesh.point_data["fe1_peak1_h1_re"][row, d] + 1j * mesh.point_data["fe1_peak1_h1_im"][row, d]
    peaks = table(out / "peaks.csv")
    same_as_csv("hbm peak 1, harmonic 1", [abs(u1)], [peaks[column][0]])
    import xml.etree.ElementTree as ElementTree
    frames = [e.get("file") for e in ElementTree.parse(out / "vtk" / "hbm_fe1_peak1.pvd").getroot().iter("DataSet")]
    start = meshio.read(out / "vtk" / frames[0]).point_data["displacement"]
    h = int(mesh.field_data["harmonics"][0])
    expected = mesh.point_data["fe1_peak1_h0_re"] + sum(mesh.point_data[f"fe1_peak1_h{k}_re"] for k in range(1, h + 1))
    if not np.abs(start - expected).max() <= 1e-14 * np.abs(expected).max():
        fail("frame 0 of hbm_fe1_peak1.pvd is not the sum of the harmonics' cosine parts")
    # The contacts over the period: one frame per AFT sample, the share of stuck samples that of
    # contact_states.csv (its first row: level 1, peak 1, contact 1).
    frames = [e.get("file") for e in ElementTree.parse(out / "vtk" / "contacts_fe1_peak1.pvd").getroot().iter("DataSet")]
    states = [meshio.read(out / "vtk" / f).point_data["state"][0] for f in frames]
    stick = sum(1 for s in states if s == 0) / len(states)
    same_as_csv("contact 1 stick share over the period", [stick], [table(out / "contact_states.csv")["stick"][0]])
    return 3


def main():
    binary, case, work, cell_type = sys.argv[1:5]
    expected = [a for a in sys.argv[5:] if "=" not in a]
    deflection = [a[4:].split(":") for a in sys.argv[5:] if a.startswith("ods=")]
    balance = [a[4:].split(":") for a in sys.argv[5:] if a.startswith("hbm=")]
    out = Path(work)
    result = subprocess.run([binary, "run", case, "--vtk", "--no-plots", "--no-cache", "--out", str(out)],
                            capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"bladebench run --vtk exited {result.returncode}:\n{result.stderr}")
    for name in expected:
        if not (out / "vtk" / name).is_file():
            fail(f"vtk/{name} was not written")
    checked = 0
    if "mesh.vtu" in expected:
        # No field over the mesh: the mesh alone, and a warning naming it.
        if "wrote the mesh alone, vtk/mesh.vtu" not in result.stderr:
            fail(f"no warning naming vtk/mesh.vtu:\n{result.stderr}")
        mesh = meshio.read(out / "vtk" / "mesh.vtu")
        ids = mesh.cell_data["element_id"][0]
        if sorted(int(i) for i in ids) != list(range(1, len(ids) + 1)) or len(mesh.points) == 0:
            fail(f"mesh.vtu: element ids {ids[:5]}..., {len(mesh.points)} points")
        checked += 1
    for vtu in sorted((out / "vtk").glob("*.vtu")):
        mesh = meshio.read(vtu)
        if [c.type for c in mesh.cells] != [cell_type]:
            fail(f"{vtu.name}: cell blocks {[c.type for c in mesh.cells]}, expected one of {cell_type}")
        ids = mesh.point_data["node_id"]
        for name, values in mesh.point_data.items():
            if name == "node_id" or "." not in name:
                continue
            table_name, column = name.split(".", 1)
            t = table(out / f"{table_name}.csv")
            if [int(v) for v in t["node"]] != [int(v) for v in ids]:
                fail(f"{vtu.name}: node order differs from {table_name}.csv")
            same_as_csv(name, values, t[column])
            checked += 1
        if vtu.name == "modes.vtu":
            shapes = table(out / "mode_shapes.csv")
            modes = sorted(int(k.split("_")[1]) for k in mesh.point_data if k.startswith("mode_"))
            for k in modes:
                vectors = mesh.point_data[f"mode_{k}"]
                for d, axis in enumerate("xyz"[: vectors.shape[1]]):
                    key = f"mode{k}_u{axis}"
                    if key in shapes:
                        same_as_csv(f"mode_{k}.{axis}", vectors[:, d], shapes[key])
                        checked += 1
            freqs = table(out / "frequencies.csv")
            same_as_csv("frequency_hz", mesh.field_data["frequency_hz"], freqs["frequency_hz"])
            checked += 1
    for node, axis, column in deflection:
        checked += check_deflection(out, int(node), axis, column)
    for node, axis, column in balance:
        checked += check_hbm(out, int(node), axis, column)
    for vtu in sorted((out / "vtk").glob("disk_nd*.vtu")):
        checked += check_disk(vtu, table(out / "nodal_diameter_map.csv"))
    if checked == 0:
        fail("no array was compared")
    print(f"{checked} arrays equal their CSV columns")


if __name__ == "__main__":
    main()
