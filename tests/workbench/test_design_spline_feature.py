"""The Design spline feature, headless: pieces from sketch edges and BasicCurve objects,
marks, recompute when a source moves, save/reopen, undo, error state. Geometry is judged
by OCCT evaluation of the feature's Part shape and against fw.design_spline."""
import math

import numpy as np
import pytest

import FreeCAD
import Part
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

from tests.scenes import assert_failed_like_freecad
import freecad_workbench as fw
from freecad_workbench.features.basic_curve import make_basic_curve
from freecad_workbench.features.design_spline import (
    DEFAULT_MARKS,
    DesignSpline,
    get_marks,
    make_design_spline,
    reversed_curve,
    set_marks,
)

V = FreeCAD.Vector
# The sketch lies in the XZ plane, moved to (0, 5, 0): sketch y is global Z.
SKETCH_PLACEMENT = FreeCAD.Placement(V(0, 5, 0), FreeCAD.Rotation(V(1, 0, 0), 90))
MARKS = [[0.3, 0.6, 0.9], [0.1, 0.35, 0.6, 0.85], [0.2, 0.5]]


# The chain of the profile in sketch coordinates: line, quarter circle, line (Fig. 14).
CHAIN = [(V(20, 0, 0), V(20, 10, 0)), (V(20, 10, 0), V(15, 15, 0)), (V(15, 15, 0), V(0, 15, 0))]


def profile_sketch(doc, reverse_line=False):
    """Fig. 14's situation: a line, a quarter circle touching it, a line touching that.
    The sketch numbers its edges in its own order: see chain_links."""
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.Placement = SKETCH_PLACEMENT
    line = (V(20, 10, 0), V(20, 0, 0)) if reverse_line else (V(20, 0, 0), V(20, 10, 0))
    sketch.addGeometry(Part.LineSegment(*line))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(15, 10, 0), V(0, 0, 1), 5), 0, math.pi / 2))
    sketch.addGeometry(Part.LineSegment(V(15, 15, 0), V(0, 15, 0)))
    doc.recompute()
    return sketch


def move_point(sketch, geo_id, pos, point):
    """Move a sketch vertex: moveGeometry since FreeCAD 1.1, movePoint before."""
    move = getattr(sketch, "moveGeometry", None) or sketch.movePoint
    move(geo_id, pos, point)


def chain_names(sketch):
    """The sketch's EdgeN names of the chain's pieces, in chain order."""
    names = []
    for a, b in CHAIN:
        ends = {tuple(SKETCH_PLACEMENT.multVec(p)) for p in (a, b)}
        for i, edge in enumerate(sketch.Shape.Edges):
            points = {tuple(v.Point) for v in edge.Vertexes}
            if all(any((V(*p) - V(*q)).Length < 1e-9 for q in points) for p in ends):
                names.append(f"Edge{i + 1}")
    assert len(names) == 3, names
    return names


def arrays(curve_or_obj):
    curve = curve_or_obj.Shape.Edges[0].Curve if hasattr(curve_or_obj, "Shape") else curve_or_obj
    return (np.array([tuple(p) for p in curve.getPoles()]), np.array(curve.getWeights()),
            np.array(curve.getKnots()), np.array(curve.getMultiplicities()))


def assert_same_curve(a, b):
    for x, y in zip(arrays(a), arrays(b)):
        np.testing.assert_array_equal(x, y)


def chain_curves(sketch):
    """The chain's basic curves, each turned to run along the chain."""
    curves = []
    for name, (a, _) in zip(chain_names(sketch), CHAIN):
        curve = fw.basic.from_edge(Part.getShape(sketch, name, needSubElement=True))
        start = SKETCH_PLACEMENT.multVec(a)
        if (curve.value(0) - start).Length > (curve.value(1) - start).Length:
            curve = reversed_curve(curve)
        curves.append(curve)
    return curves


def sketch_pieces(sketch, marks=MARKS):
    return list(zip(chain_curves(sketch), marks))


