"""The Design spline feature with sampled pieces (the unifying spline, csr paper Fig. 1),
headless: a Points object or a sketch of points as a piece next to a sketch's arc, turned to
meet end to start, recomputed when the points move, saved and reopened, and bad samples
reported in Status. Geometry is judged against fw.design_spline and by OCCT evaluation."""
import math

import numpy as np

import FreeCAD
import Part
import Points
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

import freecad_workbench as fw
from freecad_workbench.features.design_spline import get_marks, make_design_spline

V = FreeCAD.Vector
ARC_MARKS = [0.2, 0.4, 0.6, 0.8]


def quarter_samples(count=21):
    """Samples of a quarter circle of radius 2 about the origin, from (2, 0) to (0, 2)."""
    a = np.linspace(0.0, math.pi / 2, count)
    return [V(2 * math.cos(x), 2 * math.sin(x), 0) for x in a]


def arc_sketch(doc):
    """A quarter circle of radius 1 about (0, 1) from (0, 2) on to (-1, 1): it continues the
    samples where they end."""
    sketch = doc.addObject("Sketcher::SketchObject", "Arc")
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(0, 1, 0), V(0, 0, 1), 1), math.pi / 2, math.pi))
    doc.recompute()
    return sketch


def points_object(doc, vectors, name="Samples"):
    cloud = doc.addObject("Points::Feature", name)
    cloud.Points = Points.Points(vectors)
    doc.recompute()
    return cloud


def stored(cloud):
    """The points as the Points object keeps them (in single precision)."""
    return list(cloud.Points.Points)


def arrays(obj):
    curve = obj.Shape.Edges[0].Curve
    return (np.array([tuple(p) for p in curve.getPoles()]), np.array(curve.getWeights()),
            np.array(curve.getKnots()), np.array(curve.getMultiplicities()))


def expected(vectors, sketch):
    arc = fw.basic.from_edge(sketch.Shape.Edges[0])
    return fw.design_spline([fw.basic.Samples(vectors), (arc, ARC_MARKS)], join_tolerance=1e-6)


def assert_same(obj, curve):
    got = arrays(obj)
    want = (np.array([tuple(p) for p in curve.getPoles()]), np.array(curve.getWeights()),
            np.array(curve.getKnots()), np.array(curve.getMultiplicities()))
    for x, y in zip(got, want):
        np.testing.assert_array_equal(x, y)


def test_a_points_object_is_a_sampled_piece_of_the_design(doc):
    vectors = quarter_samples()
    cloud, sketch = points_object(doc, vectors), arc_sketch(doc)
    design = make_design_spline(doc, [(cloud, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    assert design.Status == "ok", design.Status
    assert list(design.MarkCounts) == [0, 4] and get_marks(design) == [[], ARC_MARKS]
    assert list(design.Joins) == ["agree"]
    assert_same(design, expected(stored(cloud), sketch))
    # OCCT: the curve starts at the first sample, ends on the arc and stays convex.
    curve = design.Shape.Edges[0].Curve
    assert (curve.value(curve.FirstParameter) - stored(cloud)[0]).Length < 1e-15
    assert (curve.value(curve.LastParameter) - V(-1, 1, 0)).Length < 1e-12
    assert fw.curvature_sign_changes(curve) == 0


def test_samples_given_backwards_are_turned_to_meet_the_arc(doc):
    vectors = quarter_samples()
    cloud, sketch = points_object(doc, vectors[::-1]), arc_sketch(doc)
    design = make_design_spline(doc, [(cloud, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    assert design.Status == "ok", design.Status
    assert list(design.Reversed) == [True, False]
    assert_same(design, expected(stored(cloud)[::-1], sketch))


def test_a_sketch_of_points_is_a_sampled_piece(doc):
    vectors = quarter_samples(15)
    points_sketch = doc.addObject("Sketcher::SketchObject", "PointSketch")
    for v in vectors:
        points_sketch.addGeometry(Part.Point(v))
    sketch = arc_sketch(doc)
    design = make_design_spline(doc, [(points_sketch, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    assert design.Status == "ok", design.Status
    assert_same(design, expected(vectors, sketch))


def test_moving_the_points_recomputes_and_save_reopen_gives_identical_poles(doc, tmp_path):
    vectors = quarter_samples()
    cloud, sketch = points_object(doc, vectors), arc_sketch(doc)
    design = make_design_spline(doc, [(cloud, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    moved = [V(v.x * 1.05, v.y, 0) for v in vectors[:-1]] + [vectors[-1]]
    cloud.Points = Points.Points(moved)
    doc.recompute()
    assert design.Status == "ok", design.Status
    assert_same(design, expected(stored(cloud), sketch))
    before = arrays(design)
    path = str(tmp_path / "samples.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        design = reopened.getObject("DesignSpline")
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert design.Status == "ok", design.Status
        for x, y in zip(arrays(design), before):
            np.testing.assert_array_equal(x, y)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_bad_samples_keep_the_last_good_shape_and_say_why(doc):
    vectors = quarter_samples()
    cloud, sketch = points_object(doc, vectors), arc_sketch(doc)
    design = make_design_spline(doc, [(cloud, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    good = arrays(design)
    cloud.Points = Points.Points(vectors[:2])
    doc.recompute()
    assert "piece 1" in design.Status and "at least 3 samples, got 2" in design.Status, design.Status
    for x, y in zip(arrays(design), good):
        np.testing.assert_array_equal(x, y)
    cloud.Points = Points.Points(vectors[:5] + [vectors[4]] + vectors[5:])
    doc.recompute()
    assert "points 4 and 5 coincide" in design.Status, design.Status


def test_undo_and_redo_of_a_design_with_a_sampled_piece_and_of_its_points_change(doc):
    doc.UndoMode = 1
    vectors = quarter_samples()
    cloud, sketch = points_object(doc, vectors), arc_sketch(doc)
    doc.openTransaction("sources")
    doc.commitTransaction()
    design = make_design_spline(doc, [(cloud, None), ((sketch, "Edge1"), ARC_MARKS)], join_tolerance=1e-6)
    assert doc.UndoNames[0] == "Create design spline"
    first = arrays(design)
    doc.openTransaction("move points")
    cloud.Points = Points.Points([V(v.x * 1.05, v.y, 0) for v in vectors[:-1]] + [vectors[-1]])
    doc.recompute()
    doc.commitTransaction()
    assert not np.allclose(arrays(design)[0], first[0])
    doc.undo()
    doc.recompute()
    for x, y in zip(arrays(design), first):
        np.testing.assert_array_equal(x, y)
    doc.undo()
    assert doc.getObject("DesignSpline") is None
    doc.redo()
    design = doc.getObject("DesignSpline")
    assert design is not None
    doc.recompute()
    assert design.Status == "ok", design.Status
    for x, y in zip(arrays(design), first):
        np.testing.assert_array_equal(x, y)
