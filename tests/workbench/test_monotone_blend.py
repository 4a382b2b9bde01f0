"""The Monotone blend and Monotone design features, headless: sources and ends, following the
sources, save/reopen/recompute, undo, and the error state (reason shown, last shape kept)."""
import math

import numpy as np
import pytest

import FreeCAD

import freecad_workbench as fw
from freecad_workbench.features.base import NOT_KNOWN
from freecad_workbench.features.monotone_blend import MonotoneBlend, end_conditions, make_monotone_blend
from freecad_workbench.features.monotone_design import MonotoneDesign, make_monotone_design

V = FreeCAD.Vector


def poles(obj):
    return np.array([tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()])


def line(doc, a, b, name="Line"):
    obj = doc.addObject("Part::Line", name)
    obj.X1, obj.Y1, obj.Z1 = a
    obj.X2, obj.Y2, obj.Z2 = b
    return obj


@pytest.fixture
def edges(doc):
    """A straight lead-in ending at the origin and a straight run-out ahead and up-left of it."""
    lead = line(doc, (-20, 0, 0), (0, 0, 0), "Lead")
    out = line(doc, (30, 15, 0), (38, 21, 0), "Out")
    doc.recompute()
    return lead, out


def assert_g1_and_monotone(blend, p0, t0, p1, t1):
    curve = blend.Shape.Edges[0].Curve
    assert curve.value(curve.FirstParameter).distanceToPoint(p0) <= 1e-12 * (p1 - p0).Length
    assert curve.value(curve.LastParameter).distanceToPoint(p1) <= 1e-12 * (p1 - p0).Length
    for u, t in ((curve.FirstParameter, t0), (curve.LastParameter, t1)):
        d = curve.getD1(u)[1]
        assert d.cross(t).Length <= 1e-9 * d.Length * t.Length and d.dot(t) > 0
    assert fw.check_monotone_curvature(curve).monotone
    kappa = [curve.curvature(u) for u in np.linspace(curve.FirstParameter, curve.LastParameter, 300)]
    steps = np.diff(kappa)
    assert np.all(steps <= 1e-9 * max(kappa)) or np.all(steps >= -1e-9 * max(kappa))


def test_blend_of_two_edges_continues_them_g1_with_monotone_curvature(doc, edges):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    assert blend.Status == "ok" and blend.Shape.isValid()
    assert type(blend.Proxy).__module__ == "freecad_workbench.features.monotone_blend"
    assert (blend.StartEnd, blend.EndEnd, blend.Method, blend.Continuity) == ("auto", "auto", "paper", "G1")
    assert_g1_and_monotone(blend, V(0, 0, 0), V(1, 0, 0), V(30, 15, 0), V(8, 6, 0))
    assert blend.Curvature.startswith("monotone: the curvature decreases")
    assert blend.getEditorMode("Status") == ["ReadOnly"] and blend.getEditorMode("Version") == ["Hidden"]
    # The same as the macro API on the same ends.
    expected = fw.monotone_curvature_spline(V(0, 0, 0), V(1, 0, 0), V(30, 15, 0), V(8, 6, 0), method="paper")
    np.testing.assert_array_equal(poles(blend), np.array([tuple(p) for p in expected.getPoles()]))


def test_chosen_ends_and_tangent_directions(doc, edges):
    lead, out = edges
    # Leaving the lead-in at its first point, backwards along it; arriving at the run-out's last point.
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), start_end="first", end_end="last")
    p0, t0, p1, t1 = end_conditions(blend)
    assert (p0, p1) == (V(-20, 0, 0), V(38, 21, 0))
    assert t0.normalize().isEqual(V(-1, 0, 0), 1e-15) and t1.normalize().isEqual(V(-0.8, -0.6, 0), 1e-15)
    blend.StartEnd, blend.EndEnd = "last", "first"
    doc.recompute()
    assert blend.Status == "ok"
    assert_g1_and_monotone(blend, V(0, 0, 0), V(1, 0, 0), V(30, 15, 0), V(8, 6, 0))


