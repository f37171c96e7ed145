#!/usr/bin/env python3
"""Meshes of the NAFEMS LE1 elliptic membrane (quarter model) as Gmsh MSH 4.1 ASCII files.

The membrane lies between the confocal ellipses (x/2)^2 + y^2 = 1 and (x/3.25)^2 + (y/2.75)^2 = 1
(both have foci at x = +-sqrt(3)). The mesh follows elliptic coordinates,
x = c cosh(mu) cos(nu), y = c sinh(mu) sin(nu), c = sqrt(3): lines of constant mu are the
confocal ellipses (the inner and outer boundaries among them), lines of constant nu the confocal
hyperbolas, so the mesh is orthogonal and every boundary node lies exactly on its ellipse. Elements
are uniform in (mu, nu): n_nu around the quarter, n_mu across. These are not the NAFEMS coarse and
fine meshes (whose node coordinates the public sources do not give); the cases state their own
mesh sensitivity.

Physical groups: "membrane" (the elements), "outer" and "inner" (every node on each ellipse, as
point elements). The solid version is the 2D mesh extruded to z in [0, t/2] with one hex20 layer
(the half-thickness of a symmetric plate: the cases hold z = 0). Units: m.

Point D = (2, 0) is node 1 of every mesh (at z = 0 in the solid): the cases' reference names it so.

Run from this folder: python3 make_le1_meshes.py (writes the three meshes the cases read, output
deterministic); python3 make_le1_meshes.py --all also writes the refinement sequences of the cases'
descriptions (6 x 2 to 384 x 128 plane, 6 x 2 to 48 x 16 solid), which are not committed.
"""
import sys
import math

C = math.sqrt(3.0)
MU_IN = math.acosh(2.0 / C)     # inner ellipse: semi-axes 2, 1
MU_OUT = math.acosh(3.25 / C)   # outer ellipse: semi-axes 3.25, 2.75
HALF_T = 0.05                   # half of the 0.1 m thickness


def point(mu, nu):
    return C * math.cosh(mu) * math.cos(nu), C * math.sinh(mu) * math.sin(nu)


def lattice(n_nu, n_mu, order):
    """Points (i along mu, j along nu) of a lattice with `order` points per element edge minus 1."""
    pts = {}
    for i in range(order * n_mu + 1):
        for j in range(order * n_nu + 1):
            mu = MU_IN + (MU_OUT - MU_IN) * i / (order * n_mu)
            nu = 0.5 * math.pi * j / (order * n_nu)
            x, y = point(mu, nu)
            if j == order * n_nu:
                x = 0.0          # on the y axis exactly
            if j == 0:
                y = 0.0          # on the x axis exactly
            pts[(i, j)] = (x, y)
    return pts


def fmt(v):
    return repr(float(v))


