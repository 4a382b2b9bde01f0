"""G2 face blends (issue 29): every case judged by OCCT on the returned Part surface against the
faces (fw.blend_errors: 101 points per edge, Surface.parameter / value / normal / getDN, normal
curvature across the edge and at 45 degrees), never by the construction's formulas; one case
also by the surface-analysis continuity check (fw.edge_continuity) on a sewn shell. Cross
sections are Part curves (uIso) whose curvature extrema are counted by sampling OCCT's
curvature."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw

from .test_fair_blend_space import import_partdesign

V = FreeCAD.Vector
GAP, ANGLE, CURVATURE = 1e-7, 1e-4, 1e-4  # the tolerances


def _edge_at(face, predicate):
    edges = [i for i, e in enumerate(face.Edges) if e.Length > 1e-12 and predicate(e)]
    assert len(edges) == 1, [e.CenterOfMass for e in face.Edges]
    return face.Edges[edges[0]]


def _rim(face, z):
    return _edge_at(face, lambda e: e.Curve.__class__.__name__ == "Circle" and abs(e.CenterOfMass.z - z) < 1e-9)


def _check(blend, report, g2=True):
    """The issue's tolerances on both sides, from the report's OCCT referee and recomputed here."""
    assert report.valid
    for side in report.errors:
        assert side["samples"] == 101
        assert side["gap"] <= GAP, side
        assert side["angle"] <= ANGLE, side
        if g2:
            assert side["curvature_jump_across"] <= CURVATURE, side
            assert side["curvature_jump_45"] <= CURVATURE, side
    assert blend.toShape().isValid()


def _section_extrema(blend, u, n=400):
    """Curvature extrema of the cross section at u (a Part curve), by sampling OCCT's curvature."""
    section = blend.uIso(u)
    k = np.array([section.curvature(section.FirstParameter + (section.LastParameter - section.FirstParameter) * i / n)
                  for i in range(n + 1)])
    d = np.diff(k)
    d = d[np.abs(d) > 1e-9 * max(k.max(), 1e-300)]
    return int(np.sum(np.sign(d[1:]) != np.sign(d[:-1])))


def _cylinder(radius, z0, height, x=0.0):
    return Part.makeCylinder(radius, height, V(x, 0, z0), V(0, 0, 1)).Faces[0]


def _bspline_face(poles, degree_u, degree_v, knots_u=None, knots_v=None, weights=None):
    nu, nv = len(poles), len(poles[0])

    def clamped(n, p, interior):
        knots = [0.0] + list(interior) + [1.0]
        mults = [p + 1] + [1] * len(interior) + [p + 1]
        assert sum(mults) == n + p + 1
        return knots, mults

    ku, mu = clamped(nu, degree_u, knots_u or [])
    kv, mv = clamped(nv, degree_v, knots_v or [])
    s = Part.BSplineSurface()
    args = [[[V(*p) for p in row] for row in poles], mu, mv, ku, kv, False, False, degree_u, degree_v]
    if weights is not None:
        args.append(weights)
    s.buildFromPolesMultsKnots(*args)
    return s.toShape()


def _wavy(nu, nv, z0, amplitude, x0=0.0, y0=0.0, lx=2.0, ly=1.0):
    return [[(x0 + lx * i / (nu - 1), y0 + ly * j / (nv - 1),
              z0 + amplitude * math.sin(1.3 * i + 0.7 * j) * (j / (nv - 1)) ** 2) for j in range(nv)]
            for i in range(nu)]


# ---- the cases ---------------------------------------------------------------------------------


