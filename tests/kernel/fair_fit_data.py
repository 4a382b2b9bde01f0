"""Test data of the fair fit (tests/kernel/test_fair_fit.py, the feature tests): shapes whose
curvature signs are known, sampled with and without noise, and the OCCT-side referees."""
import math

import numpy as np


def arc_parabola(n, noise=0.0, seed=1):
    """A half circle of radius 1 (the lower half, counter-clockwise) joined tangentially (C1)
    at (1, 0) to the flat parabola x = 1 - 0.1 y^2 up to y = 1.5: convex, curvature positive,
    jumping from 1 to 0.2. Uniform noise of `noise` times the size in each coordinate."""
    m1 = n // 2
    theta = np.linspace(math.pi, 2 * math.pi, m1, endpoint=False)
    y = np.linspace(0.0, 1.5, n - m1)
    pts = np.vstack([np.c_[np.cos(theta), np.sin(theta)], np.c_[1 - 0.1 * y ** 2, y]])
    return _noisy(pts, noise, seed)


def road(n, noise=0.0, seed=2, radius=20.0, straight=30.0):
    """A road alignment: line, arc left (90 deg), line, arc right (90 deg), line, arc left
    (60 deg), line; tangent (C1) throughout. Its curvature changes sign twice. Sampled
    uniformly in arc length."""
    plan = [("L", straight), ("A", radius, math.pi / 2), ("L", straight), ("A", -radius, math.pi / 2),
            ("L", straight), ("A", radius, math.pi / 3), ("L", straight)]
    pos, ang, dense = np.zeros(2), 0.0, []
    for piece in plan:
        if piece[0] == "L":
            s = np.linspace(0, piece[1], 4000, endpoint=False)
            dense.append(pos + np.outer(s, [math.cos(ang), math.sin(ang)]))
            pos = pos + piece[1] * np.array([math.cos(ang), math.sin(ang)])
        else:
            sgn, r, sweep = math.copysign(1.0, piece[1]), abs(piece[1]), piece[2]
            centre = pos + sgn * r * np.array([-math.sin(ang), math.cos(ang)])
            a0 = ang - sgn * math.pi / 2
            phi = a0 + sgn * np.linspace(0, sweep, 4000, endpoint=False)
            dense.append(centre + r * np.c_[np.cos(phi), np.sin(phi)])
            ang += sgn * sweep
            pos = centre + r * np.array([math.cos(a0 + sgn * sweep), math.sin(a0 + sgn * sweep)])
    dense.append(pos[None, :])
    d = np.vstack(dense)
    s = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(d, axis=0), axis=1))]
    st = np.linspace(0.0, s[-1], n)
    return _noisy(np.c_[np.interp(st, s, d[:, 0]), np.interp(st, s, d[:, 1])], noise, seed)


def ellipse(n, a=2.0, b=1.0, closed=False):
    """An ellipse sampled at equal parameter steps (the whole loop without repeating the
    first point when closed, else the upper half from (a, 0) to (-a, 0))."""
    t = np.linspace(0, 2 * math.pi, n, endpoint=False) if closed else np.linspace(0, math.pi, n)
    return np.c_[a * np.cos(t), b * np.sin(t)]


