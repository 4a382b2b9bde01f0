"""Edit polygon, headless: moving one pole changes the curve only on the (at most) four
spans it supports (judged by OCCT evaluation), keeps knots, weights and C2, follows the
design upstream, and keeps its last good shape when the design's polygon changes size."""
import numpy as np
import pytest

import FreeCAD

import freecad_workbench as fw
from tests.scenes import assert_failed_like_freecad
from freecad_workbench.features.basic_curve import make_basic_curve
from freecad_workbench.features.design_spline import make_design_spline, set_marks
from freecad_workbench.features.edit_polygon import (
    EditPolygon,
    base_curve,
    make_edit_polygon,
    reset_pole,
    set_pole,
)

V = FreeCAD.Vector
XZ = FreeCAD.Placement(V(0, 0, 0), FreeCAD.Rotation(V(1, 0, 0), 90))


@pytest.fixture
def design(doc):
    """A semi-circle joined to a semi-ellipse (Fig. 10), rational, non-uniform knots."""
    circle = make_basic_curve(doc, "Circle arc", placement=XZ, Radius=10, StartAngle=180, EndAngle=0)
    ellipse = make_basic_curve(doc, "Ellipse arc", placement=FreeCAD.Placement(V(35, 0, 0), XZ.Rotation),
                               MajorRadius=20, MinorRadius=8, StartAngle=180, EndAngle=360)
    return make_design_spline(doc, [(circle, [0.15, 0.4, 0.6, 0.85]), (ellipse, [0.1, 0.3, 0.5, 0.7, 0.9])],
                              reversed=[False, False])


def curve_of(obj):
    return obj.Shape.Edges[0].Curve


def span_samples(curve, per_span=7):
    """(span index, parameters strictly inside it) for every knot span of the curve."""
    knots = curve.getKnots()
    return [(i, np.linspace(a, b, per_span + 2)[1:-1]) for i, (a, b) in enumerate(zip(knots[:-1], knots[1:]))]


def changed_spans(before, after):
    """Per span of `before`: the largest distance between the two curves at its samples."""
    return [max((before.value(float(t)) - after.value(float(t))).Length for t in ts) for _, ts in span_samples(before)]


def supported_spans(curve, index):
    """The spans (indices into getKnots intervals) where pole `index` (from 0) has a
    nonzero B-spline basis function: [T_index, T_(index+4)] of the flat knot sequence."""
    flat = curve.KnotSequence
    lo, hi = flat[index], flat[index + 4]
    knots = curve.getKnots()
    return [i for i, (a, b) in enumerate(zip(knots[:-1], knots[1:])) if a >= lo and b <= hi]


