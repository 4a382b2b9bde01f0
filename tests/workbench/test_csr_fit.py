"""The csr fit feature, headless: sources, recompute, save/reopen, undo and error state."""
import math

import numpy as np
import pytest

import FreeCAD
import Part
import Points
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

from tests.scenes import assert_failed_like_freecad
import freecad_workbench as fw
from freecad_workbench.features.csr_fit import CsrFit, collect_points, make_csr_fit

DATA = [(0, 0, 0), (10, 8, 0), (20, 11, 0), (30, 9, 0), (40, 2, 0), (50, 0, 0)]


def poles(curve_or_obj):
    curve = curve_or_obj.Shape.Edges[0].Curve if hasattr(curve_or_obj, "Shape") else curve_or_obj
    return np.array([tuple(p) for p in curve.getPoles()])


def vertices(doc, data=DATA):
    objs = []
    for x, y, z in data:
        v = doc.addObject("Part::Vertex", "V")
        v.X, v.Y, v.Z = x, y, z
        objs.append(v)
    doc.recompute()
    return objs


def test_fit_of_vertices_is_the_csr_spline_of_their_points(doc):
    fit = make_csr_fit(doc, vertices(doc))
    assert fit.Status == "ok"
    assert type(fit.Proxy).__module__ + "." + type(fit.Proxy).__name__ == "freecad_workbench.features.csr_fit.CsrFit"
    assert fit.Shape.isValid() and len(fit.Shape.Edges) == 1
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(DATA)))
    assert fit.Shape.Edges[0].Curve.Continuity == "C2"
    assert fit.getEditorMode("Status") == ["ReadOnly"] and fit.getEditorMode("Version") == ["Hidden"]


def test_sources_keep_their_order_across_objects(doc):
    wire = doc.addObject("Part::Feature", "Wire")
    wire.Shape = Part.makePolygon([FreeCAD.Vector(*p) for p in DATA[:3]])
    extra = vertices(doc, DATA[3:])
    fit = make_csr_fit(doc, [(wire, ["Vertex1", "Vertex2"]), extra[0], (wire, "Vertex3")] + extra[1:])
    expected = [DATA[0], DATA[1], DATA[3], DATA[2], DATA[4], DATA[5]]
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(expected)))


def test_fit_of_points_object_uses_its_placed_points(doc):
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in DATA])
    cloud.Placement = FreeCAD.Placement(FreeCAD.Vector(5, -3, 7), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))
    doc.recompute()
    fit = make_csr_fit(doc, [cloud], parametrization="centripetal")
    placed = [cloud.Placement.multVec(FreeCAD.Vector(*p)) for p in DATA]
    assert fit.Status == "ok"
    np.testing.assert_allclose(poles(fit), poles(fw.csr_spline(placed, parametrization="centripetal")), atol=1e-12)


def test_fit_of_sketch_uses_its_point_geometries_in_order_placed(doc):
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    sketch.addGeometry(Part.LineSegment(FreeCAD.Vector(0, -20, 0), FreeCAD.Vector(50, -20, 0)))  # not a point: ignored
    for i, (x, y, _) in enumerate(DATA):
        sketch.addGeometry(Part.Point(FreeCAD.Vector(x, y, 0)), i % 2 == 1)  # construction or not
    sketch.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 10), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))
    doc.recompute()
    fit = make_csr_fit(doc, [sketch])
    placed = [sketch.Placement.multVec(FreeCAD.Vector(x, y, 0)) for x, y, _ in DATA]
    assert fit.Status == "ok"
    np.testing.assert_allclose(poles(fit), poles(fw.csr_spline(placed)), atol=1e-12)


def test_sketch_without_points_is_an_error(doc):
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    sketch.addGeometry(Part.LineSegment(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(5, 0, 0)))
    doc.recompute()
    fit = make_csr_fit(doc, [sketch])
    assert "has no points" in fit.Status


def test_fit_of_edge_samples_it_equally_in_arc_length(doc):
    arc = doc.addObject("Part::Feature", "Arc")
    arc.Shape = Part.Edge(Part.Arc(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(20, 15, 0), FreeCAD.Vector(40, 0, 0)))
    fit = make_csr_fit(doc, [(arc, "Edge1")], samples=30)
    samples = arc.Shape.Edges[0].discretize(Number=30)
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(samples)))
    fit.Samples = 12
    doc.recompute()
    direct = fw.csr_spline(arc.Shape.Edges[0].discretize(Number=12))
    assert len(fit.Shape.Edges[0].Curve.getPoles()) == len(direct.getPoles())
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(arc.Shape.Edges[0].discretize(Number=12))))


