#!/usr/bin/python3
"""Writes two CalculiX decks of a piston skirt (the default case's piston):

  skirt.inp           one static step per node of the skirt's outer (film) surface, each a unit
                      INWARD radial force (1 N, toward the piston axis: the way the film pressure
                      pushes the skirt) on that node, printing every outer-surface node's
                      displacement (skirt.dat). Column b of the surface's compliance is the
                      inward radial displacement of every node in step b (convert.py).
  skirt_pressure.inp  the same skirt under 1 MPa on its thrust panel, for check.py: step 1 the
                      pressure on the element faces with |alpha| <= 45 deg (*DLOAD), step 2 the
                      pressure over |alpha| <= 46 deg lumped on the surface nodes (*CLOAD: each
                      node's area share times the pressure, the loads check.py puts on the matrix).

The skirt: a full 360 deg cylinder of outer radius R = 36.5 mm (the film surface), wall T =
2.5 mm, length L = 28 mm from the top edge (z = 0, the film's y = 0) to the open bottom edge
(z = L); above it the same wall continues BELT = 3.5 mm as a stand-in for the ring belt
(z = -BELT ... 0), up to the joint to the crown. An Al-Si alloy (E = 75 GPa, nu = 0.33). The
thrust axis is x; alpha is measured from it toward y; the pin axis is y (alpha = 90 and
270 deg); z, the piston axis, is the film's y (down the skirt from its top).

Supports: the belt's top edge (every node at z = -BELT, through the wall) held in x, y and z
(the stiff crown); each pin boss: the inner-surface nodes within BOSS_HALF_ANGLE of alpha =
90 deg and 270 deg with BOSS_TOP <= z <= BOSS_DEPTH held in x, y and z (BOSS_TOP = -BELT: the
boss hangs from the crown, through the belt section, down to 18 mm). The skirt's top edge
z = 0 is not held: it moves with the belt. The thrust side, the anti-thrust side and the bottom
edge are free.

Elements: ELEMENT = "C3D20R" (20-node bricks, reduced integration), N_THETA around, N_R through
the wall, N_BELT along the belt section and N_Z along the skirt. The film surface is the
corner nodes on the outer face from z = 0 to z = L inclusive, the only nodes loaded and
printed: N_THETA x (N_Z + 1) of them; the belt's nodes are structure only. Eight-node bricks
(ELEMENT = "C3D8", N_R = 2) lock in the skirt's bending: on this surface grid they deflect
9 % less under the thrust-panel pressure (README.md), so the quadratic bricks are used; one of
them through the wall is within 2 % of the converged deflections, and the 576 steps take about
three minutes.

(CalculiX's *SUBSTRUCTURE GENERATE would condense the surface's stiffness in one step, but for a
bearing shell the matrix ccx 2.20 wrote was about three times stiffer than its own static
solution (examples/calculix-bearing-shell); the unit-load steps are used here too.)

Usage: /usr/bin/python3 make_deck.py && ccx -i skirt && /usr/bin/python3 convert.py
       (and for the check: ccx -i skirt_pressure && /usr/bin/python3 check.py)
"""
import math

R, T, L, BELT = 36.5e-3, 2.5e-3, 28.0e-3, 3.5e-3
E, NU = 75.0e9, 0.33
BOSS_HALF_ANGLE, BOSS_TOP, BOSS_DEPTH = math.radians(20.0), -BELT, 18.0e-3
ELEMENT, N_THETA, N_R, N_BELT, N_Z = "C3D20R", 64, 1, 1, 8
PRESSURE = 1.0e6  # [Pa] for skirt_pressure.inp

Q = 2 if ELEMENT.startswith("C3D20") else 1  # node lines per element edge (midside nodes)
NI, NK, NJ = Q * N_THETA, Q * N_R + 1, Q * (N_BELT + N_Z) + 1  # lines around, through, along
J0 = Q * N_BELT  # the node line at z = 0 (the skirt's top edge, the film's first row)


def node_id(i, k, j):
    """Node on line i around (periodic), k through the wall (0 = inner), j along (0 = the belt's
    top, J0 = the skirt's top)."""
    return 1 + (i % NI) + NI * (k + NK * j)


def exists(i, k, j):
    """A 20-node brick has its corners and edge midpoints only: no face or body centres."""
    return Q == 1 or (i % 2) + (k % 2) + (j % 2) <= 1


def angle(i):
    return 2.0 * math.pi * i / NI


def height(j):
    """z [m] of node line j: the belt section -BELT ... 0, then the skirt 0 ... L."""
    if j <= J0:
        return -BELT + BELT * j / J0 if j < J0 else 0.0
    return L * (j - J0) / (NJ - 1 - J0)


def surface():
    """The film-surface nodes (corners of the outer face, z = 0 ... L) as (i, j), in rows from
    the skirt's top, alpha increasing along each row (ascending node numbers)."""
    return [(i, j) for j in range(J0, NJ, Q) for i in range(0, NI, Q)]