@pytest.mark.parametrize("which", ["first", "second", "middle", "last"])
def test_moving_one_pole_changes_only_the_spans_it_supports(doc, design, which):
    edited = make_edit_polygon(doc, design)
    assert edited.Status == "ok" and isinstance(edited.Proxy, EditPolygon)
    before = curve_of(edited)
    n = before.NbPoles
    index = {"first": 0, "second": 1, "middle": n // 2, "last": n - 1}[which]
    set_pole(edited, index, before.getPole(index + 1) + V(1.5, 0.7, -2.0))
    doc.recompute()
    after = curve_of(edited)
    support = supported_spans(before, index)
    assert 1 <= len(support) <= 4
    if which == "middle":
        assert len(support) == 4
    changes = changed_spans(before, after)
    for span, change in enumerate(changes):
        if span in support:
            assert change > 1e-3, (span, change)
        else:
            assert change == 0.0, (span, change)  # bit for bit: the same poles, weights and knots there
    # knots, multiplicities and weights are untouched, the curve stays C2
    assert after.getKnots() == before.getKnots() and after.getMultiplicities() == before.getMultiplicities()
    assert after.getWeights() == before.getWeights()
    assert after.Continuity == "C2"
    assert [tuple(p) for p in edited.Poles] == [tuple(p) for p in after.getPoles()]


def test_the_circle_stays_exact_away_from_a_moved_pole_of_the_ellipse(doc, design):
    edited = make_edit_polygon(doc, design)
    curve = curve_of(edited)
    set_pole(edited, curve.NbPoles - 3, curve.getPole(curve.NbPoles - 2) + V(0, 0, 5))
    doc.recompute()
    result = curve_of(edited)
    knots = result.getKnots()
    assert knots[3] == pytest.approx(0.6)  # the circle's third mark: exact from its free end to here
    for t in np.linspace(knots[0], knots[3], 100):
        p = result.value(float(t))
        assert abs(p.Length - 10.0) < 1e-12 * 10 and abs(p.y) < 1e-12


def test_edits_follow_the_design_upstream(doc, design):
    edited = make_edit_polygon(doc, design)
    k = 6
    offset = V(0.5, 0, 1.25)
    set_pole(edited, k, base_curve(edited).getPole(k + 1) + offset)
    doc.recompute()
    set_marks(design, [[0.15, 0.45, 0.6, 0.85], [0.1, 0.3, 0.5, 0.75, 0.9]])  # same number of poles
    doc.recompute()
    assert edited.Status == "ok"
    base = curve_of(design)
    result = curve_of(edited)
    assert result.NbPoles == base.NbPoles
    for i in range(base.NbPoles):
        expected = base.getPole(i + 1) + (offset if i == k else V())
        assert (result.getPole(i + 1) - expected).Length < 1e-12


def test_a_design_with_more_poles_keeps_the_last_good_shape(doc, design):
    edited = make_edit_polygon(doc, design)
    set_pole(edited, 3, curve_of(edited).getPole(4) + V(1, 0, 0))
    doc.recompute()
    good = [tuple(p) for p in curve_of(edited).getPoles()]
    set_marks(design, [[0.15, 0.4, 0.6, 0.85], [0.1, 0.2, 0.3, 0.5, 0.7, 0.9]])  # one pole more
    doc.recompute()
    assert edited.Status.startswith("the source now has")
    assert "clear PoleOffsets" in edited.Status
    assert [tuple(p) for p in curve_of(edited).getPoles()] == good
    edited.PoleOffsets = []
    doc.recompute()
    assert edited.Status == "ok"
    assert [tuple(p) for p in curve_of(edited).getPoles()] == [tuple(p) for p in curve_of(design).getPoles()]


def test_reset_pole_puts_it_back(doc, design):
    edited = make_edit_polygon(doc, design)
    original = [tuple(p) for p in curve_of(edited).getPoles()]
    set_pole(edited, 2, V(1, 2, 3))
    doc.recompute()
    assert tuple(curve_of(edited).getPole(3)) == pytest.approx((1, 2, 3), abs=1e-12)
    reset_pole(edited, 2)
    doc.recompute()
    assert list(edited.PoleOffsets) == []
    assert [tuple(p) for p in curve_of(edited).getPoles()] == original
    with pytest.raises(fw.InputError, match="pole 99 does not exist"):
        set_pole(edited, 99, V())


def test_any_bspline_edge_can_be_edited(doc):
    cloud = doc.addObject("Part::Feature", "Fit")
    cloud.Shape = fw.csr_spline([(0, 0), (2, 3), (5, 4), (8, 2), (11, 3)]).toShape()
    doc.recompute()
    edited = make_edit_polygon(doc, (cloud, "Edge1"))
    assert edited.Status == "ok"
    set_pole(edited, 2, curve_of(edited).getPole(3) + V(0, 1, 0))
    doc.recompute()
    assert edited.Shape.isValid() and edited.Status == "ok"


def test_missing_source_is_an_error_not_a_crash(doc, design):
    edited = make_edit_polygon(doc, design)
    good = [tuple(p) for p in curve_of(edited).getPoles()]
    edited.Source = (design, ["Edge7"])
    doc.recompute()
    assert edited.Status == "DesignSpline.Edge7 is not an edge"
    assert [tuple(p) for p in curve_of(edited).getPoles()] == good


def test_save_reopen_recompute_gives_identical_edited_poles(doc, design, tmp_path):
    edited = make_edit_polygon(doc, design)
    set_pole(edited, 5, curve_of(edited).getPole(6) + V(0.123456789, 0, -0.987654321))
    doc.recompute()
    before = [tuple(p) for p in curve_of(edited).getPoles()]
    path = str(tmp_path / "edited.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        edited = reopened.getObject("EditPolygon")
        assert isinstance(edited.Proxy, EditPolygon)
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert edited.Status == "ok"
        assert [tuple(p) for p in curve_of(edited).getPoles()] == before
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_nan_offset_is_an_error_not_ignored(doc, design):
    """Issue 13: NaN PoleOffsets were skipped with Status ok."""
    edited = make_edit_polygon(doc, design)
    good = [tuple(p) for p in curve_of(edited).getPoles()]
    offsets = [V(0, 0, 0)] * len(good)
    offsets[3] = V(float("nan"), 0, 0)
    edited.PoleOffsets = offsets
    doc.recompute()
    assert_failed_like_freecad(edited, "PoleOffsets: the offset of pole 4 is not finite")
    assert [tuple(p) for p in curve_of(edited).getPoles()] == good  # last good shape kept