def test_coaxial_cylinders_closed_rim_is_g2_exact_and_fair():
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.5, 2.0, 1.0)
    blend, report = fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0))
    _check(blend, report)
    assert all(side["method"] == "exact" and side["closed"] for side in report.sides)
    # The blend closes around the axis, G2 across its own seam (the surface analysis's verdict).
    assert blend.value(0.0, 0.5).distanceToPoint(blend.value(1.0, 0.5)) < 1e-12
    seam = [r for r in fw.edge_continuity(blend.toShape()) if r.kind == "seam"]
    assert len(seam) == 1 and seam[0].continuity == "G2" and seam[0].curvature_jump < 1e-9, seam
    # Rotationally symmetric data: every section the same S between two straight generators, whose
    # unsigned curvature has the least possible extrema: 0, a maximum, 0 (the inflection), a maximum, 0.
    counts = {_section_extrema(blend, u) for u in (0.05, 0.31, 0.5, 0.77)}
    assert counts == {3}, counts
    assert all(s["curvature_extrema"] == 3 for s in report.sections)


def test_offset_cylinders():
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.0, 2.0, 1.0, x=0.4)
    blend, report = fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0))
    _check(blend, report)
    assert max(_section_extrema(blend, u) for u in np.linspace(0, 1, 9)) <= 3


def _section_fairness(blend, u, n=200):
    """(curvature extrema, L^3 int (dkappa/ds)^2 ds) of the section at u, from OCCT's curvature and arc length."""
    section = blend.uIso(u)
    t = np.linspace(section.FirstParameter, section.LastParameter, n + 1)
    k = np.array([section.curvature(x) for x in t])
    ds = np.array([section.length(t[i], t[i + 1]) for i in range(n)])
    dk = np.diff(k)
    length = ds.sum()
    return _section_extrema(blend, u), float(length ** 3 * np.sum(dk * dk / ds))


def test_fair_magnitudes_beat_fixed_ones():
    """The chosen magnitudes give sections with no more curvature extrema, and then no more
    variation, than fixed magnitudes (a third of the chord and others), as OCCT measures them."""
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.0, 2.0, 1.0, x=0.4)
    fair, report = fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0), measure=False)
    us = np.linspace(0.0, 1.0, 9)

    def score(blend):
        values = [_section_fairness(blend, float(u)) for u in us]
        return sum(e for e, _ in values), sum(v for _, v in values)

    best = score(fair)
    compared = 0
    for scale in (0.4, 0.7, 1.0, 1.5, 2.2):
        try:
            fixed, _ = fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0), scale_a=scale, scale_b=scale, measure=False)
        except fw.InputError as exc:  # too long a magnitude folds the blend: refused
            assert "cross itself" in str(exc)
            continue
        other = score(fixed)
        compared += 1
        assert best[0] < other[0] or (best[0] == other[0] and best[1] <= other[1] * 1.001), (scale, best, other)
    assert compared >= 3


def test_plane_to_curved_bspline_face():
    plane = Part.makePlane(2.0, 1.0, V(0, -1.0, 0))  # y in [-1, 0], edge y = 0
    edge_a = _edge_at(plane, lambda e: abs(e.CenterOfMass.y) < 1e-12 and e.Length > 1.9)
    surface = _bspline_face(_wavy(6, 5, 0.8, 0.15, y0=0.6), 3, 3, [0.3, 0.7], [0.5])
    edge_b = _edge_at(surface, lambda e: abs(e.CenterOfMass.y - 0.6) < 1e-9)
    blend, report = fw.blend_faces(plane, edge_a, surface, edge_b)
    _check(blend, report)
    assert report.sides[0]["surface_type"] == "Plane"


def test_report_sections_agree_with_occt():
    """A plane into a quarter cylinder turning the same way: every section's certified extremum
    count is what OCCT's curvature along the section (uIso) shows, and it is the fewest such
    ends admit here (one: a clothoid from 0 to 1/r turning 90 degrees is longer than the gap)."""
    plane = Part.makePlane(2.0, 1.0, V(0, -1.0, 0))
    edge_a = _edge_at(plane, lambda e: abs(e.CenterOfMass.y) < 1e-12 and e.Length > 1.9)
    arc = Part.makeCircle(1.0, V(0, 0.2, 0.8), V(1, 0, 0), 0, 90)
    quarter = arc.extrude(V(2, 0, 0)).Faces[0]
    edge_b = _edge_at(quarter, lambda e: e.Curve.__class__.__name__ == "Line" and abs(e.CenterOfMass.y - 1.2) < 1e-9)
    blend, report = fw.blend_faces(plane, edge_a, quarter, edge_b)
    _check(blend, report)
    for section in report.sections:
        assert section["curvature_extrema"] == section["sampled_extrema"] == _section_extrema(blend, section["u"])
    assert {s["curvature_extrema"] for s in report.sections} == {1}