def held(i, k, j):
    if j == 0:
        return True  # the belt's top edge: the joint to the crown
    if k != 0 or not BOSS_TOP - 1e-12 <= height(j) <= BOSS_DEPTH + 1e-12:
        return False
    a = angle(i)
    return any(abs(a - c) <= BOSS_HALF_ANGLE + 1e-9 for c in (0.5 * math.pi, 1.5 * math.pi))


def share(i, j, half_width):
    """The area of surface node (i, j)'s tile [m^2] inside the panel |alpha| <= half_width: half
    way to its neighbours (the top and bottom rows: half a row, the film ends there)."""
    a = math.remainder(angle(i), 2.0 * math.pi)
    da = 2.0 * math.pi / N_THETA
    width = max(0.0, min(a + 0.5 * da, half_width) - max(a - 0.5 * da, -half_width))
    dz = L / N_Z
    return R * width * (0.5 * dz if j in (J0, NJ - 1) else dz)


def inward(i):
    """The inward radial unit vector's x, y at angle line i."""
    return -math.cos(angle(i)), -math.sin(angle(i))


def cload(i, j, force):
    lines = []
    for dof, value in zip((1, 2), inward(i)):
        if abs(value) > 1e-12:  # a zero component needs no card
            lines.append(f"{node_id(i, NK - 1, j)}, {dof}, {force * value:.10g}")  # <= 20 chars
    return lines


def model():
    out = ["*NODE"]
    for j in range(NJ):
        for k in range(NK):
            for i in range(NI):
                if exists(i, k, j):
                    r = R - T + T * k / (NK - 1)
                    out.append(f"{node_id(i, k, j)}, {r * math.cos(angle(i)):.12e}, "
                               f"{r * math.sin(angle(i)):.12e}, {height(j):.12e}")
    out.append(f"*ELEMENT, TYPE={ELEMENT}, ELSET=SKIRT")
    thrust = []
    e = 1
    for j in range(0, NJ - 1, Q):
        for k in range(0, NK - 1, Q):
            for i in range(0, NI, Q):
                # Corners: the face z = j counter-clockwise seen from +z (i, k), (i, k + 1),
                # (i + 1, k + 1), (i + 1, k), then the same at z = j + 1; face S4 is the outer.
                face = [(i, k), (i, k + Q), (i + Q, k + Q), (i + Q, k)]
                nodes = [node_id(a, b, j) for a, b in face] + [node_id(a, b, j + Q) for a, b in face]
                if Q == 2:  # midside nodes: the edges of face z = j, of face z = j + 1, then along z
                    edges = [(i, k + 1), (i + 1, k + 2), (i + 2, k + 1), (i + 1, k)]
                    nodes += [node_id(a, b, j) for a, b in edges]
                    nodes += [node_id(a, b, j + 2) for a, b in edges]
                    nodes += [node_id(a, b, j + 1) for a, b in face]
                ids = [str(n) for n in nodes]
                out.append(f"{e}, " + ", ".join(ids[:15]) + ("," if len(ids) > 15 else ""))
                if len(ids) > 15:
                    out.append(", ".join(ids[15:]))  # a card holds 16 entries
                middle = math.remainder(angle(i + 0.5 * Q), 2.0 * math.pi)
                if j >= J0 and k + Q == NK - 1 and abs(middle) < math.radians(45.0):
                    thrust.append(e)
                e += 1
    out.append("*NSET, NSET=SURFACE")
    out += [f"{node_id(i, NK - 1, j)}," for i, j in surface()]
    out.append("*NSET, NSET=HELD")
    out += [f"{node_id(i, k, j)}," for j in range(NJ) for k in range(NK) for i in range(NI)
            if exists(i, k, j) and held(i, k, j)]
    out.append("*ELSET, ELSET=THRUST45")
    out += [f"{e}," for e in thrust]
    out += ["*MATERIAL, NAME=ALSI", "*ELASTIC", f"{E:.6e}, {NU}",
            "*SOLID SECTION, ELSET=SKIRT, MATERIAL=ALSI",
            "*BOUNDARY", "HELD, 1, 3"]
    return out


def write(path, heading, lines):
    with open(path, "w") as f:
        f.write("\n".join(["*HEADING", heading] + lines) + "\n")


def main():
    mesh = model()
    steps = []
    for i, j in surface():
        steps += ["*STEP", "*STATIC", "*CLOAD, OP=NEW"] + cload(i, j, 1.0)
        steps += ["*NODE PRINT, NSET=SURFACE", "U", "*END STEP"]
    write("skirt.inp", "FilmDyn example: piston skirt, outer-surface unit inward loads", mesh + steps)
    pressure = ["*STEP", "*STATIC", "*DLOAD", f"THRUST45, P4, {PRESSURE:.10g}",
                "*NODE PRINT, NSET=SURFACE", "U", "*END STEP",
                "*STEP", "*STATIC", "*DLOAD, OP=NEW", "*CLOAD"]
    for i, j in surface():
        a = share(i, j, math.radians(46.0))
        if a > 0.0:
            pressure += cload(i, j, PRESSURE * a)
    pressure += ["*NODE PRINT, NSET=SURFACE", "U", "*END STEP"]
    write("skirt_pressure.inp", "FilmDyn example: piston skirt, 1 MPa on the thrust panel",
          mesh + pressure)


if __name__ == "__main__":
    main()
