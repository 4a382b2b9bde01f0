"""The BasicCurve feature, headless: each kind's dimensions give the curve they say
(checked on the OCCT geometry of the shape), placement, degrees, error state, save/reopen."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

from freecad_workbench.features.basic_curve import (
    KIND_DEFAULTS,
    KIND_PROPERTIES,
    KINDS,
    BasicCurveFeature,
    local_curve,
    make_basic_curve,
)
from tests.scenes import assert_failed_like_freecad
import freecad_workbench as fw

# The XZ plane through (1, 2, 3): the curve's x is global X, its y is global Z.
PLACEMENT = FreeCAD.Placement(FreeCAD.Vector(1, 2, 3), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))


def local_points(obj, n=101):
    """Points of the shape's edge (OCCT evaluation), in the placement's coordinates."""
    edge = obj.Shape.Edges[0]
    inverse = obj.Placement.inverse()
    params = np.linspace(edge.FirstParameter, edge.LastParameter, n)
    return np.array([tuple(inverse.multVec(edge.valueAt(float(t)))) for t in params])


def ends(obj):
    edge = obj.Shape.Edges[0]
    inverse = obj.Placement.inverse()
    return (np.array(tuple(inverse.multVec(edge.valueAt(edge.FirstParameter)))),
            np.array(tuple(inverse.multVec(edge.valueAt(edge.LastParameter)))))


def test_circle_arc_has_its_radius_and_angles_in_degrees(doc):
    arc = make_basic_curve(doc, "Circle arc", placement=PLACEMENT, Radius=7, StartAngle=30, EndAngle=120)
    assert arc.Status == "ok" and arc.Shape.isValid()
    assert str(arc.StartAngle) == "30.0 deg" and arc.EndAngle.Value == 120
    points = local_points(arc)
    np.testing.assert_allclose(np.linalg.norm(points[:, :2], axis=1), 7, rtol=1e-14)
    np.testing.assert_allclose(points[:, 2], 0, atol=1e-13)
    start, end = ends(arc)
    np.testing.assert_allclose(start, [7 * math.cos(math.radians(30)), 7 * math.sin(math.radians(30)), 0], atol=1e-13)
    np.testing.assert_allclose(end, [7 * math.cos(math.radians(120)), 7 * math.sin(math.radians(120)), 0], atol=1e-13)
    # placed in the XZ plane through (1, 2, 3): the curve's y is global Z
    p = arc.Shape.Edges[0].valueAt(arc.Shape.Edges[0].FirstParameter)
    assert p.y == pytest.approx(2.0, abs=1e-12) and p.z == pytest.approx(3 + 3.5, abs=1e-12)


def test_clockwise_arc_when_end_angle_is_below_start(doc):
    arc = make_basic_curve(doc, "Circle arc", Radius=5, StartAngle=90, EndAngle=0)
    start, end = ends(arc)
    np.testing.assert_allclose(start, [0, 5, 0], atol=1e-13)
    np.testing.assert_allclose(end, [5, 0, 0], atol=1e-13)


def test_ellipse_parabola_hyperbola_satisfy_their_equations(doc):
    ellipse = make_basic_curve(doc, "Ellipse arc", MajorRadius=8, MinorRadius=3, StartAngle=-40, EndAngle=200)
    p = local_points(ellipse)
    np.testing.assert_allclose((p[:, 0] / 8) ** 2 + (p[:, 1] / 3) ** 2, 1, rtol=1e-12)
    np.testing.assert_allclose(ends(ellipse)[1], [8 * math.cos(math.radians(200)), 3 * math.sin(math.radians(200)), 0],
                               atol=1e-12)

    parabola = make_basic_curve(doc, "Parabola arc", Focal=2.5, StartY=-4, EndY=6)
    p = local_points(parabola)
    np.testing.assert_allclose(p[:, 0], p[:, 1] ** 2 / 10, atol=1e-12)
    np.testing.assert_allclose([ends(parabola)[0][1], ends(parabola)[1][1]], [-4, 6], atol=1e-12)

    hyperbola = make_basic_curve(doc, "Hyperbola arc", MajorRadius=3, MinorRadius=2, StartParameter=-1,
                                 EndParameter=1.5)
    p = local_points(hyperbola)
    np.testing.assert_allclose((p[:, 0] / 3) ** 2 - (p[:, 1] / 2) ** 2, 1, rtol=1e-12, atol=1e-11)
    np.testing.assert_allclose(ends(hyperbola)[1], [3 * math.cosh(1.5), 2 * math.sinh(1.5), 0], atol=1e-12)


def test_spiral_radius_grows_by_the_pitch_per_turn(doc):
    spiral = make_basic_curve(doc, "Archimedean spiral", Radius=2, Pitch=4, StartAngle=45, Turns=1.5)
    assert spiral.Status == "ok"
    start, end = ends(spiral)
    theta0, theta1 = math.radians(45), math.radians(45) + 3 * math.pi
    np.testing.assert_allclose(start, [(2 + 4 * theta0 / (2 * math.pi)) * math.cos(theta0),
                                       (2 + 4 * theta0 / (2 * math.pi)) * math.sin(theta0), 0], atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(end), 2 + 4 * theta1 / (2 * math.pi), rtol=1e-9)
    # every point of the shape: r = a + b * theta for its polar angle unwrapped along the curve
    p = local_points(spiral, 301)
    theta = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    theta += theta0 - theta[0]
    np.testing.assert_allclose(np.linalg.norm(p[:, :2], axis=1), 2 + 4 * theta / (2 * math.pi), atol=1e-7)


def test_involute_unrolls_from_its_base_circle(doc):
    involute = make_basic_curve(doc, "Circle involute", Radius=3, StartAngle=0, EndAngle=150)
    start, end = ends(involute)
    np.testing.assert_allclose(start, [3, 0, 0], atol=1e-12)
    t = math.radians(150)
    np.testing.assert_allclose(end, [3 * (math.cos(t) + t * math.sin(t)), 3 * (math.sin(t) - t * math.cos(t)), 0],
                               atol=1e-8)


def test_rational_cubic_is_its_rational_bezier(doc):
    poles = [FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(2, 4, 0), FreeCAD.Vector(6, 4, 0), FreeCAD.Vector(8, 0, 0)]
    weights = [1.0, 0.5, 2.0, 1.0]
    cubic = make_basic_curve(doc, "Rational cubic", Poles=poles, Weights=weights)
    curve = cubic.Shape.Edges[0].Curve
    reference = Part.BezierCurve()
    reference.setPoles(poles)
    for i, w in enumerate(weights, start=1):
        reference.setWeight(i, w)
    for u in np.linspace(0, 1, 11):
        t = curve.FirstParameter + u * (curve.LastParameter - curve.FirstParameter)
        # equal as point sets: the closest point of the reference is on it
        p = curve.value(float(t))
        q = reference.value(reference.parameter(p))
        assert (p - q).Length < 1e-12


def test_line_segment_between_its_points_in_the_placement(doc):
    line = make_basic_curve(doc, "Line segment", placement=PLACEMENT, Start=FreeCAD.Vector(1, 1, 0),
                            End=FreeCAD.Vector(4, 5, 0))
    start, end = ends(line)
    np.testing.assert_allclose(start, [1, 1, 0], atol=1e-14)
    np.testing.assert_allclose(end, [4, 5, 0], atol=1e-14)


@pytest.mark.parametrize("kind", KINDS)
def test_every_kind_default_is_valid_and_matches_its_basic_curve(doc, kind):
    obj = make_basic_curve(doc, kind)
    assert obj.Status == "ok", obj.Status
    assert obj.Shape.isValid() and len(obj.Shape.Edges) == 1
    assert obj.Kind == kind and isinstance(obj.Proxy, BasicCurveFeature)
    curve = local_curve(obj)
    edge = obj.Shape.Edges[0]
    tolerance = 1e-10 * curve.size() if curve.exact else 1e-8 * curve.size()
    for u in np.linspace(0, 1, 21):
        assert edge.distToShape(Part.Vertex(curve.value(u)))[0] < tolerance
    # the property editor shows the kind's dimensions only
    for name in {p for props in KIND_PROPERTIES.values() for p in props}:
        assert obj.getEditorMode(name) == ([] if name in KIND_PROPERTIES[kind] else ["Hidden"]), name


def test_exact_curve_for_a_design_is_placed_where_the_shape_is(doc):
    arc = make_basic_curve(doc, "Ellipse arc", placement=PLACEMENT)
    curve = arc.Proxy.basic_curve(arc)
    edge = arc.Shape.Edges[0]
    for u in np.linspace(0, 1, 11):
        assert edge.distToShape(Part.Vertex(curve.value(u)))[0] < 1e-12 * curve.size()
    group = doc.addObject("App::Part", "Group")
    group.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 50), FreeCAD.Rotation())
    group.addObject(arc)
    doc.recompute()
    moved = arc.Proxy.basic_curve(arc)
    assert (moved.value(0.3) - curve.value(0.3) - FreeCAD.Vector(0, 0, 50)).Length < 1e-12


@pytest.mark.parametrize("kind, change, message", [
    ("Circle arc", dict(Radius=0), "degenerate circle arc"),
    ("Line segment", dict(End=FreeCAD.Vector(0, 0, 0), Start=FreeCAD.Vector(0, 0, 0)), "Start and End coincide"),
    ("Archimedean spiral", dict(Turns=0), "Turns must be positive"),
    ("Rational cubic", dict(Weights=[1, -1, 1, 1]), "weights of a rational cubic must be positive"),
    ("Hyperbola arc", dict(StartParameter=1, EndParameter=1), "hyperbola"),
])
def test_bad_dimensions_keep_the_last_good_shape_and_say_why(doc, kind, change, message):
    obj = make_basic_curve(doc, kind)
    good = local_points(obj)
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    for key, value in change.items():
        setattr(obj, key, value)
    box.Length = 42
    doc.recompute()
    assert message in obj.Status, obj.Status
    np.testing.assert_array_equal(local_points(obj), good)  # last good shape kept
    assert_failed_like_freecad(obj, message)
    assert box.Shape.BoundBox.XLength == pytest.approx(42)
    for key, value in KIND_DEFAULTS[kind].items():
        setattr(obj, key, value)
    doc.recompute()
    assert obj.Status == "ok"


def test_factory_rejects_unknown_kinds_and_dimensions(doc):
    with pytest.raises(fw.InputError, match="unknown kind"):
        make_basic_curve(doc, "Clothoid")
    with pytest.raises(fw.InputError, match="Circle arc has no dimension Focal"):
        make_basic_curve(doc, "Circle arc", Focal=3)
    assert not doc.Objects


def test_save_and_reopen_keep_kind_dimensions_and_shape(doc, tmp_path):
    obj = make_basic_curve(doc, "Archimedean spiral", placement=PLACEMENT, Radius=1, Pitch=3, StartAngle=10,
                           Turns=2.25)
    poles = [tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()]
    name = obj.Name
    path = str(tmp_path / "basic.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        obj = reopened.getObject(name)
        assert isinstance(obj.Proxy, BasicCurveFeature)
        assert (obj.Kind, obj.Radius.Value, obj.Pitch.Value, obj.StartAngle.Value, obj.Turns) == (
            "Archimedean spiral", 1.0, 3.0, 10.0, 2.25)
        assert obj.getEditorMode("Focal") == ["Hidden"]
        obj.touch()
        reopened.recompute()
        assert obj.Status == "ok"
        assert [tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()] == poles
    finally:
        FreeCAD.closeDocument(reopened.Name)
