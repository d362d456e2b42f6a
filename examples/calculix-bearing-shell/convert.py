#!/usr/bin/python3
"""Converts the unit-load steps of shell.inp (CalculiX's shell.dat) into FilmDyn's compliance
files:

  shell_compliance.mtx        Matrix Market, array real symmetric: C[a, b] [m/N], the radial
                              (film-opening) displacement of surface node a under a unit outward
                              radial force on surface node b
  shell_compliance.nodes.csv  x[m] = R psi (psi the node's angle from the x axis), y[m] = z

Step b of shell.dat loads node b of the inner surface (make_deck.py's order); its printed
displacements, projected on each node's outward radial direction, are column b. The FE solution
is symmetric to round-off (Maxwell-Betti); the script prints the asymmetry it removes.
"""
import math

import numpy as np

R = 15.0e-3  # the shell's inner radius [m] (make_deck.py)


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
    """The displacement blocks of shell.dat, each {node: (ux, uy, uz)}, in step order."""
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
    coords = read_nodes("shell.inp")
    blocks = read_steps("shell.dat")
    nodes = list(blocks[0].keys())  # the printed order = the loaded order (set INNER)
    if len(blocks) != len(nodes):
        raise SystemExit(f"shell.dat: {len(blocks)} steps for {len(nodes)} surface nodes")
    radial = {n: (math.cos(math.atan2(coords[n][1], coords[n][0])),
                  math.sin(math.atan2(coords[n][1], coords[n][0]))) for n in nodes}
    m = len(nodes)
    c = np.zeros((m, m))
    for b, block in enumerate(blocks):
        for a, n in enumerate(nodes):
            ux, uy, _ = block[n]
            c[a, b] = ux * radial[n][0] + uy * radial[n][1]
    asym = np.abs(c - c.T).max() / np.abs(c).max()
    c = 0.5 * (c + c.T)
    with open("shell_compliance.mtx", "w") as f:
        f.write("%%MatrixMarket matrix array real symmetric\n")
        f.write("% radial compliance [m/N] of the inner surface of the bearing shell of\n")
        f.write("% examples/calculix-bearing-shell (CalculiX 2.20 unit-load steps, convert.py)\n")
        f.write(f"{m} {m}\n")
        for j in range(m):
            for i in range(j, m):
                f.write(f"{c[i, j]:.9e}\n")
    with open("shell_compliance.nodes.csv", "w") as f:
        f.write("x[m],y[m]\n")
        for n in nodes:
            x, y, z = coords[n]
            f.write(f"{R * (math.atan2(y, x) % (2.0 * math.pi)):.12e},{z:.12e}\n")
    print(f"{m} surface nodes; asymmetry removed {asym:.2g} of the largest entry; diagonal "
          f"{c.diagonal().min():.4g} .. {c.diagonal().max():.4g} m/N")


if __name__ == "__main__":
    main()