def test_blend_between_vertices_uses_the_given_directions(doc):
    a = doc.addObject("Part::Vertex", "A")
    b = doc.addObject("Part::Vertex", "B")
    b.X, b.Y, b.Z = 10, 5, 3
    doc.recompute()
    # In the plane of t0 = x and B, tilted out of XY: t1 turns 40 degrees from t0 in it.
    t0 = V(1, 0, 0)
    e2 = t0.cross(V(10, 5, 3)).cross(t0).normalize()
    t1 = t0 * math.cos(math.radians(40)) + e2 * math.sin(math.radians(40))
    blend = make_monotone_blend(doc, a, b, start_direction=t0, end_direction=t1)
    assert blend.Status == "ok", blend.Status
    assert_g1_and_monotone(blend, V(0, 0, 0), t0, V(10, 5, 3), t1)


def test_blend_follows_its_sources(doc, edges):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    before = poles(blend)
    out.X1, out.Y1 = 28, 14
    out.X2, out.Y2 = 36, 22
    doc.recompute()
    assert blend.Status == "ok"
    assert not np.allclose(poles(blend), before)
    assert_g1_and_monotone(blend, V(0, 0, 0), V(1, 0, 0), V(28, 14, 0), V(8, 8, 0))


def test_no_solution_keeps_the_last_shape_and_shows_why(doc, edges):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    good = poles(blend)
    other = doc.addObject("Part::Box", "Box")
    out.X2, out.Y2 = 30, 25  # the run-out turns by 90 degrees
    other.Length = 5
    doc.recompute()
    assert "turns by 90 deg" in blend.Status and "no monotone-curvature curve" in blend.Status
    np.testing.assert_array_equal(poles(blend), good)
    assert other.Shape.Volume == pytest.approx(5 * 10 * 10)  # the rest of the document recomputed
    assert blend.Curvature == NOT_KNOWN  # no verdict left looking valid
    out.X2, out.Y2 = 38, 21
    doc.recompute()
    assert blend.Status == "ok" and blend.Curvature.startswith("monotone")
    np.testing.assert_array_equal(poles(blend), good)


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda blend, doc: setattr(blend, "Start", None), "Start is not set"),
        (lambda blend, doc: setattr(blend, "End", (doc.getObject("Box"), ["Face1"])), "not one edge or one vertex"),
        (lambda blend, doc: setattr(blend, "End", doc.getObject("Box")), "not one edge or one vertex"),
    ],
)
def test_unusable_sources_are_reported(doc, edges, change, message):
    lead, out = edges
    doc.addObject("Part::Box", "Box")
    doc.recompute()
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    good = poles(blend)
    change(blend, doc)
    doc.recompute()
    assert message in blend.Status
    np.testing.assert_array_equal(poles(blend), good)


def test_grid_method_gives_the_papers_first_hit(doc, edges):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), method="grid")
    expected = fw.monotone_curvature_spline(V(0, 0, 0), V(1, 0, 0), V(30, 15, 0), V(8, 6, 0), method="grid")
    np.testing.assert_array_equal(poles(blend), np.array([tuple(p) for p in expected.getPoles()]))