def test_sphere_to_cone():
    sphere = Part.makeSphere(1.0, V(0, 0, 0), V(0, 0, 1), -30, 30).Faces[0]
    cone = Part.makeCone(1.3, 0.9, 1.0, V(0, 0, 1.4)).Faces[0]
    blend, report = fw.blend_faces(sphere, _rim(sphere, 0.5), cone, _rim(cone, 1.4))
    _check(blend, report)
    assert [s["surface_type"] for s in report.sides] == ["SphericalSurface", "ConicalSurface"]


def test_bspline_faces_of_different_degrees_and_knots():
    a = _bspline_face(_wavy(7, 4, 0.0, 0.1), 3, 3, [0.2, 0.5, 0.8], [])
    b = _bspline_face(_wavy(5, 6, 0.0, 0.1, y0=1.8, lx=2.5), 2, 4, [0.4, 0.6], [0.5])
    edge_a = _edge_at(a, lambda e: abs(e.CenterOfMass.y - 1.0) < 1e-9)
    edge_b = _edge_at(b, lambda e: abs(e.CenterOfMass.y - 1.8) < 1e-9)
    blend, report = fw.blend_faces(a, edge_a, b, edge_b)
    _check(blend, report)
    # Cross-checked by the surface analysis (issue 27): the sewn shell is G2 along both edges.
    shell = Part.makeShell([a, blend.toShape(), b])
    shell.sewShape()
    verdicts = [r for r in fw.edge_continuity(shell) if r.kind == "shared"]
    assert len(verdicts) == 2
    assert all(r.continuity == "G2" and r.curvature_jump < 1e-6 for r in verdicts), verdicts


def test_rational_face():
    poles = _wavy(4, 4, 0.0, 0.2)
    weights = [[1.0, 1.4, 0.7, 1.0], [1.0, 0.6, 1.5, 1.0], [1.0, 1.2, 0.9, 1.0], [1.0, 0.8, 1.3, 1.0]]
    a = _bspline_face(poles, 3, 3, weights=weights)
    assert a.Surface.isURational() or a.Surface.isVRational()
    # Half a cylinder along x above the gap: its straight boundary nearest face a.
    b = Part.makeCylinder(0.6, 2.0, V(0, 2.4, 0.9), V(1, 0, 0), 180).Faces[0]
    edge_a = _edge_at(a, lambda e: abs(e.CenterOfMass.y - 1.0) < 1e-9)
    lines = [e for e in b.Edges if e.Curve.__class__.__name__ == "Line"]
    edge_b = min(lines, key=lambda e: e.distToShape(edge_a)[0])
    blend, report = fw.blend_faces(a, edge_a, b, edge_b)
    _check(blend, report)
    assert report.sides[0]["rational"] and report.sides[1]["rational"]
    weights = np.array(blend.getWeights())
    assert np.ptp(weights) > 0.1  # the blend carries the faces' weights


def test_basic_shapes_are_sides():
    zone = fw.shapes.SphereZone((0, 0, 0), 1.0, np.linspace(0, 2 * np.pi, 5), [-0.5, 0.0, 0.5])
    torus = fw.shapes.Torus((0, 0, 2.2), 1.6, 0.4, np.linspace(0, 2 * np.pi, 5), [-np.pi / 2, 0.0, np.pi / 2])
    blend, report = fw.blend_faces(zone, "end", torus, "start")
    _check(blend, report)
    assert report.sides[1]["surface_type"] == "ToroidalSurface"
    cylinder = fw.shapes.Cylinder((0, 0, 0), 1.0, np.linspace(0, np.pi, 3), [0.0, 1.0])
    cone = fw.shapes.Cone((0, 0, 1.8), 0.9, 0.4, np.linspace(0, np.pi, 3), [0.0, 1.0])
    blend, report = fw.blend_faces(cylinder, "end", cone, "start")
    _check(blend, report)