def test_edges_picked_in_any_direction_are_joined_without_repeating_points(doc):
    corners = [FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 0, 0), FreeCAD.Vector(10, 10, 0), FreeCAD.Vector(20, 15, 0)]
    wire = doc.addObject("Part::Feature", "Wire")
    wire.Shape = Part.makePolygon(corners)
    doc.recompute()
    # Edge2 then Edge1: Edge2 is turned to end where Edge1 begins, Edge1 turned to continue it,
    # the shared corner taken once; Edge3 does not touch the end and is appended as it is.
    points, origins = collect_points([(wire, ("Edge2", "Edge1", "Edge3"))], samples=3)
    expected = [corners[2], FreeCAD.Vector(10, 5, 0), corners[1], FreeCAD.Vector(5, 0, 0), corners[0]]
    assert [tuple(p) for p in points[:5]] == pytest.approx([tuple(p) for p in expected])
    assert [tuple(p) for p in points[5:]] == pytest.approx([(10, 10, 0), (15, 12.5, 0), (20, 15, 0)])
    assert origins == ["Wire.Edge2"] * 3 + ["Wire.Edge1"] * 2 + ["Wire.Edge3"] * 3


def test_whole_wire_object_is_sampled_along_the_wire(doc):
    corners = [FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 0, 0), FreeCAD.Vector(10, 10, 0)]
    wire = doc.addObject("Part::Feature", "Wire")
    wire.Shape = Part.makePolygon(corners)
    doc.recompute()
    fit = make_csr_fit(doc, [wire], samples=21)
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(wire.Shape.Wires[0].discretize(Number=21))))


def test_closed_fit_of_a_closed_edge_leaves_out_the_repeated_end(doc):
    circle = doc.addObject("Part::Circle", "Circle")
    circle.Radius = 10
    doc.recompute()
    fit = make_csr_fit(doc, [(circle, "Edge1")], closed=True, samples=40)
    assert fit.Status == "ok"
    curve = fit.Shape.Edges[0].Curve
    assert curve.isPeriodic() and fit.Shape.Edges[0].isClosed()
    assert fw.max_distance(curve, circle.Shape.Edges[0].discretize(Number=40)) < 0.05


def test_moving_a_source_vertex_changes_the_fit_on_recompute(doc):
    objs = vertices(doc)
    fit = make_csr_fit(doc, objs)
    before = poles(fit)
    objs[2].Y = 20
    doc.recompute()
    after = poles(fit)
    assert not np.allclose(before, after)
    moved = list(DATA)
    moved[2] = (20, 20, 0)
    np.testing.assert_array_equal(after, poles(fw.csr_spline(moved)))


def test_parameter_changes_recompute(doc):
    fit = make_csr_fit(doc, vertices(doc))
    fit.Parametrization = "uniform"
    doc.recompute()
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(DATA, parametrization="uniform")))
    fit.Closed = True
    doc.recompute()
    assert fit.Shape.Edges[0].Curve.isPeriodic()


def line_and_arc(doc, radius=2e4, length=30.0):
    """A wire of a straight edge ending at the origin and a gently bent arc tangent to it
    there (curvature * size = 60 / radius = 3e-3, between the Epsilon values used)."""
    line = Part.LineSegment(FreeCAD.Vector(-length, 0, 0), FreeCAD.Vector(0, 0, 0))
    circle = Part.Circle(FreeCAD.Vector(0, radius, 0), FreeCAD.Vector(0, 0, 1), radius)
    arc = Part.ArcOfCircle(circle, -math.pi / 2, -math.pi / 2 + length / radius)
    wire = doc.addObject("Part::Feature", "LineArc")
    wire.Shape = Part.Wire([line.toShape(), arc.toShape()])
    doc.recompute()
    return wire


def test_epsilon_change_recomputes_with_the_new_tolerance(doc):
    wire = line_and_arc(doc)
    fit = make_csr_fit(doc, [(wire, ("Edge1", "Edge2"))], samples=31)
    before = poles(fit)
    fit.Epsilon = 1e-2
    doc.recompute()
    assert fit.Status == "ok"
    # Measured: the poles near the join move by 4.2e-6 (the case rule takes mu = nu = 1/2
    # where line meets arc once epsilon/size exceeds the arc's curvature).
    assert np.abs(poles(fit) - before).max() > 4e-7
    points, _ = collect_points(fit.Sources, fit.Samples)
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(points, epsilon=1e-2)))


