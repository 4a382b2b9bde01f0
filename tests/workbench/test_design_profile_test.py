"""Profile test, headless: the exact surface of revolution of a profile (judged by OCCT
evaluation), its default axis, recompute, error state, save/reopen; and the zebra mesh
and stripes the GUI shows it with."""
import math

import numpy as np
import pytest

import FreeCAD
import Part
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

import freecad_workbench as fw
from freecad_workbench.features.basic_curve import make_basic_curve
from freecad_workbench.features.design_spline import make_design_spline, set_marks
from freecad_workbench.features.profile_test import ProfileTest, make_profile_test
from freecad_workbench.gui.zebra import MIN_PER_SPAN, _span_samples, stripe_image, zebra_mesh

V = FreeCAD.Vector
XZ = FreeCAD.Rotation(V(1, 0, 0), 90)


@pytest.fixture
def profile(doc):
    """Fig. 14: a line touching a quarter circle, in the XZ plane, designed into one C2 curve."""
    line = make_basic_curve(doc, "Line segment", placement=FreeCAD.Placement(V(), XZ), Start=V(20, 0, 0),
                            End=V(20, 10, 0))
    arc = make_basic_curve(doc, "Circle arc", placement=FreeCAD.Placement(V(15, 0, 10), XZ), Radius=5,
                           StartAngle=0, EndAngle=90)
    return make_design_spline(doc, [(line, [0.3, 0.6, 0.9]), (arc, [0.1, 0.3, 0.6, 0.9])])


def arrays(surface):
    return (np.array([[tuple(p) for p in row] for row in surface.getPoles()]), np.array(surface.getWeights()),
            np.array(surface.getUKnots()), np.array(surface.getVKnots()))


def test_surface_is_the_exact_revolution_of_the_profile_about_z(doc, profile):
    test = make_profile_test(doc, profile)
    assert test.Status == "ok" and isinstance(test.Proxy, ProfileTest)
    assert tuple(test.AxisPoint) == (0, 0, 0) and tuple(test.AxisDirection) == (0, 0, 1)
    assert test.Shape.isValid() and len(test.Shape.Faces) == 1
    surface = test.Shape.Faces[0].Surface
    for x, y in zip(arrays(surface), arrays(fw.revolve_profile(profile.Shape.Edges[0], V(), V(0, 0, 1)))):
        np.testing.assert_array_equal(x, y)
    # every point: as far from the axis and as high as a point of the profile
    edge = profile.Shape.Edges[0]
    u0, u1, v0, v1 = surface.bounds()
    for u in np.linspace(u0, u1, 17):
        base = surface.value(float(u), v0)
        assert edge.distToShape(Part.Vertex(base))[0] < 1e-12 * 20
        radius = math.hypot(base.x, base.y)
        for v in np.linspace(v0, v1, 13):
            p = surface.value(float(u), float(v))
            assert abs(math.hypot(p.x, p.y) - radius) < 1e-12 * 20 and abs(p.z - base.z) < 1e-12 * 20


def test_default_axis_of_a_sketch_edge_is_the_sketch_vertical_axis(doc):
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    sketch.Placement = FreeCAD.Placement(V(3, 4, 5), FreeCAD.Rotation(V(0, 0, 1), 30))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(10, 0, 0), V(0, 0, 1), 4), -1.0, 1.0))
    doc.recompute()
    test = make_profile_test(doc, (sketch, "Edge1"))
    assert test.Status == "ok"
    np.testing.assert_allclose(tuple(test.AxisPoint), (3, 4, 5), atol=1e-12)
    np.testing.assert_allclose(tuple(test.AxisDirection), (-math.sin(math.radians(30)), math.cos(math.radians(30)), 0),
                               atol=1e-12)


def test_default_axis_of_a_profile_across_z_lies_in_its_plane(doc):
    arc = make_basic_curve(doc, "Circle arc", placement=FreeCAD.Placement(V(10, 0, 0), FreeCAD.Rotation()), Radius=3,
                           StartAngle=-60, EndAngle=60)
    test = make_profile_test(doc, arc)
    assert test.Status == "ok"
    assert tuple(test.AxisDirection) == pytest.approx((0, 1, 0), abs=1e-12)
    given = make_profile_test(doc, arc, axis_point=V(0, 0, 0), axis_direction=V(1, 1, 0), name="Given")
    assert tuple(given.AxisDirection) == (1, 1, 0)


