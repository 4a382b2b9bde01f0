"""Curve analysis on Part curves and edges."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import FreeCAD
import Part


def test_profile_of_a_circle_edge():
    edge = Part.makeCircle(2.0, FreeCAD.Vector(1, 1, 0))
    p = fw.curvature_profile(edge, n=300)
    assert p.signed
    assert p.kappa == pytest.approx(np.full(len(p.kappa), 0.5), abs=1e-9)
    assert p.s[-1] == pytest.approx(4 * math.pi, rel=1e-9)
    assert np.all(np.diff(p.u) > 0)


def test_profile_sign_follows_orientation():
    c = fw.csr_spline([(math.cos(a), -math.sin(a)) for a in np.linspace(0, 3, 20)])  # clockwise
    assert fw.curvature_profile(c).kappa.max() < 0


def test_non_planar_curve_has_unsigned_curvature():
    helix = Part.makeHelix(1.0, 3.0, 1.0)
    p = fw.curvature_profile(helix)
    assert not p.signed
    # Helix of radius r and pitch 2 pi c: kappa = r / (r^2 + c^2).
    c = 1.0 / (2 * math.pi)
    assert np.median(p.kappa) == pytest.approx(1.0 / (1.0 + c * c), rel=1e-3)
    assert fw.curvature_sign_changes(helix) == 0


def test_extrema_of_an_ellipse_arc():
    ellipse = Part.Ellipse(FreeCAD.Vector(0, 0, 0), 3.0, 1.0)
    edge = ellipse.toShape(0.2, 6.0)
    ext = fw.curvature_extrema(edge)
    maxima = [e for e in ext if e.maximum]
    minima = [e for e in ext if not e.maximum]
    assert len(maxima) == 1 and len(minima) == 2
    assert maxima[0].kappa == pytest.approx(3.0, rel=1e-3)
    assert all(m.kappa == pytest.approx(1.0 / 9.0, rel=1e-3) for m in minima)


def test_max_distance():
    edge = Part.makeCircle(1.0)
    assert fw.max_distance(edge, [(1.5, 0, 0), (0, 0.9, 0)]) == pytest.approx(0.5, abs=1e-10)


def test_analysis_rejects_non_curves():
    with pytest.raises(fw.InputError, match="not a curve"):
        fw.curvature_profile(42)
