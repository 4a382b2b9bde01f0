"""Test data shared by the kernel tests."""
import math

import numpy as np


def fig2_samples(per_half_circle=12, parabola_samples=19):
    """Fig. 2 of the csr paper: a half circle (radius 1, counter-clockwise from (1,0) to
    (-1,0)) continued tangentially by an almost flat parabola (curvature 0.04 at the
    joint), sampled at equal spacing."""
    h = math.pi / per_half_circle
    a = np.arange(per_half_circle + 1) * h
    circle = np.c_[np.cos(a), np.sin(a)]
    s = np.arange(1, parabola_samples + 1) * h
    parabola = np.c_[-1.0 + 0.02 * s**2, -s]
    return np.r_[circle, parabola]


def signed_curvatures(curve, per_span=32):
    """Signed curvature (about +z) evaluated by OCCT through Part, per knot span."""
    knots = curve.getKnots()
    out = []
    for a, b in zip(knots[:-1], knots[1:]):
        for j in range(per_span):
            u = a + (b - a) * j / per_span
            _, d1, d2 = curve.getD2(u)
            out.append(d1.cross(d2).z / d1.Length**3)
    return np.array(out)


def sign_changes(kappa, tol=1e-9):
    signs = np.sign(kappa[np.abs(kappa) > tol])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


def distance_to_curve(curve, point):
    """Distance from a point to the curve by OCCT's projection (Part)."""
    import FreeCAD
    import Part

    vertex = Part.Vertex(FreeCAD.Vector(*point))
    return vertex.distToShape(curve.toShape())[0]
