#!/usr/bin/python3
"""Checks skirt_compliance.mtx / .nodes.csv (the numbers in README.md):

1. the matrix: size, symmetry, extreme eigenvalues, diagonal range [m/N];
2. the skirt's deflection at the thrust-side middle (alpha = 0, y = L/2 and y = L) under 1 MPa
   on the thrust panel |alpha| <= 46 deg, the pressure lumped on the surface nodes (each node's
   tile of the grid inside the panel times the pressure), against
   - CalculiX's own solution of the same nodal loads (skirt_pressure.dat step 2, if present:
     ccx -i skirt_pressure) and of the pressure on the element faces over |alpha| <= 45 deg
     (step 1, against the matrix with that panel lumped the same way);
   - hand estimates: a ring slice of the skirt between the pin bosses, an axial strip of the
     wall cantilevered from the held belt top (y = -BELT), and the two carrying the load side
     by side.

Needs only numpy; run in this folder: /usr/bin/python3 check.py
"""
import math
import os

import numpy as np

R, T, L, BELT = 36.5e-3, 2.5e-3, 28.0e-3, 3.5e-3  # make_deck.py
E, NU = 75.0e9, 0.33
BOSS_HALF_ANGLE = math.radians(20.0)
PRESSURE = 1.0e6


def read_matrix(path):
    values, size = [], None
    for line in open(path):
        if line.startswith("%"):
            continue
        if size is None:
            size = tuple(int(v) for v in line.split())
            continue
        values.append(float(line))
    m = size[0]
    c = np.zeros((m, m))
    c[np.triu_indices(m)] = values  # the lower triangle column by column = the upper row by row
    return c + np.triu(c, 1).T


def read_nodes(path):
    rows = [line.split(",") for line in open(path).read().split("\n")[1:] if line]
    return np.array([[float(a), float(b)] for a, b in rows])


def tile_loads(xy, half_width, pressure):
    """Nodal forces [N] of a pressure on the panel |alpha| <= half_width: each node's tile (half
    way to its neighbours; around the skirt the grid is periodic, along it the first and last
    rows' tiles end at the grid's ends, y = 0 and L, where the film does)."""
    xs, ys = np.unique(xy[:, 0]), np.unique(xy[:, 1])
    dx = 2.0 * math.pi * R / len(xs)
    ylo = np.concatenate([[ys[0]], 0.5 * (ys[:-1] + ys[1:])])
    yhi = np.concatenate([0.5 * (ys[:-1] + ys[1:]), [ys[-1]]])
    f = np.zeros(len(xy))
    for k, (x, y) in enumerate(xy):
        a = math.remainder(x, 2.0 * math.pi * R)  # signed arc from the thrust axis
        width = max(0.0, min(a + 0.5 * dx, R * half_width) - max(a - 0.5 * dx, -R * half_width))
        j = np.searchsorted(ys, y)
        f[k] = pressure * width * (yhi[j] - ylo[j])
    return f


def ring_slice(half_width, clamp):
    """Inward deflection [m] at alpha = 0 of a ring slice (unit axial length) of the wall
    (mid-surface radius R - T/2, plane-strain modulus) clamped at alpha = +-clamp, the
    pressure on |alpha| <= half_width; curved-beam theory with bending and hoop stretching, the
    two redundants at alpha = 0 (moment, hoop force) from Castigliano's theorem."""
    rm = R - 0.5 * T
    ep = E / (1.0 - NU**2)
    ei, ea = ep * T**3 / 12.0, ep * T
    q = PRESSURE * R / rm  # [N/m] per unit arc length of the mid-surface
    th = np.linspace(0.0, clamp, 2001)
    tangent = np.stack([-np.sin(th), np.cos(th)], 1)
    point = lambda a: rm * np.stack([np.cos(a), np.sin(a)], -1)
    cross = lambda r, f: r[..., 0] * f[..., 1] - r[..., 1] * f[..., 0]
    # Section forces (hoop force N, moment M) at each th of the arc [0, th] loaded by ...
    load_n, load_m = np.zeros_like(th), np.zeros_like(th)
    for k, t in enumerate(th):  # ... the pressure, inward ...
        phi = np.linspace(0.0, min(t, half_width), 401)
        df = -q * rm * np.stack([np.cos(phi), np.sin(phi)], 1)
        load_n[k] = np.trapz(df, phi, axis=0) @ tangent[k]
        load_m[k] = np.trapz(cross(point(phi) - point(t), df), phi)
    arm = point(0.0) - point(th)

    def end_force(f):  # ... or a force f at alpha = 0
        return tangent @ f, cross(arm, np.tile(f, (len(th), 1)))
    hoop = end_force(np.array([0.0, 1.0]))
    moment = (np.zeros_like(th), np.ones_like(th))
    unit = end_force(np.array([-1.0, 0.0]))  # a unit inward force at alpha = 0
    work = lambda a, b: np.trapz(a[0] * b[0] / ea + a[1] * b[1] / ei, th) * rm
    load = (load_n, load_m)
    x = np.linalg.solve([[work(hoop, hoop), work(hoop, moment)],
                         [work(moment, hoop), work(moment, moment)]],
                        [-work(load, hoop), -work(load, moment)])
    actual = tuple(load[i] + x[0] * hoop[i] + x[1] * moment[i] for i in range(2))
    return work(actual, unit)