def test_save_close_reopen_recompute_gives_identical_poles(doc, tmp_path):
    fit = make_csr_fit(doc, vertices(doc), parametrization="centripetal", epsilon=1e-6)
    before = poles(fit)
    path = str(tmp_path / "fit.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        fit = reopened.getObject("CsrFit")
        assert isinstance(fit.Proxy, CsrFit)
        assert (fit.Parametrization, fit.Epsilon, fit.Version, fit.Status) == (
            "centripetal", 1e-6, CsrFit.VERSION, "ok")
        # as stored: FreeCAD writes the shape's BREP with 16 digits, so the last bit may differ
        np.testing.assert_allclose(poles(fit), before, rtol=1e-15, atol=1e-15)
        fit.touch()
        reopened.recompute()
        assert fit.Status == "ok"
        np.testing.assert_array_equal(poles(fit), before)  # as recomputed: bit for bit
        reopened.getObject(fit.Sources[2][0].Name).Y = 30  # the links survived
        reopened.recompute()
        assert not np.allclose(poles(fit), before)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_curvature_tolerance_shows_epsilon_readably_and_sets_it(doc):
    wire = line_and_arc(doc)
    fit = make_csr_fit(doc, [(wire, ("Edge1", "Edge2"))], samples=31)
    assert fit.CurvatureTolerance == "1e-09" and fit.Epsilon == 1e-9  # the property editor showed 0.00
    assert fit.getEditorMode("Epsilon") == ["Hidden"] and fit.getEditorMode("CurvatureTolerance") == []
    fit.CurvatureTolerance = "1e-2"
    doc.recompute()
    assert fit.Epsilon == 1e-2 and fit.Status == "ok"
    points, _ = collect_points(fit.Sources, fit.Samples)
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(points, epsilon=1e-2)))
    fit.Epsilon = 1e-6  # a macro sets the number: the text follows
    assert fit.CurvatureTolerance == "1e-06"
    fit.CurvatureTolerance = "small"
    doc.recompute()
    assert_failed_like_freecad(fit, "CurvatureTolerance is not a number: 'small'")


def test_samples_shows_only_where_an_edge_is_sampled(doc):
    fit = make_csr_fit(doc, vertices(doc))
    assert fit.getEditorMode("Samples") == ["Hidden"]  # points are taken as they are
    wire = line_and_arc(doc)
    fit.Sources = [(wire, ["Edge1", "Edge2"])]
    doc.recompute()
    assert fit.getEditorMode("Samples") == []


def test_old_document_without_new_properties_loads_and_migrates(doc, tmp_path):
    fit = make_csr_fit(doc, vertices(doc), epsilon=1e-7)
    for name in ("Version", "Status", "Samples", "CurvatureTolerance"):
        fit.removeProperty(name)
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        fit = reopened.getObject("CsrFit")
        assert (fit.Version, fit.Status, fit.Samples) == (CsrFit.VERSION, "ok", 50)
        assert fit.CurvatureTolerance == "1e-07" and fit.Epsilon == 1e-7
        fit.touch()
        reopened.recompute()
        assert fit.Status == "ok" and len(fit.Shape.Edges) == 1
    finally:
        FreeCAD.closeDocument(reopened.Name)


def undoable_vertices(doc):
    """The source vertices in a document with undo on, their creation one committed step."""
    doc.UndoMode = 1
    objs = vertices(doc)
    doc.openTransaction("vertices")
    doc.commitTransaction()
    return objs


def test_undo_removes_the_created_feature_and_redo_restores_it(doc):
    objs = undoable_vertices(doc)
    count = len(doc.Objects)
    created = poles(make_csr_fit(doc, objs))
    assert len(doc.Objects) == count + 1
    assert doc.UndoNames[0] == "Create csr fit"
    doc.undo()
    assert len(doc.Objects) == count and doc.getObject("CsrFit") is None
    doc.redo()
    assert doc.getObject("CsrFit") is not None
    doc.recompute()
    fit = doc.getObject("CsrFit")
    assert fit.Status == "ok" and fit.Shape.isValid() and len(fit.Shape.Edges) == 1
    np.testing.assert_array_equal(poles(fit), created)