def test_save_close_reopen_recompute(doc, edges, tmp_path):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), end_end="first")
    design = make_monotone_design(doc, (10, 0), [(10, 5), (3, 4.5), (1, 2)])
    blend_poles, design_poles = poles(blend), poles(design)
    path = str(tmp_path / "monotone.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend, design = reopened.getObject("MonotoneBlend"), reopened.getObject("MonotoneDesign")
        assert isinstance(blend.Proxy, MonotoneBlend) and isinstance(design.Proxy, MonotoneDesign)
        assert (blend.EndEnd, blend.Version, blend.Status) == ("first", MonotoneBlend.VERSION, "ok")
        np.testing.assert_allclose(poles(blend), blend_poles, rtol=1e-15, atol=1e-14)
        for obj in (blend, design):
            obj.touch()
        reopened.recompute()
        np.testing.assert_array_equal(poles(blend), blend_poles)
        np.testing.assert_array_equal(poles(design), design_poles)
        assert design.UsedDifferences[2] != V(1, 2, 0)  # moved into its fair location, and kept so
        reopened.getObject("Out").X1 = 29  # the links survived
        reopened.recompute()
        assert blend.Status == "ok" and not np.allclose(poles(blend), blend_poles)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_old_document_without_new_properties_loads_and_migrates(doc, edges, tmp_path):
    lead, out = edges
    blend = make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    for name in ("Version", "Curvature", "Method"):
        blend.removeProperty(name)
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend = reopened.getObject("MonotoneBlend")
        assert (blend.Version, blend.Method, blend.Continuity) == (MonotoneBlend.VERSION, "paper", "G1")
        blend.touch()
        reopened.recompute()
        assert blend.Status == "ok" and blend.Curvature.startswith("monotone")
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_creation_is_one_undo_step(doc, edges):
    doc.UndoMode = 1
    lead, out = edges
    doc.openTransaction("lines")
    doc.commitTransaction()
    count = len(doc.Objects)
    make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    assert doc.UndoNames[0] == "Create monotone blend"
    doc.undo()
    assert len(doc.Objects) == count
    make_monotone_design(doc, (1, 0), [(1, 0.5), (0.3, 0.45)])
    assert doc.UndoNames[0] == "Create monotone design"


def test_factory_rejects_unknown_choices(doc, edges):
    lead, out = edges
    with pytest.raises(fw.InputError, match="start_end"):
        make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), start_end="middle")
    with pytest.raises(fw.InputError, match="method"):
        make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"), method="newton")
    with pytest.raises(fw.InputError, match="not a document object"):
        make_monotone_blend(doc, "Lead", (out, "Edge1"))


# --- Monotone design ------------------------------------------------------------------------


def test_design_feature_is_algorithm_1_placed(doc):
    design = make_monotone_design(doc, (10, 0), [(10, 5), (3, 4.5), (1, 2)])
    assert design.Status == "ok"
    curve = fw.monotone_curvature_design((10, 0), [(10, 5), (3, 4.5), (1, 2)])
    np.testing.assert_allclose(poles(design), np.array([tuple(p) for p in curve.getPoles()]), atol=1e-12)
    used, moved = fw.clamp_to_fair_locations((10, 0), [(10, 5), (3, 4.5), (1, 2)])
    assert [tuple(v)[:2] for v in design.UsedDifferences] == [tuple(u) for u in used]
    assert moved[2] > 0
    design.Placement = FreeCAD.Placement(V(5, 5, 5), FreeCAD.Rotation(V(1, 0, 0), 90))
    doc.recompute()
    assert design.Shape.Edges[0].Vertexes[0].Point.isEqual(V(5, 5, 5), 1e-12)
    assert fw.check_monotone_curvature(design.Shape.Edges[0]).monotone


def test_design_with_bad_vectors_keeps_its_shape_and_says_why(doc):
    design = make_monotone_design(doc, (10, 0), [(10, 5), (3, 4.5)])
    good = poles(design)
    design.FirstVector = V(0, 0, 0)
    doc.recompute()
    assert design.Status == "the first control vector is zero"
    np.testing.assert_array_equal(poles(design), good)
    design.FirstVector = V(10, 0, 0)
    design.Differences = [V(1, 1, 0)]
    doc.recompute()
    assert "at least 2 differences" in design.Status
    design.Differences = [V(10, 5, 0), V(3, 4.5, 0)]
    doc.recompute()
    assert design.Status == "ok"


def test_creation_without_undo_leaves_no_transaction_open(doc, edges):
    # Regression: a transaction opened in a document that keeps no undo never closed, and
    # FreeCAD gave its name to the next command's undo step in any document.
    from freecad_workbench.features.csr_fit import make_csr_fit

    assert doc.UndoMode == 0
    lead, out = edges
    make_monotone_blend(doc, (lead, "Edge1"), (out, "Edge1"))
    make_monotone_design(doc, (1, 0), [(1, 0.5), (0.3, 0.45)])
    make_csr_fit(doc, [(lead, "Edge1"), (out, "Edge1")])
    assert FreeCAD.getActiveTransaction() is None