def test_surface_follows_profile_and_axis(doc, profile):
    test = make_profile_test(doc, profile)
    first = arrays(test.Shape.Faces[0].Surface)[0]
    set_marks(profile, [[0.5], [0.2, 0.5, 0.8]])
    doc.recompute()
    second = arrays(test.Shape.Faces[0].Surface)
    assert second[0].shape != first.shape or not np.allclose(second[0], first)
    for x, y in zip(second, arrays(fw.revolve_profile(profile.Shape.Edges[0], V(), V(0, 0, 1)))):
        np.testing.assert_array_equal(x, y)
    test.AxisPoint = V(-5, 0, 0)
    doc.recompute()
    for x, y in zip(arrays(test.Shape.Faces[0].Surface),
                    arrays(fw.revolve_profile(profile.Shape.Edges[0], V(-5, 0, 0), V(0, 0, 1)))):
        np.testing.assert_array_equal(x, y)


def test_bad_axis_or_profile_keeps_the_last_good_surface(doc, profile):
    test = make_profile_test(doc, profile)
    good = arrays(test.Shape.Faces[0].Surface)[0]
    test.AxisDirection = V(0, 0, 0)
    doc.recompute()
    assert test.Status == "the axis direction must not be zero"
    np.testing.assert_array_equal(arrays(test.Shape.Faces[0].Surface)[0], good)
    test.AxisDirection = V(0, 0, 1)
    test.Profile = None
    doc.recompute()
    assert test.Status == "no profile"
    np.testing.assert_array_equal(arrays(test.Shape.Faces[0].Surface)[0], good)
    test.Profile = (profile, [])
    doc.recompute()
    assert test.Status == "ok"


def test_save_reopen_recompute_gives_the_identical_surface(doc, profile, tmp_path):
    test = make_profile_test(doc, profile)
    before = arrays(test.Shape.Faces[0].Surface)
    path = str(tmp_path / "profile.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        test = reopened.getObject("ProfileTest")
        assert isinstance(test.Proxy, ProfileTest)
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert test.Status == "ok"
        for x, y in zip(arrays(test.Shape.Faces[0].Surface), before):
            np.testing.assert_array_equal(x, y)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_zebra_mesh_has_the_surface_points_and_unit_normals(doc, profile):
    surface = make_profile_test(doc, profile).Shape.Faces[0].Surface
    points, normals, quads, (nu, nv) = zebra_mesh(surface, u_samples=60, v_samples=32)
    assert points.shape == normals.shape == (nu * nv, 3) and quads.shape == ((nu - 1) * (nv - 1), 4)
    assert nu >= 60 and nv >= 32
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, rtol=1e-12)
    rng = np.random.default_rng(5)
    for k in rng.integers(0, len(points), 40):
        i, j = divmod(int(k), nv)
        # the normal is perpendicular to both partial derivatives at the point
        u, v = surface.parameter(V(*points[k]))
        du, dv = surface.getDN(u, v, 1, 0), surface.getDN(u, v, 0, 1)
        n = V(*normals[k])
        assert abs(n.dot(du)) < 1e-9 * du.Length and abs(n.dot(dv)) < 1e-9 * max(dv.Length, 1e-300)
    assert quads.max() == len(points) - 1


def test_mesh_rows_include_every_knot_and_split_spans_by_length():
    knots = [0.0, 0.0, 0.1, 0.12, 0.9, 1.0]
    u = _span_samples(knots, 100)
    assert all(np.isclose(u, k, rtol=0, atol=1e-15).any() for k in set(knots))
    assert np.all(np.diff(u) > 0)
    counts = [int(((u > a) & (u <= b)).sum()) for a, b in [(0, 0.1), (0.1, 0.12), (0.12, 0.9), (0.9, 1.0)]]
    assert counts == [10, MIN_PER_SPAN, 78, 10]


def test_stripe_image_has_the_asked_number_of_stripes():
    data, size = stripe_image(12, 256)
    image = np.frombuffer(data, dtype=np.uint8).reshape(size, size)
    assert set(np.unique(image)) == {0, 255}
    assert (np.diff(image[0].astype(int)) != 0).sum() == 2 * 12 - 1  # 12 white and 12 black bands
    assert (image == image[0]).all()  # vertical stripes