def test_partial_edges_and_flip():
    a = _bspline_face(_wavy(6, 4, 0.0, 0.1), 3, 3, [0.3, 0.6], [])
    b = _bspline_face(_wavy(6, 4, 0.3, 0.1, y0=1.9)[::-1], 3, 3, [0.3, 0.6], [])  # its edge runs the other way
    edge_a = _edge_at(a, lambda e: abs(e.CenterOfMass.y - 1.0) < 1e-9)
    edge_b = _edge_at(b, lambda e: abs(e.CenterOfMass.y - 1.9) < 1e-9)
    blend, report = fw.blend_faces(a, edge_a, b, edge_b, flip=True, start=0.2, end=0.7)
    assert report.valid
    for side, face, edge in ((0, a, edge_a), (1, b, edge_b)):
        errors = fw.blend_errors(blend, face, edge, float(side), 0.2, 0.7, report.size)
        assert errors["gap"] <= GAP and errors["angle"] <= ANGLE and errors["curvature_jump"] <= CURVATURE, errors
    # u = 0 starts at 0.2 of edge a and (flipped) at 0.7 of edge b; u = 1 at 0.7 of a and 0.2 of b.

    def at(edge, f):
        return edge.valueAt(edge.FirstParameter + f * (edge.LastParameter - edge.FirstParameter))

    for u, fa, fb in ((0.0, 0.2, 0.7), (1.0, 0.7, 0.2)):
        assert blend.value(u, 0.0).distanceToPoint(at(edge_a, fa)) < 1e-12
        assert blend.value(u, 1.0).distanceToPoint(at(edge_b, fb)) < 1e-12


def test_partdesign_solid_faces(doc):
    import_partdesign()
    body = doc.addObject("PartDesign::Body", "Body")
    cylinder = body.newObject("PartDesign::AdditiveCylinder", "Cylinder")
    cylinder.Radius, cylinder.Height = 1.0, 1.0
    other = doc.addObject("PartDesign::Body", "Body001")
    cone = other.newObject("PartDesign::AdditiveCone", "Cone")
    cone.Radius1, cone.Radius2, cone.Height = 1.4, 0.8, 1.0
    other.Placement = FreeCAD.Placement(V(0.2, 0, 2.0), FreeCAD.Rotation())
    doc.recompute()
    face_a = [f for f in body.Shape.Faces if f.Surface.__class__.__name__ == "Cylinder"][0]
    face_b = [f for f in other.Shape.Faces if f.Surface.__class__.__name__ == "Cone"][0]
    blend, report = fw.blend_faces(face_a, _rim(face_a, 1.0), face_b, _rim(face_b, 2.0))
    _check(blend, report)


def test_g1_against_occt_fillet():
    """The walls a fillet leaves: OCCT's fillet is G1 there (curvature jumps by 1/r); our G1 blend
    meets them as closely in normal, our G2 blend in curvature too."""
    box = Part.makeBox(2, 2, 2)
    edge = _edge_at(box, lambda e: abs(e.CenterOfMass.x - 1) < 1e-9 and abs(e.CenterOfMass.y) < 1e-9
                    and abs(e.CenterOfMass.z - 2) < 1e-9)
    filleted = box.makeFillet(0.5, [edge])
    fillet = [f for f in filleted.Faces if f.Surface.__class__.__name__ == "Cylinder"][0]
    walls = []
    for e in (e for e in fillet.Edges if e.Curve.__class__.__name__ == "Line"):
        for f in filleted.Faces:
            if not f.isSame(fillet) and any(fe.isSame(e) for fe in f.Edges) and f.Surface.__class__.__name__ == "Plane":
                walls.append((f, [fe for fe in f.Edges if fe.isSame(e)][0]))
    assert len(walls) == 2
    (fa, ea), (fb, eb) = walls
    size = fillet.BoundBox.DiagonalLength
    occt = [fw.blend_errors(fillet.Surface, f, e, None, size=size) for f, e in walls]
    g1, report1 = fw.blend_faces(fa, ea, fb, eb, continuity="G1")
    g2, report2 = fw.blend_faces(fa, ea, fb, eb, continuity="G2")
    _check(g1, report1, g2=False)
    _check(g2, report2)
    for ours, theirs in zip(report1.errors, occt):
        assert ours["angle"] <= max(theirs["angle"], ANGLE)
    # The fillet's curvature jumps by 1/r across its edges; the G2 blend's by rounding.
    assert min(t["curvature_jump_across"] for t in occt) > 0.5
    assert max(e["curvature_jump"] for e in report2.errors) < 1e-6