def make_profile_design(doc, sketch, marks=MARKS, **kw):
    return make_design_spline(doc, [((sketch, name), m) for name, m in zip(chain_names(sketch), marks)], **kw)


def expected_reversed(sketch):
    flags = []
    for name, (a, _) in zip(chain_names(sketch), CHAIN):
        curve = fw.basic.from_edge(Part.getShape(sketch, name, needSubElement=True))
        start = SKETCH_PLACEMENT.multVec(a)
        flags.append((curve.value(0) - start).Length > (curve.value(1) - start).Length)
    return flags


def test_design_of_sketch_edges_is_the_design_spline_of_those_edges(doc):
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    assert design.Status == "ok"
    assert isinstance(design.Proxy, DesignSpline)
    assert design.Shape.isValid() and len(design.Shape.Edges) == 1
    curve = design.Shape.Edges[0].Curve
    assert isinstance(curve, Part.BSplineCurve) and curve.Degree == 3 and curve.Continuity == "C2"
    assert_same_curve(design, fw.design_spline(sketch_pieces(sketch)))
    assert list(design.Joins) == ["agree", "agree"] and list(design.MarksAdded) == [0, 0, 0]
    assert list(design.Reversed) == expected_reversed(sketch)
    assert get_marks(design) == MARKS
    for name in ("Joins", "MarksAdded", "Status"):
        assert design.getEditorMode(name) == ["ReadOnly"], name
    assert design.getEditorMode("Version") == ["Hidden"]
    # the curve runs from the sketch's first point to its last, in the placed sketch
    start, end = curve.value(curve.FirstParameter), curve.value(curve.LastParameter)
    assert (start - SKETCH_PLACEMENT.multVec(V(20, 0, 0))).Length < 1e-12
    assert (end - SKETCH_PLACEMENT.multVec(V(0, 15, 0))).Length < 1e-12


def test_the_arc_stays_exact_between_its_marks(doc):
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    result = fw.design_spline(sketch_pieces(sketch), details=True)
    t0, scale = result.ranges[1]
    u = result.marks[1]  # u_0 = 0, u_1, ..., u_m = 1
    curve = design.Shape.Edges[0].Curve
    center = SKETCH_PLACEMENT.multVec(V(15, 10, 0))
    size = 20.0
    for x in np.linspace(u[2], u[-3], 200):
        p = curve.value(t0 + scale * x)
        assert abs((p - center).Length - 5.0) < 1e-12 * size
        assert abs(p.y - 5.0) < 1e-12 * size  # in the sketch plane


def test_basic_curve_objects_are_used_exactly_with_their_placement(doc):
    xz = FreeCAD.Placement(V(10, 0, 10), FreeCAD.Rotation(V(1, 0, 0), 90))
    arc = make_basic_curve(doc, "Ellipse arc", placement=xz, MajorRadius=10, MinorRadius=5, StartAngle=0,
                           EndAngle=120)
    spiral = make_basic_curve(doc, "Archimedean spiral", placement=xz, Radius=1, Pitch=4, StartAngle=0, Turns=1)
    design = make_design_spline(doc, [(arc, [0.25, 0.5, 0.75]), ((spiral, "Edge1"), [0.2, 0.4, 0.6, 0.8])],
                                reversed=[False, False])
    assert design.Status == "ok"
    expected = fw.design_spline([(arc.Proxy.basic_curve(arc), [0.25, 0.5, 0.75]),
                                 (spiral.Proxy.basic_curve(spiral), [0.2, 0.4, 0.6, 0.8])])
    assert_same_curve(design, expected)
    assert list(design.Joins) == ["edge"]  # the ellipse ends far from the spiral's start
    arc.MajorRadius = 12
    doc.recompute()
    assert design.Status == "ok"
    moved = fw.design_spline([(arc.Proxy.basic_curve(arc), [0.25, 0.5, 0.75]),
                              (spiral.Proxy.basic_curve(spiral), [0.2, 0.4, 0.6, 0.8])])
    assert_same_curve(design, moved)


