#!/usr/bin/python3
"""Writes shell.inp: a CalculiX deck of a big-end bearing shell with one static step per node of
its inner surface, each a unit radial force (1 N, outward: the film pushing the shell away from
the journal) on that node, printing every inner-surface node's displacement (shell.dat). Column b
of the surface's compliance is the radial displacement of every node in step b (convert.py).

The shell: inner radius R = 15 mm (the default case's bearing), thickness T = 1.5 mm, width
L = 22 mm, an Al-Sn alloy (E = 70 GPa, nu = 0.33), its outer surface held (a rigid rod eye).
Eight-node bricks: N_THETA around, N_R through the thickness, N_Z across the width; the
surface has N_THETA x (N_Z + 1) nodes.

(CalculiX's *SUBSTRUCTURE GENERATE would give the surface's condensed stiffness in one step, but
the matrix ccx 2.20 wrote for this deck, read as its manual describes, was about three times
stiffer than its own static solution under a uniform pressure; the unit-load steps agree with
that static solution, so they are used.)

Usage: /usr/bin/python3 make_deck.py && ccx -i shell && /usr/bin/python3 convert.py
"""
import math

R, T, L = 15.0e-3, 1.5e-3, 22.0e-3
E, NU = 70.0e9, 0.33
N_THETA, N_R, N_Z = 48, 3, 10


def node_id(i, k, j):
    """Node at angle index i (periodic), radial index k (0 = inner), axial index j."""
    return 1 + (i % N_THETA) + N_THETA * (k + (N_R + 1) * j)


def main():
    out = ["*HEADING", "FilmDyn example: big-end bearing shell, inner-surface substructure", "*NODE"]
    for j in range(N_Z + 1):
        for k in range(N_R + 1):
            for i in range(N_THETA):
                psi = 2.0 * math.pi * i / N_THETA
                r = R + T * k / N_R
                out.append(f"{node_id(i, k, j)}, {r * math.cos(psi):.12e}, "
                           f"{r * math.sin(psi):.12e}, {L * j / N_Z:.12e}")
    out.append("*ELEMENT, TYPE=C3D8, ELSET=SHELL")
    e = 1
    for j in range(N_Z):
        for k in range(N_R):
            for i in range(N_THETA):
                # Counter-clockwise bottom face (z = j), then the top face (z = j + 1).
                bottom = [node_id(i, k, j), node_id(i, k + 1, j), node_id(i + 1, k + 1, j),
                          node_id(i + 1, k, j)]
                top = [node_id(i, k, j + 1), node_id(i, k + 1, j + 1),
                       node_id(i + 1, k + 1, j + 1), node_id(i + 1, k, j + 1)]
                out.append(f"{e}, " + ", ".join(str(n) for n in bottom + top))
                e += 1
    out.append("*NSET, NSET=OUTER")
    out += [f"{node_id(i, N_R, j)}," for j in range(N_Z + 1) for i in range(N_THETA)]
    out.append("*NSET, NSET=INNER")
    out += [f"{node_id(i, 0, j)}," for j in range(N_Z + 1) for i in range(N_THETA)]
    out += ["*MATERIAL, NAME=ALSN", "*ELASTIC", f"{E:.6e}, {NU}",
            "*SOLID SECTION, ELSET=SHELL, MATERIAL=ALSN",
            "*BOUNDARY", "OUTER, 1, 3"]
    for j in range(N_Z + 1):
        for i in range(N_THETA):
            psi = 2.0 * math.pi * i / N_THETA
            out += ["*STEP", "*STATIC", "*CLOAD, OP=NEW"]
            for dof, value in ((1, math.cos(psi)), (2, math.sin(psi))):
                if abs(value) > 1e-12:  # a zero component needs no card
                    out.append(f"{node_id(i, 0, j)}, {dof}, {value:.12e}")  # ccx: <= 20 chars
            out += ["*NODE PRINT, NSET=INNER", "U", "*END STEP"]
    with open("shell.inp", "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