def test_undo_of_a_moved_source_point_restores_the_fit(doc):
    objs = undoable_vertices(doc)
    fit = make_csr_fit(doc, objs)
    before = poles(fit)
    doc.openTransaction("move")
    objs[2].Y = 20
    doc.commitTransaction()
    doc.recompute()  # outside the step: undo does not restore the shape, recompute must
    moved = poles(fit)
    assert not np.allclose(moved, before)
    doc.undo()
    doc.recompute()
    assert objs[2].Y == DATA[2][1] and fit.Status == "ok"
    np.testing.assert_array_equal(poles(fit), before)
    doc.redo()
    doc.recompute()
    np.testing.assert_array_equal(poles(fit), moved)


def test_undo_of_a_sources_change_restores_the_fit(doc):
    objs = undoable_vertices(doc)
    fit = make_csr_fit(doc, objs)
    before = poles(fit)
    doc.openTransaction("sources")
    fit.Sources = [(o, "") for o in objs[:4]]
    doc.commitTransaction()
    doc.recompute()
    np.testing.assert_array_equal(poles(fit), poles(fw.csr_spline(DATA[:4])))
    doc.undo()
    doc.recompute()
    assert [link[0] for link in fit.Sources] == objs and fit.Status == "ok"
    np.testing.assert_array_equal(poles(fit), before)


def _too_few(fit, objs):
    fit.Sources = [(o, "") for o in objs[:2]]


def _coincident_consecutive(fit, objs):
    objs[3].X, objs[3].Y = objs[2].X, objs[2].Y


def _all_coincide(fit, objs):
    for o in objs:
        o.X = o.Y = o.Z = 1.0


def _nan(fit, objs):
    objs[3].X = float("nan")


def _infinity(fit, objs):
    # FreeCAD's vertex shape turns this into (nan, inf, nan) (inf * 0 in its placement).
    objs[3].Y = float("inf")


BAD_INPUT = {
    "too few points": (_too_few, "the csr-spline needs at least 3 points, got 2"),
    "coincident consecutive points": (_coincident_consecutive, "points 2 and 3 coincide"),
    "all points coincide": (_all_coincide, "all points coincide"),
    "nan": (_nan, "point 3 is not finite (NaN or infinity)"),
    "infinity": (_infinity, "point 3 is not finite (NaN or infinity)"),
}


@pytest.mark.parametrize("case", sorted(BAD_INPUT))
def test_bad_input_puts_the_feature_in_error_state_and_keeps_last_good_shape(doc, case):
    break_it, message = BAD_INPUT[case]
    objs = vertices(doc)
    fit = make_csr_fit(doc, objs)
    good = poles(fit)
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()

    break_it(fit, objs)
    box.Length = 42
    doc.recompute()

    assert message in fit.Status, fit.Status
    assert fit.Status != "ok"
    np.testing.assert_array_equal(poles(fit), good)  # last good shape kept
    assert_failed_like_freecad(fit, message)
    assert box.Shape.BoundBox.XLength == pytest.approx(42)  # the rest of the document recomputed

    fit.Sources = [(o, "") for o in vertices(doc)]  # good data again
    doc.recompute()
    assert fit.Status == "ok"
    np.testing.assert_array_equal(poles(fit), good)


def test_coincident_points_message_names_their_sources(doc):
    objs = vertices(doc)
    objs[2].Label, objs[3].Label = "Left", "Right"
    objs[3].X, objs[3].Y = objs[2].X, objs[2].Y
    fit = make_csr_fit(doc, objs)
    assert fit.Status == "points 2 and 3 coincide (from Left and Right)"
    assert fit.Shape.isNull()  # never had a good shape


def test_deleted_source_is_an_error_not_a_crash(doc):
    objs = vertices(doc)
    fit = make_csr_fit(doc, objs)
    good = poles(fit)
    fit.Sources = [(objs[0], "Vertex1"), (objs[1], "Edge5"), (objs[2], "")]
    doc.recompute()
    assert fit.Status == f"{objs[1].Label}.Edge5 not found"
    np.testing.assert_array_equal(poles(fit), good)


def test_factory_rejects_unknown_parametrization(doc):
    with pytest.raises(fw.InputError, match="parametrization"):
        make_csr_fit(doc, vertices(doc), parametrization="affine")
    assert doc.getObject("CsrFit") is None