def test_pieces_are_turned_to_meet_end_to_start(doc):
    for reverse_line in (False, True):
        sketch = profile_sketch(doc, reverse_line=reverse_line)
        design = make_profile_design(doc, sketch)
        flags = expected_reversed(sketch)
        assert list(design.Reversed) == flags
        assert list(design.Joins) == ["agree", "agree"]
        assert_same_curve(design, fw.design_spline(sketch_pieces(sketch)))
        curve = design.Shape.Edges[0].Curve
        assert (curve.value(curve.FirstParameter) - SKETCH_PLACEMENT.multVec(V(20, 0, 0))).Length < 1e-12
    assert flags[0]  # the reversed line is turned round
    as_given = make_profile_design(doc, sketch, reversed=[False, False, False], name="AsGiven")
    assert list(as_given.Reversed) == [False, False, False]
    assert "edge" in list(as_given.Joins)


@pytest.mark.parametrize("basic", [
    fw.basic.LineSegment((0, 0, 0), (1, 2, 3)),
    fw.basic.CircleArc((1, 0, 0), 2.0, 0.3, 4.0, (0, 1, 1), (1, 0, 0)),
    fw.basic.EllipseArc((0, 0, 0), 3.0, 1.0, -0.2, 2.0),
    fw.basic.ParabolaArc((1, 1, 0), 2.0, -1.0, 2.0),
    fw.basic.HyperbolaArc((0, 0, 0), 2.0, 1.0, -0.5, 1.2),
    fw.basic.RationalCubic([(0, 0, 0), (1, 2, 0), (3, 2, 0), (4, 0, 0)], [1, 0.6, 1.7, 1]),
    fw.basic.ArchimedeanSpiral(),
    fw.basic.CircleInvolute(),
], ids=lambda b: type(b).__name__)
def test_reversed_curve_runs_backwards_with_the_same_speed(basic):
    back = reversed_curve(basic)
    assert back.exact == basic.exact
    for u in np.linspace(0, 1, 13):
        assert (back.value(u) - basic.value(1 - u)).Length < 1e-13 * max(1.0, basic.size())
        assert (back.d1(u) + basic.d1(1 - u)).Length < 1e-12 * max(1.0, basic.size())
        assert (back.d2(u) - basic.d2(1 - u)).Length < 1e-11 * max(1.0, basic.size())


def test_marks_given_as_points_are_located_on_the_piece(doc):
    sketch = profile_sketch(doc)
    name = chain_names(sketch)[1]
    arc = fw.basic.from_edge(Part.getShape(sketch, name, needSubElement=True))
    points = [arc.value(u) for u in (0.15, 0.5, 0.7)]
    design = make_design_spline(doc, [((sketch, name), points)])
    np.testing.assert_allclose(get_marks(design)[0], [0.15, 0.5, 0.7], atol=1e-12)
    with pytest.raises(fw.InputError, match="piece 0: mark 1"):
        make_design_spline(doc, [((sketch, name), [points[0], V(100, 100, 100)])], name="Off")
    assert doc.getObject("Off") is None


def test_pieces_without_marks_get_the_default_marks(doc):
    sketch = profile_sketch(doc)
    design = make_design_spline(doc, [((sketch, n), None) for n in chain_names(sketch)[:2]])
    assert get_marks(design) == [list(DEFAULT_MARKS)] * 2
    assert design.Status == "ok"


def test_moving_a_sketch_edge_recomputes_the_design(doc):
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    before = arrays(design)[0]
    move_point(sketch, 2, 2, V(-5, 18, 0))  # the end of the last line (geometry 2)
    doc.recompute()
    after = arrays(design)[0]
    assert not np.allclose(before, after)
    CHAIN[2] = (V(15, 15, 0), V(-5, 18, 0))
    try:
        assert_same_curve(design, fw.design_spline(sketch_pieces(sketch)))
    finally:
        CHAIN[2] = (V(15, 15, 0), V(0, 15, 0))
    assert (design.Shape.Edges[0].Curve.EndPoint - SKETCH_PLACEMENT.multVec(V(-5, 18, 0))).Length < 1e-12