def test_continuity_per_side_g2_on_one_edge_g1_on_the_other():
    """("G2", "G1"): G2 along edge a, G1 along edge b, a quartic across (3 rows set by side a, 2 by
    side b). OCCT's referee: side a within every tolerance; side b in position and normal, and its
    curvature across is the blend's own (the cylinder's is 0 along its generator, the blend's is
    not), so it is G1 there and no more. Swapped, the roles swap."""
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.5, 2.0, 1.0)
    ea, eb = _rim(a, 1.0), _rim(b, 2.0)
    for pair in (("G2", "G1"), ("G1", "G2")):
        blend, report = fw.blend_faces(a, ea, b, eb, continuity=pair)
        assert blend.VDegree == 4, pair
        assert [side["continuity"] for side in report.sides] == [2 if g == "G2" else 1 for g in pair]
        assert report.valid and blend.toShape().isValid()
        for g, errors in zip(pair, report.errors):
            assert errors["samples"] == 101 and errors["gap"] <= GAP and errors["angle"] <= ANGLE, (pair, errors)
            if g == "G2":
                assert errors["curvature_jump_across"] <= CURVATURE, (pair, errors)
            else:
                assert errors["curvature_jump_across"] > 1e-3, (pair, errors)
    # A fitted side takes its own continuity: G1 fits position and normal only, G2 the normal
    # curvature too (the plane's, 0, within the tolerance by OCCT's referee).
    holed, circle = _holed_plane()
    tube = Part.makeCylinder(0.3, 1.0, V(1, 1, 1), V(0, 0, 1)).Faces[0]
    for pair in (("G1", "G2"), ("G2", "G1")):
        blend, report = fw.blend_faces(holed, circle, tube, _rim(tube, 1.0), continuity=pair)
        side = report.sides[0]
        assert side["method"] == "fitted" and side["continuity"] == (2 if pair[0] == "G2" else 1), side
        for g, errors in zip(pair, report.errors):
            assert errors["gap"] <= GAP and errors["angle"] <= ANGLE, (pair, errors)
            assert g == "G1" or errors["curvature_jump_across"] <= CURVATURE, (pair, errors)
    # One choice for both stays as it was: degree 5 (G2) and 3 (G1).
    assert fw.blend_faces(a, ea, b, eb, continuity="G2")[0].VDegree == 5
    assert fw.blend_faces(a, ea, b, eb, continuity="G1")[0].VDegree == 3
    for bad in (("G2",), ("G2", "G3"), ("G1", "G2", "G2")):
        with pytest.raises(fw.InputError, match="continuity"):
            fw.blend_faces(a, ea, b, eb, continuity=bad)


# ---- fitted sides: trimmed edges, seams, mismatched parametrisations --------------------------------------


def _check_fitted(blend, report, fitted, g2=True):
    """The issue's tolerances at 101 points of each edge (OCCT's referee, _check), the report's method
    per side, and, for each fitted side, the fit's own worst misfit between its samples within a
    tenth of the tolerances."""
    _check(blend, report, g2=g2)
    for side, expected in zip(report.sides, fitted):
        assert side["method"] == ("fitted" if expected else "exact"), side
        if expected:
            assert side["reason"] and side["spans"] >= 1 and side["samples"] > side["spans"], side
            assert side["fit_gap"] <= GAP and side["fit_angle"] <= ANGLE, side
            assert not g2 or side["fit_curvature"] <= CURVATURE, side