def naca4(digits="2412", n=101, blunt=False):
    """A NACA 4-digit airfoil of chord 1 from its analytic formula (cosine spacing), as a
    Selig coordinate file lists it: from the trailing edge over the upper surface to the
    leading edge and back along the lower one (2 n - 1 points). Sharp trailing edge (the
    last coefficient -0.1036: the first and last points coincide) or blunt (-0.1015, the
    original formula: a gap of about 0.25 % of the chord)."""
    m, p, t = int(digits[0]) / 100, int(digits[1]) / 10, int(digits[2:]) / 100
    beta = np.linspace(0, math.pi, n)
    x = (1 - np.cos(beta)) / 2
    a4 = -0.1015 if blunt else -0.1036
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 + a4 * x ** 4)
    if m == 0:  # symmetric: no camber
        yc = dyc = np.zeros_like(x)
    else:
        yc = np.where(x < p, m / p ** 2 * (2 * p * x - x ** 2), m / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * x - x ** 2))
        dyc = np.where(x < p, 2 * m / p ** 2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    th = np.arctan(dyc)
    upper = np.c_[x - yt * np.sin(th), yc + yt * np.cos(th)]
    lower = np.c_[x + yt * np.sin(th), yc - yt * np.cos(th)]
    return np.vstack([upper[::-1], lower[1:]])


def hairpin_road(seed=0, spacing=10.0, noise=0.05):
    """A road alignment of lines, clothoids and arcs with two hairpins (turns of 160-175 deg
    on radii of 7-10 m, under 3 sample spacings of 10 m) and a reverse curve between, sampled
    every `spacing` metres along it with Gaussian noise of standard deviation `noise` per
    coordinate (5 cm, a survey's). Returns (points, true curvature sign changes): the plan's
    curvature is piecewise linear in arc length (clothoids), so its signs are exact."""
    rng = np.random.default_rng(seed)
    r1, r2 = rng.uniform(7.0, 10.0, 2)
    sweep1, sweep2 = np.radians(rng.uniform(160.0, 175.0, 2))
    L = rng.uniform(25.0, 40.0)  # clothoid lengths around the gentle arcs
    r3, r4 = rng.uniform(80.0, 150.0, 2)
    # (length, curvature at start, curvature at end): lines, clothoids, arcs.
    plan = [(120.0, 0, 0), (8.0, 0, 1 / r1), (sweep1 * r1 - 8.0, 1 / r1, 1 / r1), (8.0, 1 / r1, 0),
            (150.0, 0, 0), (L, 0, -1 / r3), (60.0, -1 / r3, -1 / r3), (L, -1 / r3, 0), (40.0, 0, 0),
            (L, 0, 1 / r4), (50.0, 1 / r4, 1 / r4), (L, 1 / r4, 0), (130.0, 0, 0), (8.0, 0, -1 / r2),
            (sweep2 * r2 - 8.0, -1 / r2, -1 / r2), (8.0, -1 / r2, 0), (120.0, 0, 0)]
    ds = 0.01
    k = np.concatenate([np.linspace(k0, k1, max(2, int(round(length / ds))), endpoint=False)
                        for length, k0, k1 in plan])
    lengths = np.concatenate([np.full(max(2, int(round(length / ds))), length / max(2, int(round(length / ds))))
                              for length, _, _ in plan])
    heading = np.concatenate([[0.0], np.cumsum(k * lengths)])[:-1] + 0.5 * k * lengths
    xy = np.vstack([[0.0, 0.0], np.cumsum(np.c_[np.cos(heading), np.sin(heading)] * lengths[:, None], axis=0)])
    s = np.r_[0.0, np.cumsum(lengths)]
    st = np.arange(0.0, s[-1], spacing)
    pts = np.c_[np.interp(st, s, xy[:, 0]), np.interp(st, s, xy[:, 1])]
    pts = pts + rng.normal(0.0, noise, pts.shape)
    signs = [np.sign(k0 + k1) for _, k0, k1 in plan if k0 + k1 != 0]
    true_changes = int(sum(a != b for a, b in zip(signs[:-1], signs[1:])))
    return pts, true_changes


def helix(n, noise=0.0, seed=3, turns=1.5):
    """A helix of radius 1 and pitch 0.5 (3D, not planar)."""
    t = np.linspace(0, 2 * math.pi * turns, n)
    return _noisy(np.c_[np.cos(t), np.sin(t), 0.5 * t / (2 * math.pi)], noise, seed)


def size_of(pts):
    return float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0)))


def _noisy(pts, noise, seed):
    if noise == 0.0:
        return pts
    rng = np.random.default_rng(seed)
    return pts + rng.uniform(-noise * size_of(pts), noise * size_of(pts), pts.shape)


def signed_curvatures(curve, per_span=20, normal=(0.0, 0.0, 1.0)):
    """OCCT's signed curvature of a planar Part curve (about `normal`), per_span samples per
    knot span (getD2)."""
    knots = curve.getKnots()
    us = [u for a, b in zip(knots[:-1], knots[1:]) for u in np.linspace(a, b, per_span, endpoint=False)]
    us.append(knots[-1])
    nrm = np.asarray(normal, dtype=float)
    out = []
    for u in us:
        _, d1, d2 = curve.getD2(u)
        v1, v2 = np.array([d1.x, d1.y, d1.z]), np.array([d2.x, d2.y, d2.z])
        out.append(float(np.cross(v1, v2) @ nrm) / float(v1 @ v1) ** 1.5)
    return np.array(out)


def sign_changes(kappa, closed=False, zero=1e-6):
    """Sign changes of a curvature sequence, skipping |kappa| <= zero * max |kappa|."""
    k = kappa[np.abs(kappa) > zero * np.abs(kappa).max()]
    s = np.sign(k)
    changes = int(np.sum(s[1:] != s[:-1]))
    if closed and len(s) > 1 and s[0] != s[-1]:
        changes += 1
    return changes


def distances(curve, pts):
    """OCCT's distance from each point to the curve: the curve's own projection
    (parameter, value), confirmed by BRepExtrema (distToShape) where it is not the nearest."""
    import FreeCAD
    import Part

    edge = None
    out = np.empty(len(pts))
    for i, p in enumerate(pts):
        v = FreeCAD.Vector(*([float(c) for c in p] + [0.0] * (3 - len(p))))
        out[i] = (curve.value(curve.parameter(v)) - v).Length
    return out, lambda i: _dist_to_shape(edge, curve, pts[i], Part, FreeCAD)


def _dist_to_shape(edge, curve, p, Part, FreeCAD):
    edge = edge or curve.toShape()
    v = FreeCAD.Vector(*([float(c) for c in p] + [0.0] * (3 - len(p))))
    return edge.distToShape(Part.Vertex(v))[0]


def max_distance(curve, pts):
    """The largest OCCT distance from the points to the curve."""
    d, exact = distances(curve, pts)
    worst = int(np.argmax(d))
    return min(float(d[worst]), exact(worst)) if d[worst] > 0 else 0.0


def within(curve, pts, tol):
    """Every point within tol of the curve (OCCT's projection, confirmed by distToShape for
    any point the projection puts beyond tol)."""
    d, exact = distances(curve, pts)
    bad = [i for i in np.nonzero(d > tol)[0] if exact(i) > tol]
    return len(bad) == 0, bad
