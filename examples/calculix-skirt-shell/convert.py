#!/usr/bin/python3
"""Converts the unit-load steps of skirt.inp (CalculiX's skirt.dat) into FilmDyn's compliance
files:

  skirt_compliance.mtx        Matrix Market, array real symmetric: C[a, b] [m/N], the inward
                              radial displacement (the film's opening) of outer-surface node a
                              under a unit inward radial force on outer-surface node b
  skirt_compliance.nodes.csv  x[m] = R alpha (alpha the node's angle from the thrust axis,
                              0 <= alpha < 2 pi), y[m] = z (from the skirt top, 0 ... L)

Step b of skirt.dat loads node b of the outer surface (make_deck.py's order: rows of z from the
skirt's top z = 0 to its bottom z = L, alpha increasing along each row; the belt section above
z = 0 is structure only, neither loaded nor printed); its printed displacements, projected on
each node's inward radial direction, are column b. The FE solution is symmetric to round-off
(Maxwell-Betti): the script prints the asymmetry it removes, then checks that the matrix is
positive definite.
"""
import math

import numpy as np

R = 36.5e-3  # the skirt's outer radius [m] (make_deck.py)


def read_nodes(path):
    coords, on = {}, False
    for line in open(path):
        s = line.strip()
        if s.startswith("*"):
            on = s.upper() == "*NODE"
            continue
        if on and s:
            f = [t.strip() for t in s.split(",")]
            coords[int(f[0])] = (float(f[1]), float(f[2]), float(f[3]))
    return coords


def read_steps(path):
    """The displacement blocks of skirt.dat, each {node: (ux, uy, uz)}, in step order."""
    blocks, block = [], None
    for line in open(path):
        if line.strip().startswith("displacements"):
            block = {}
            blocks.append(block)
            continue
        f = line.split()
        if block is not None and len(f) == 4:
            block[int(f[0])] = tuple(float(v) for v in f[1:])
    return blocks


def main():
    coords = read_nodes("skirt.inp")
    blocks = read_steps("skirt.dat")
    nodes = list(blocks[0].keys())  # the printed order = the loaded order (set SURFACE)
    if len(blocks) != len(nodes):
        raise SystemExit(f"skirt.dat: {len(blocks)} steps for {len(nodes)} surface nodes")
    angle = {n: math.atan2(coords[n][1], coords[n][0]) for n in nodes}
    inward = {n: (-math.cos(angle[n]), -math.sin(angle[n])) for n in nodes}
    m = len(nodes)
    c = np.zeros((m, m))
    for b, block in enumerate(blocks):
        for a, n in enumerate(nodes):
            ux, uy, _ = block[n]
            c[a, b] = ux * inward[n][0] + uy * inward[n][1]
    asym = np.abs(c - c.T).max() / np.abs(c).max()
    c = 0.5 * (c + c.T)
    try:
        np.linalg.cholesky(c)
    except np.linalg.LinAlgError:
        raise SystemExit("the compliance is not positive definite: is the skirt held?")

    # The film's coordinates: alpha on the periodic grid 2 pi i / N_THETA (never 2 pi itself).
    n_theta = len({round(angle[n], 9) for n in nodes})
    step = 2.0 * math.pi / n_theta
    xy = []
    for n in nodes:
        i = round((angle[n] % (2.0 * math.pi)) / step) % n_theta
        xy.append((R * step * i, coords[n][2]))
    if xy != sorted(xy, key=lambda p: (p[1], p[0])):
        raise SystemExit("skirt.dat: the surface nodes are not in rows of z, alpha increasing")

    with open("skirt_compliance.mtx", "w") as f:
        f.write("%%MatrixMarket matrix array real symmetric\n")
        f.write("% inward radial compliance [m/N] of the outer (film) surface of the piston skirt\n")
        f.write("% of examples/calculix-skirt-shell: entry (i, j) is node i's inward displacement\n")
        f.write("% under a unit inward force on node j (CalculiX 2.20 unit-load steps, convert.py)\n")
        f.write(f"{m} {m}\n")
        for j in range(m):
            for i in range(j, m):
                f.write(f"{c[i, j]:.9e}\n")
    with open("skirt_compliance.nodes.csv", "w") as f:
        f.write("x[m],y[m]\n")
        for x, y in xy:
            f.write(f"{x:.12e},{y:.12e}\n")
    print(f"{m} surface nodes ({n_theta} around x {m // n_theta} along); asymmetry removed "
          f"{asym:.2g} of the largest entry; positive definite; diagonal "
          f"{c.diagonal().min():.4g} .. {c.diagonal().max():.4g} m/N")


if __name__ == "__main__":
    main()