def _leaves_the_face(blend, face, s):
    """The blend leaves the face: its points a little way in from the edge (v = s +- 0.05) lie off the
    face by more than 1e-3 of the face's size (a blend that folded back over the face would not)."""
    size = face.BoundBox.DiagonalLength
    inner = 0.05 if s == 0.0 else 0.95
    for u in np.linspace(0.02, 0.98, 7):
        d = face.distToShape(Part.Vertex(blend.value(float(u), inner)))[0]
        assert d > 1e-3 * size, (u, d)


def _holed_plane():
    plane = Part.makePlane(2, 2)
    disc = Part.Face(Part.Wire(Part.makeCircle(0.5, V(1, 1, 0))))
    trimmed = plane.cut(disc).Faces[0]
    return trimmed, _edge_at(trimmed, lambda e: e.Curve.__class__.__name__ == "Circle")


def test_curved_edge_of_a_boolean_plane_is_fitted_g2_to_a_cylinder():
    """A plane with a hole cut by Part's boolean: its circle is no isoline of the plane. The blend
    leaves the hole's rim in the plane and rises into a narrower cylinder above it, G2 and G1."""
    holed, circle = _holed_plane()
    tube = Part.makeCylinder(0.3, 1.0, V(1, 1, 1), V(0, 0, 1)).Faces[0]
    for continuity in ("G2", "G1"):
        blend, report = fw.blend_faces(holed, circle, tube, _rim(tube, 1.0), continuity=continuity)
        _check_fitted(blend, report, (True, False), g2=continuity == "G2")
        assert report.sides[0]["surface_type"] == "Plane" and "plane" in report.sides[0]["reason"]
        _leaves_the_face(blend, holed, 0.0)
    assert report.sides[0]["closed"]
    assert blend.value(0.0, 0.5).distanceToPoint(blend.value(1.0, 0.5)) < 1e-7


def _floor():
    return _bspline_face(_wavy(7, 5, 0.0, 0.08), 3, 3, [0.25, 0.5, 0.75], [0.5])


def _slanted_prism():
    """The half space y > 0.4 + 0.2 x (in x, z within the floor's box), as a solid."""
    poly = Part.makePolygon([V(-1, 0.2, -1), V(3, 1.0, -1), V(3, 3, -1), V(-1, 3, -1), V(-1, 0.2, -1)])
    return Part.Face(poly).extrude(V(0, 0, 2))


def _flip_for(edge_a, edge_b):
    """flip so that the two edges' parameters run the same way in space."""
    a0, b0, b1 = edge_a.valueAt(edge_a.FirstParameter), edge_b.valueAt(edge_b.FirstParameter), \
        edge_b.valueAt(edge_b.LastParameter)
    return (a0 - b1).Length < (a0 - b0).Length


def test_trimmed_bspline_faces_cut_by_a_boolean_are_fitted_on_both_sides():
    """Two bicubic B-spline faces cut along a slanted line by Part's cut and common: their cut edges
    cross the faces' knot lines and parameter rectangles (the pcurves are B-splines of OCCT's
    intersection). The blend steps from one to the other, G2 along the whole of both edges."""
    floor, prism = _floor(), _slanted_prism()
    low = floor.cut(prism).Faces[0]
    high = floor.common(prism).Faces[0].translated(V(0, 0.3, 0.8))

    def slanted(e):  # the cut edge: neither x nor y constant along it
        p, q = e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)
        return abs(p.x - q.x) > 0.5 and abs(p.y - q.y) > 0.1

    edge_a, edge_b = _edge_at(low, slanted), _edge_at(high, slanted)
    blend, report = fw.blend_faces(low, edge_a, high, edge_b, flip=_flip_for(edge_a, edge_b))
    _check_fitted(blend, report, (True, True))
    _leaves_the_face(blend, low, 0.0)
    _leaves_the_face(blend, high, 1.0)
    assert all("trimmed" in side["reason"] for side in report.sides)
    # Wavy faces: 3 to 5 curvature extrema per section, as the bench's exact ones (FACE_BLENDS.md section 8).
    assert max(_section_extrema(blend, u) for u in np.linspace(0, 1, 9)) <= 5