def test_changing_marks_recomputes(doc):
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    new = [[0.5], [0.05, 0.3, 0.55, 0.8, 0.95], []]
    set_marks(design, new)
    doc.recompute()
    assert list(design.MarkCounts) == [1, 5, 0]
    assert_same_curve(design, fw.design_spline(sketch_pieces(sketch, new)))


def test_joins_report_agree_averaged_and_edge(doc):
    first = make_basic_curve(doc, "Circle arc", Radius=10, StartAngle=0, EndAngle=90)  # ends at (0, 10)
    agree = make_basic_curve(doc, "Line segment", Start=V(0, 10, 0), End=V(-10, 10, 0))
    close = make_basic_curve(doc, "Line segment", Start=V(-10, 10.0004, 0), End=V(-20, 10, 0))
    apart = make_basic_curve(doc, "Line segment", Start=V(-22, 10, 0), End=V(-30, 10, 0))
    design = make_design_spline(doc, [(first, None), (agree, None), (close, None), (apart, None)],
                                join_tolerance=1e-3, reversed=[False] * 4)
    assert list(design.Joins) == ["agree", "averaged", "edge"]
    assert design.Shape.Edges[0].Curve.Continuity == "C2"
    design.JoinTolerance = 1e-5
    doc.recompute()
    assert list(design.Joins) == ["agree", "edge", "edge"]


def test_wide_arc_gets_marks_added_to_keep_weights_positive(doc):
    wide = make_basic_curve(doc, "Circle arc", Radius=10, StartAngle=0, EndAngle=300)
    design = make_design_spline(doc, [(wide, [0.5])])
    assert design.Status == "ok"
    assert design.MarksAdded[0] > 0
    assert min(design.Shape.Edges[0].Curve.getWeights()) > 0