def strip(y):
    """Inward deflection [m] at y of an axial strip of the wall (unit width, plate bending
    stiffness D) cantilevered from the belt top y = -BELT, the pressure on y = 0 ... L: the
    unit-load integral of M m / D over the strip."""
    d = E * T**3 / (12.0 * (1.0 - NU**2))
    s = np.linspace(-BELT, y, 4001)  # the unit load at y bends the strip above it only
    start = np.maximum(s, 0.0)  # the loaded part below each section s ...
    moment = PRESSURE * 0.5 * ((L - s) ** 2 - (start - s) ** 2)  # ... its moment about s
    return np.trapz(moment * (y - s), s) / d


def dat_steps(path):
    blocks, block = [], None
    for line in open(path):
        if line.strip().startswith("displacements"):
            block = []
            blocks.append(block)
            continue
        f = line.split()
        if block is not None and len(f) == 4:
            block.append([float(v) for v in f[1:]])
    return [np.array(b) for b in blocks]


def main():
    c = read_matrix("skirt_compliance.mtx")
    xy = read_nodes("skirt_compliance.nodes.csv")
    m = len(c)
    eig = np.linalg.eigvalsh(c)
    print(f"1. {m} x {m} ({len(np.unique(xy[:, 0]))} around x {len(np.unique(xy[:, 1]))} "
          f"along, y {xy[:, 1].min() * 1e3:.2f} .. {xy[:, 1].max() * 1e3:.2f} mm); "
          f"symmetric to {np.abs(c - c.T).max() / np.abs(c).max():.1g}; eigenvalues "
          f"{eig[0]:.4g} .. {eig[-1]:.4g} m/N (condition {eig[-1] / eig[0]:.3g}); diagonal "
          f"{c.diagonal().min():.4g} .. {c.diagonal().max():.4g} m/N; "
          f"{np.mean(c < 0):.0%} of the entries negative")

    at = lambda y: int(np.flatnonzero((np.abs(xy[:, 0]) < 1e-12) & (np.abs(xy[:, 1] - y) < 1e-9))[0])
    mid, bottom = at(0.5 * L), at(L)
    f46 = tile_loads(xy, math.radians(46.0), PRESSURE)
    w46 = c @ f46
    print(f"2. 1 MPa on |alpha| <= 46 deg ({f46.sum():.1f} N), lumped: inward deflection at "
          f"alpha = 0: y = L/2 {w46[mid] * 1e6:.3f} um, y = L {w46[bottom] * 1e6:.3f} um")
    if os.path.exists("skirt_pressure.dat"):
        steps = dat_steps("skirt_pressure.dat")
        # The printed rows are the surface nodes in the matrix's order: project on the inward
        # radial direction at alpha = x / R.
        alpha = xy[:, 0] / R
        direct = [-(s[:, 0] * np.cos(alpha) + s[:, 1] * np.sin(alpha)) for s in steps]
        print(f"   ccx, the same nodal loads: y = L/2 {direct[1][mid] * 1e6:.3f} um, y = L "
              f"{direct[1][bottom] * 1e6:.3f} um (matrix - ccx: largest "
              f"{np.abs(w46 - direct[1]).max() / np.abs(direct[1]).max():.1g} of the largest)")
        w45 = c @ tile_loads(xy, math.radians(45.0), PRESSURE)
        print(f"   ccx, 1 MPa on the faces |alpha| <= 45 deg: y = L/2 {direct[0][mid] * 1e6:.3f} "
              f"um, y = L {direct[0][bottom] * 1e6:.3f} um; the matrix, that panel lumped: "
              f"{w45[mid] * 1e6:.3f}, {w45[bottom] * 1e6:.3f} um")
    else:
        print("   (no skirt_pressure.dat: ccx -i skirt_pressure for CalculiX's own solution)")

    clamp = 0.5 * math.pi - BOSS_HALF_ANGLE
    ring = ring_slice(math.radians(46.0), clamp)
    strip_mid, strip_end = strip(0.5 * L), strip(L)
    both = lambda a, b: 1.0 / (1.0 / a + 1.0 / b)
    print(f"   hand: a ring slice between the bosses (clamped at +-{math.degrees(clamp):.0f} deg) "
          f"{ring * 1e6:.2f} um; a wall strip cantilevered from the belt top {strip_mid * 1e6:.0f} um "
          f"at L/2, {strip_end * 1e6:.0f} um at L; side by side {both(ring, strip_mid) * 1e6:.2f} "
          f"um at L/2, {both(ring, strip_end) * 1e6:.2f} um at L: "
          f"{both(ring, strip_mid) / w46[mid]:.2f} and {both(ring, strip_end) / w46[bottom]:.2f} "
          f"times the matrix's")


if __name__ == "__main__":
    main()