def test_curved_plane_edge_with_uneven_speed_meets_an_exact_side():
    """Mismatched parametrisations: a plane bounded by a wavy B-spline whose speed varies more than twofold
    along it (uneven knots), blended to the exact isoparametric edge of a B-spline wall."""
    wave = Part.BSplineCurve()
    poles = [V(0, 0, 0), V(0.1, 0.05, 0), V(0.3, -0.05, 0), V(1.0, 0.1, 0), V(1.6, -0.05, 0), V(2.0, 0, 0)]
    wave.buildFromPolesMultsKnots(poles, [4, 1, 1, 4], [0.0, 0.1, 0.2, 1.0], False, 3)
    edge = wave.toShape()
    wire = Part.Wire([edge, Part.makeLine(V(2, 0, 0), V(2, -1, 0)), Part.makeLine(V(2, -1, 0), V(0, -1, 0)),
                      Part.makeLine(V(0, -1, 0), V(0, 0, 0))])
    plane = Part.Face(wire)
    wavy = _edge_at(plane, lambda e: e.Curve.__class__.__name__ == "BSplineCurve")
    wall = _bspline_face(_wavy(6, 4, 0.6, 0.1, y0=0.6), 3, 3, [0.4, 0.7], [])
    rim = _edge_at(wall, lambda e: abs(e.CenterOfMass.y - 0.6) < 1e-9)
    speeds = [wavy.derivative1At(wavy.FirstParameter + f * (wavy.LastParameter - wavy.FirstParameter)).Length
              for f in np.linspace(0, 1, 41)]
    assert max(speeds) > 2 * min(speeds)
    blend, report = fw.blend_faces(plane, wavy, wall, rim)
    _check_fitted(blend, report, (True, False))
    _leaves_the_face(blend, plane, 0.0)


def test_seam_of_a_cylinder_is_fitted():
    """The seam line of a whole cylinder's face (the face on both sides of it): fitted from the side
    the edge's orientation gives, G2 to a plane strip beside it."""
    tube = _cylinder(1.0, 0.0, 1.0)
    seam = _edge_at(tube, lambda e: e.Curve.__class__.__name__ == "Line")
    results = []
    for sign in (1.0, -1.0):
        strip = Part.Face(Part.makePolygon([V(1.6, sign * 0.8, 0), V(1.6, sign * 1.6, 0), V(1.6, sign * 1.6, 1),
                                            V(1.6, sign * 0.8, 1), V(1.6, sign * 0.8, 0)]))
        near = _edge_at(strip, lambda e: abs(abs(e.CenterOfMass.y) - 0.8) < 1e-9 and abs(e.CenterOfMass.z - 0.5) < 1e-9)
        try:
            results.append(fw.blend_faces(tube, seam, strip, near, flip=_flip_for(seam, near)))
        except fw.InputError as exc:
            assert "cross itself" in str(exc)
    assert results
    for blend, report in results:
        _check_fitted(blend, report, (True, False))
        assert "seam" in report.sides[0]["reason"]


# ---- bad input -------------------------------------------------------------------------------------------


def test_bad_input_names_the_problem():
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.5, 2.0, 1.0)
    with pytest.raises(fw.InputError, match="edge_a is not an edge of face_a"):
        fw.blend_faces(a, _rim(b, 2.0), b, _rim(b, 2.0))
    box = Part.makeBox(1, 1, 1)
    f1, f2 = box.Faces[0], [f for f in box.Faces if any(e.isSame(box.Faces[0].Edges[0]) for e in f.Edges)
                            and not f.isSame(box.Faces[0])][0]
    shared = box.Faces[0].Edges[0]
    with pytest.raises(fw.InputError, match="faces touch"):
        fw.blend_faces(f1, shared, f2, shared)
    sphere = Part.makeSphere(1.0).Faces[0]
    pole = [i + 1 for i, e in enumerate(sphere.Edges) if e.Length < 1e-12][0]
    with pytest.raises(fw.InputError, match="degenerate"):
        fw.blend_faces(sphere, pole, b, _rim(b, 2.0))
    with pytest.raises(fw.InputError, match="continuity"):
        fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0), continuity="G3")
    with pytest.raises(fw.InputError, match="start and end"):
        fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0), start=0.6, end=0.4)
    with pytest.raises(fw.InputError, match="edge_b is edge 9"):
        fw.blend_faces(a, _rim(a, 1.0), b, 9)
    with pytest.raises(fw.InputError, match="face_a must be"):
        fw.blend_faces("face", 1, b, 1)