def test_save_close_reopen_recompute_gives_identical_poles(doc, tmp_path):
    rng = np.random.default_rng(3)
    marks = [sorted(rng.uniform(0.01, 0.99, 4).tolist()) for _ in range(3)]  # full-precision floats
    sketch = profile_sketch(doc, reverse_line=True)
    design = make_profile_design(doc, sketch, marks=marks, join_tolerance=0.123456789012345)
    assert design.Status == "ok"
    before = arrays(design)
    reversed_ = list(design.Reversed)
    names = chain_names(sketch)
    path = str(tmp_path / "design.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        design = reopened.getObject("DesignSpline")
        assert isinstance(design.Proxy, DesignSpline)
        assert get_marks(design) == marks  # bit for bit (the float list is stored in binary)
        assert list(design.Reversed) == reversed_ and design.Version == DesignSpline.VERSION
        assert [(o.Name, subs) for o, subs in design.Pieces] == [("Profile", tuple(names))]
        # as stored: FreeCAD writes the shape's BREP with 16 digits
        np.testing.assert_allclose(arrays(design)[0], before[0], rtol=1e-15, atol=1e-14)
        for obj in reopened.Objects:  # recompute everything, the sketch from its exact geometry
            obj.touch()
        reopened.recompute()
        assert design.Status == "ok"
        for x, y in zip(arrays(design), before):  # as recomputed: identical
            np.testing.assert_array_equal(x, y)
        move_point(reopened.getObject("Profile"), 2, 2, V(-5, 18, 0))  # the links survived
        reopened.recompute()
        assert not np.allclose(arrays(design)[0], before[0])
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_old_document_without_new_properties_loads_and_migrates(doc, tmp_path):
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    design.Reversed = []  # as a file from before Reversed existed: every piece as it runs
    doc.recompute()
    expected = arrays(design)
    for name in ("Version", "Joins", "MarksAdded", "Reversed"):
        design.removeProperty(name)
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        design = reopened.getObject("DesignSpline")
        assert design.Version == DesignSpline.VERSION and list(design.Reversed) == []
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert design.Status == "ok" and len(design.Joins) == 2
        for x, y in zip(arrays(design), expected):
            np.testing.assert_array_equal(x, y)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_undo_and_redo_of_creation_and_of_a_marks_change(doc):
    doc.UndoMode = 1
    sketch = profile_sketch(doc)
    doc.openTransaction("sketch")
    doc.commitTransaction()
    design = make_profile_design(doc, sketch)
    assert doc.UndoNames[0] == "Create design spline"
    first = arrays(design)
    doc.openTransaction("marks")
    set_marks(design, [[0.5], [0.5], [0.5]])
    doc.recompute()
    doc.commitTransaction()
    assert not np.allclose(arrays(design)[0][:4], first[0][:4])
    doc.undo()
    doc.recompute()
    assert get_marks(design) == MARKS
    for x, y in zip(arrays(design), first):
        np.testing.assert_array_equal(x, y)
    doc.undo()
    assert doc.getObject("DesignSpline") is None
    doc.redo()
    assert doc.getObject("DesignSpline") is not None


def test_factory_leaves_no_transaction_behind_without_undo(doc):
    before = FreeCAD.getActiveTransaction()
    sketch = profile_sketch(doc)
    assert doc.UndoMode == 0
    make_profile_design(doc, sketch)
    assert FreeCAD.getActiveTransaction() == before


def _decreasing(design, sketch):
    set_marks(design, [[0.6, 0.3], [0.5], [0.5]])


def _outside(design, sketch):
    set_marks(design, [[0.5], [0.5, 1.5], [0.5]])


def _bspline_edge(design, sketch):
    other = design.Document.addObject("Part::Feature", "Freeform")
    other.Shape = fw.csr_spline([(0, 0), (1, 2), (3, 1), (4, 3)]).toShape()
    names = chain_names(sketch)
    design.Pieces = [(sketch, names[0]), (other, "Edge1"), (sketch, names[2])]


def _missing_edge(design, sketch):
    names = chain_names(sketch)
    design.Pieces = [(sketch, names[0]), (sketch, "Edge9"), (sketch, names[2])]


def _counts(design, sketch):
    design.MarkCounts = [3, 4, 5]


BAD_INPUT = {
    "decreasing marks": (_decreasing, "piece 1", "Profile.Edge"),  # numbered from 1, as a designer counts
    "mark outside [0, 1]": (_outside, "piece 2", "Profile.Edge"),
    "B-spline edge": (_bspline_edge, "a B-spline or Bézier edge is not a basic curve", "Freeform.Edge1"),
    "missing edge": (_missing_edge, "Profile.Edge9 not found", "piece 2"),
    "counts": (_counts, "MarkCounts [3, 4, 5] do not add up to the 9 Marks", ""),
}


@pytest.mark.parametrize("case", sorted(BAD_INPUT))
def test_bad_input_keeps_the_last_good_shape_and_names_the_piece(doc, case):
    break_it, message, source = BAD_INPUT[case]
    sketch = profile_sketch(doc)
    design = make_profile_design(doc, sketch)
    good = arrays(design)
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    pieces, marks = list(design.Pieces), get_marks(design)

    break_it(design, sketch)
    box.Length = 42
    doc.recompute()

    assert design.Status != "ok"
    assert message in design.Status and source in design.Status, design.Status
    for x, y in zip(arrays(design), good):
        np.testing.assert_array_equal(x, y)  # last good shape kept
    assert_failed_like_freecad(design, message)
    assert box.Shape.BoundBox.XLength == pytest.approx(42)  # the rest of the document recomputed

    design.Pieces = pieces
    set_marks(design, marks)
    doc.recompute()
    assert design.Status == "ok"
    for x, y in zip(arrays(design), good):
        np.testing.assert_array_equal(x, y)


def test_factory_rejects_what_cannot_be_stored(doc):
    with pytest.raises(fw.InputError, match="not a document object"):
        make_design_spline(doc, [("Sketch", [0.5])])
    with pytest.raises(fw.InputError, match="at least one piece"):
        make_design_spline(doc, [])
    assert doc.getObject("DesignSpline") is None