def write_msh(path, nodes, elements, element_type, dim, groups):
    """nodes: list of (tag, x, y, z); elements: list of node-tag lists; groups: {name: [node tags]}."""
    names = list(groups)
    lines = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(names) + 1)]
    for k, name in enumerate(names):
        lines.append('0 %d "%s"' % (k + 1, name))
    lines.append('%d %d "membrane"' % (dim, len(names) + 1))
    lines.append("$EndPhysicalNames")
    lines.append("$Entities")
    counts = [len(names), 0, 0, 0]
    counts[dim] += 1
    lines.append(" ".join(str(c) for c in counts))
    for k in range(len(names)):
        lines.append("%d 0 0 0 1 %d" % (k + 1, k + 1))
    xs = [n[1] for n in nodes]
    ys = [n[2] for n in nodes]
    zs = [n[3] for n in nodes]
    lines.append("1 %s %s %s %s %s %s 1 %d 0" % (fmt(min(xs)), fmt(min(ys)), fmt(min(zs)), fmt(max(xs)), fmt(max(ys)),
                                                 fmt(max(zs)), len(names) + 1))
    lines.append("$EndEntities")
    lines.append("$Nodes")
    lines.append("1 %d 1 %d" % (len(nodes), len(nodes)))
    lines.append("%d 1 0 %d" % (dim, len(nodes)))
    lines.extend(str(n[0]) for n in nodes)
    lines.extend("%s %s %s" % (fmt(n[1]), fmt(n[2]), fmt(n[3])) for n in nodes)
    lines.append("$EndNodes")
    n_points = sum(len(g) for g in groups.values())
    lines.append("$Elements")
    lines.append("%d %d 1 %d" % (len(names) + 1, n_points + len(elements), n_points + len(elements)))
    tag = 1
    for k, name in enumerate(names):
        lines.append("0 %d 15 %d" % (k + 1, len(groups[name])))
        for n in groups[name]:
            lines.append("%d %d" % (tag, n))
            tag += 1
    lines.append("%d 1 %d %d" % (dim, element_type, len(elements)))
    for e in elements:
        lines.append("%d %s" % (tag, " ".join(str(n) for n in e)))
        tag += 1
    lines.append("$EndElements")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def plane(n_nu, n_mu, triangles):
    pts = lattice(n_nu, n_mu, 1)
    tags = {}
    nodes = []
    for key in sorted(pts, key=lambda k: (k[1], k[0])):
        tags[key] = len(nodes) + 1
        nodes.append((tags[key], pts[key][0], pts[key][1], 0.0))
    elements = []
    for j in range(n_nu):
        for i in range(n_mu):
            # (mu, nu) is right-handed in (x, y): these corners run counterclockwise.
            q = [tags[(i, j)], tags[(i + 1, j)], tags[(i + 1, j + 1)], tags[(i, j + 1)]]
            if triangles:
                # Diagonals alternate in a checkerboard: no preferred direction.
                if (i + j) % 2 == 0:
                    elements += [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
                else:
                    elements += [[q[0], q[1], q[3]], [q[1], q[2], q[3]]]
            else:
                elements.append(q)
    groups = {"inner": [tags[(0, j)] for j in range(n_nu + 1)], "outer": [tags[(n_mu, j)] for j in range(n_nu + 1)]}
    kind = "cst" if triangles else "q4"
    write_msh("le1_%s_%dx%d.msh" % (kind, n_nu, n_mu), nodes, elements, 2 if triangles else 3, 2, groups)


# Gmsh's 20-node hexahedron: corners 0-7, then the edges 0-1, 0-3, 0-4, 1-2, 1-5, 2-3, 2-6, 3-7,
# 4-5, 4-7, 5-6, 6-7 (Gmsh reference manual, "Node ordering").
GMSH_HEX20_EDGES = [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 7), (5, 6), (6, 7)]


def solid(n_nu, n_mu):
    pts = lattice(n_nu, n_mu, 2)  # the mid-edge nodes sit at the mid (mu, nu) of their edge: on the curves
    tags = {}
    nodes = []

    def tag(i, j, k):  # k = 0, 1, 2: z = 0, t/4, t/2
        key = (i, j, k)
        if key not in tags:
            tags[key] = len(nodes) + 1
            x, y = pts[(i, j)]
            nodes.append((tags[key], x, y, HALF_T * k / 2.0))
        return tags[key]

    elements = []
    for j in range(n_nu):
        for i in range(n_mu):
            corner = [(2 * i, 2 * j), (2 * i + 2, 2 * j), (2 * i + 2, 2 * j + 2), (2 * i, 2 * j + 2)]
            lattice8 = [(c[0], c[1], 0) for c in corner] + [(c[0], c[1], 2) for c in corner]
            e = [tag(*p) for p in lattice8]
            for a, b in GMSH_HEX20_EDGES:
                pa, pb = lattice8[a], lattice8[b]
                e.append(tag((pa[0] + pb[0]) // 2, (pa[1] + pb[1]) // 2, (pa[2] + pb[2]) // 2))
            elements.append(e)
    groups = {"inner": sorted(t for (i, j, k), t in tags.items() if i == 0),
              "outer": sorted(t for (i, j, k), t in tags.items() if i == 2 * n_mu)}
    write_msh("le1_hex20_%dx%d.msh" % (n_nu, n_mu), nodes, elements, 17, 3, groups)


if __name__ == "__main__":
    if "--all" in sys.argv[1:]:
        for n_nu, n_mu in [(6, 2), (12, 4), (24, 8), (48, 16), (96, 32), (192, 64), (384, 128)]:
            plane(n_nu, n_mu, False)
            plane(n_nu, n_mu, True)
        for n_nu, n_mu in [(6, 2), (12, 4), (24, 8), (48, 16)]:
            solid(n_nu, n_mu)
    else:
        plane(96, 32, False)
        plane(96, 32, True)
        solid(24, 8)