def test_crossing_blend_is_refused():
    """Edges that run opposite ways make the sections cross: refused, never returned."""
    a = _bspline_face(_wavy(6, 4, 0.0, 0.0), 3, 3, [0.3, 0.6], [])
    b = _bspline_face(_wavy(6, 4, 0.0, 0.0, y0=1.2)[::-1], 3, 3, [0.3, 0.6], [])
    edge_a = _edge_at(a, lambda e: abs(e.CenterOfMass.y - 1.0) < 1e-9)
    edge_b = _edge_at(b, lambda e: abs(e.CenterOfMass.y - 1.2) < 1e-9)
    with pytest.raises(fw.InputError, match="cross itself"):
        fw.blend_faces(a, edge_a, b, edge_b)
    blend, report = fw.blend_faces(a, edge_a, b, edge_b, flip=True)
    _check(blend, report)


def _curve_extrema(curve, n=600):
    """Interior extrema of a Part curve's curvature (OCCT's curvature at n + 1 points)."""
    a, b = curve.FirstParameter, curve.LastParameter
    k = np.array([curve.curvature(a + (b - a) * i / n) for i in range(n + 1)])
    d = np.diff(k)
    d = d[np.abs(d) > 1e-9 * max(k.max(), 1e-300)]
    return int(np.sum(np.sign(d[1:]) != np.sign(d[:-1])))


def test_no_wave_along_the_edges_that_the_edges_do_not_have():
    """Along the edges the blend waves no more than the edges do: every isoline v = const (a
    curve from one end of the blend to the other, as OCCT's vIso gives it) has at most as many
    curvature extrema as the edge with more. A wavy floor's edge (7) into a wall's straight
    bottom edge (0); two offset cylinders' rims (circles, 0: the isolines stay circles). The
    count sees a wave: one middle pole of the cylinders' blend moved out by 1 % of its size."""
    from tests.scenes import wavy_floor_and_wall

    doc = FreeCAD.newDocument("NoWave")
    try:
        floor, edge_f, wall, edge_w = wavy_floor_and_wall(doc)
        ea, eb = floor.Shape.getElement(edge_f), wall.Shape.getElement(edge_w)
        wavy, _ = fw.blend_faces(floor.Shape.Faces[0], ea, wall.Shape.Faces[0], eb)
        edges = max(_curve_extrema(e.Curve.trim(e.FirstParameter, e.LastParameter)) for e in (ea, eb))
        assert edges == 7
        counts = [_curve_extrema(wavy.vIso(float(v))) for v in np.linspace(0.0, 1.0, 11)]
        assert max(counts) <= edges, counts
    finally:
        FreeCAD.closeDocument(doc.Name)
    a, b = _cylinder(1.0, 0.0, 1.0), _cylinder(1.0, 2.0, 1.0, x=0.4)
    blend, _ = fw.blend_faces(a, _rim(a, 1.0), b, _rim(b, 2.0))
    assert [_curve_extrema(blend.vIso(float(v))) for v in np.linspace(0.0, 1.0, 11)] == [0] * 11
    # The referee sees a wave: one middle pole moved out by 1 % of the blend's size.
    waved = blend.copy()
    i, j = waved.NbUPoles // 2, waved.NbVPoles // 2
    pole = waved.getPole(i + 1, j + 1)
    out = V(pole.x, pole.y, 0).normalize() * 0.01 * blend.toShape().BoundBox.DiagonalLength
    waved.setPole(i + 1, j + 1, pole + out)
    assert _curve_extrema(waved.vIso(0.5)) > 0
